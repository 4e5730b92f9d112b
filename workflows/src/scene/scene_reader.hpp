// Private: the TOML layer of scene loading. Parses text, applies --set
// overrides and checks every key against the schema, so later code only
// ever sees known keys of the right type within range.
#pragma once

#include <toml++/toml.h>

#include <map>
#include <string>
#include <vector>

#include "rockfdem/printable.hpp"

namespace rockfdem::workflows::detail {

struct RawScene {
  toml::table root;
  std::string source;                                ///< file name for messages
  std::map<std::string, std::string> override_text;  ///< dotted path set with --set -> the argument
};

/// Refuses, before any TOML parsing, scene text that toml++ could not parse
/// safely or that no scene needs: over 1 MiB, brackets and braces nested
/// over 32 deep, a key or table header of over 16 dotted parts, a key of
/// over 256 characters. Throws InputError "<source>:<line>: <what>; allowed: <limit>".
void check_scene_bounds(const std::string& text, const std::string& source);

/// `text` with its control characters (C0, DEL, C1) shown as escapes
/// (\n, \x1b, \u009b): every message that echoes a scene's text goes
/// through it (rockfdem/printable.hpp).
using ::rockfdem::printable;

/// check_scene_bounds(), then toml++.
RawScene read_raw_scene(const std::string& text, const std::string& source,
                        const std::vector<std::string>& overrides);

/// "<source>[:line]: <key> = <value>: <problem>", or for a key set on the
/// command line "--set <argument>: <problem>": fail_key's text, for warnings.
std::string key_message(const RawScene& scene, const std::string& path, const toml::node* node,
                        const std::string& problem);

/// Throws InputError "<source>[:line]: <key> = <value>: <problem>; allowed: <what>",
/// or, for a key set on the command line, "--set <argument>: <problem>; allowed: <what>".
[[noreturn]] void fail_key(const RawScene& scene, const std::string& path, const toml::node* node,
                           const std::string& problem);

std::string node_text(const toml::node& node);

/// The shortest decimal text that reads back as `v` (%g style: 8.8, 1e-06, 200).
std::string number_text(double v);

/// Whether `path` (or a table above it) was set with --set.
bool from_command_line(const RawScene& scene, const std::string& path);

/// The (path, --set argument) that set `path` or a table above it; null if none.
const std::pair<const std::string, std::string>* override_of(const RawScene& scene,
                                                             const std::string& path);

/// "stages[2].kind" -> "stages[].kind" (the schema's form).
std::string normalise(const std::string& path);

}  // namespace rockfdem::workflows::detail
