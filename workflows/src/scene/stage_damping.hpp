// The damping a scene asks of its explicit stages after the hand-off step:
// read by the engine's set-up and by the scene's own checks.
#pragma once

#include "rockfdem/fdem/model_input.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The damping of the explicit stages after the hand-off step: the scene's
/// local damping (0.8 unless set) and mass-proportional damping.
fdem::DampingSettings stage_damping(const Scene& s);

}  // namespace rockfdem::workflows
