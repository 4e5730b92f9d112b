// The study flags read into checked records: --vary (sweep), --free,
// --target and --weight (calibrate), --realisations (both). Every refusal is an InputError that
// names the flag, its value and what is allowed (exit 2).
#pragma once

#include <string>
#include <vector>

#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows::study {

/// One --vary: a list of values (the product) or a range (Latin hypercube).
struct VariedKey {
  std::string key;                  ///< scene key, as --set spells it
  std::vector<std::string> values;  ///< list: the values' text, as given
  bool range = false;
  double lo = 0, hi = 0;  ///< range: bounds, in the key's unit
};

/// One --free: a scene number the optimiser moves within [lo, hi].
struct FreeKey {
  std::string key;
  double lo = 0, hi = 0;
};

/// One --target: a figure of the run's summary and the value to match.
struct Target {
  std::string name;    ///< vault, left_shoulder, ..., peak_stress, tensile_strength
  std::string column;  ///< the key figure it reads (study_figures.hpp)
  double value = 0;    ///< mm for key points and chords, MPa for specimen stresses
  double weight = 1;
};

/// --vary, all lists (samples == 0) or all ranges (samples > 0), then the
/// seeds of --realisations (a list) where it is given.
std::vector<VariedKey> read_vary(const StudyOptions& options);

/// --free: number keys with finite bounds lo < hi.
std::vector<FreeKey> read_free(const StudyOptions& options);

/// --target and --weight; the names allowed depend on the scene's model.
std::vector<Target> read_targets(const StudyOptions& options, const Scene& scene);

/// The key --realisations N varies: materials.rock.heterogeneity_seed.
extern const char* const kRealisationKey;

/// --realisations N: the seeds 1..N of kRealisationKey, N from 2 to 10000;
/// no values when the flag is not given.
VariedKey read_realisations(const StudyOptions& options);

/// Refuses --realisations when no run's rock is heterogeneous
/// (materials.rock.heterogeneity = 0): every seed would give the same run.
void check_realisations_differ(const StudyOptions& options, bool heterogeneous);

/// Whether the scene's rock has strength heterogeneity (a Weibull modulus > 0).
bool heterogeneous_rock(const Scene& scene);

/// The scene with `overrides` added to the command line's; a refusal is
/// rethrown naming `flag` and `value` first.
Scene scene_with(const CommandLine& cli, const std::vector<std::string>& overrides,
                 const std::string& flag, const std::string& value);

}  // namespace rockfdem::workflows::study
