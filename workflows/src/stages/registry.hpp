// The stage kinds a scene may name in [[stages]] kind, each a Stage.
// Built-in kinds are listed in registry.cpp (one line each, so the linker
// keeps every stage of the static library); a test build adds its own
// with register_stage.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/stage_kind.hpp"

namespace rockfdem::workflows {

class Stage;

/// Adds `stage` under `kind` after the built-in kinds; a kind registered
/// twice is a programming error (std::logic_error).
void register_stage(const std::string& kind, std::unique_ptr<const Stage> stage);
/// The stage of `kind`; std::logic_error when none is registered (a
/// validated scene names only registered kinds).
const Stage& stage_of(const std::string& kind);

}  // namespace rockfdem::workflows
