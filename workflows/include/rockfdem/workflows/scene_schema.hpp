// Every key a scene file may hold: type, unit, default, allowed range and a
// one-line meaning. Validation, defaults and docs/scene-reference.md all come
// from this one table, so they cannot drift apart: the scene builder reads
// each key's value or this table's default, and the Scene structs hold no
// defaults of their own.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rockfdem::workflows {

enum class KeyType {
  kNumber,
  kInteger,
  kBool,
  kString,
  kChoice,
  kNumberArray,
  kStringMap,
  kStringArray
};

struct KeySpec {
  std::string path;  ///< dotted path; "[]" marks an array of tables, e.g. "stages[].kind"
  KeyType type = KeyType::kNumber;
  std::string unit;  ///< SI unit, "-" for dimensionless
  /// The default: a value ("2700", "true", "[1.0]", "\"\"" for the empty
  /// string), or another key whose value it takes ("friction_angle" in the
  /// key's own section, "engine.steps"); empty: none (required where the
  /// model needs it).
  std::string default_text;
  std::string
      default_doc;  ///< the reference's default where it depends on the model; empty: default_text
  double min = -1e300;               ///< lower bound for numbers (and array elements)
  double max = 1e300;                ///< upper bound
  bool min_open = false;             ///< true: value must be > min (else >=)
  bool max_open = false;             ///< true: value must be < max (else <=)
  std::vector<std::string> choices;  ///< allowed strings (kChoice, and kStringMap values)
  std::string description;
};

/// The whole schema in documentation order.
const std::vector<KeySpec>& scene_schema();

/// Most values insitu.alpha may hold: each is a full implicit solve.
inline constexpr std::size_t kMaxAlphas = 100;

/// Most [[stages]] entries a scene may hold: each costs a stage change and
/// an output at its end (10-25 ms on a small tunnel) beyond its steps; a
/// construction sequence has tens.
inline constexpr std::size_t kMaxStages = 1000;

/// Local damping of tunnel stages when engine.local_damping is not given
/// (specimen runs: none).
inline constexpr double kTunnelLocalDamping = 0.8;

/// The spec for a normalised path ("stages[].kind"), or nullptr.
const KeySpec* find_key(const std::string& normalised_path);

/// Where `spec`'s default is another key's value, that key's path for the
/// key at `path` (a relative name resolved in `path`'s own section, so
/// "materials.core.residual_friction_angle" gives
/// "materials.core.friction_angle"); else "".
std::string default_key(const KeySpec& spec, const std::string& path);

/// True when some key lives under this section ("tunnel", "materials.rock", "stages[]").
bool is_known_section(const std::string& normalised_section);

/// Keys directly under a section, for "allowed keys are ..." messages.
std::vector<std::string> keys_in_section(const std::string& normalised_section);

/// "allowed: > 0 (m)" style description of a key's range or choices.
std::string describe_allowed(const KeySpec& spec);

/// docs/scene-reference.md, generated from the schema.
std::string scene_reference_markdown();

}  // namespace rockfdem::workflows
