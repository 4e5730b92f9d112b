// A run's key figures, read from its summary.json: what sweep.csv lists per
// variant and what calibrate's targets are matched against.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows::study {

/// The six key points of a tunnel (monitors.hpp), in the summary's names.
const std::vector<std::string>& key_point_names();

/// The figure columns of a run of `scene`'s model, in sweep.csv's order:
/// tunnels: per key point `<name>_radial_mm` (its displacement towards the
/// opening at the end of the run), the vault settlement and the wall and
/// shoulder chord convergences [mm]; specimens: peak_stress_MPa. Then the
/// broken crack elements by mode, the steps run and the state hash.
std::vector<std::string> figure_columns(const Scene& scene);

/// The figures of one run (column -> value); columns its summary lacks
/// (a run stopped early) are absent.
nlohmann::json key_figures(const nlohmann::json& summary);

/// A --target name and the column it reads.
struct TargetName {
  std::string name, column, unit;
};

/// The --target names a scene's model offers.
std::vector<TargetName> target_names(const Scene& scene);
const TargetName* find_target(const std::vector<TargetName>& names, const std::string& name);
/// "allowed: vault, ... (radial displacement, mm)" for messages.
std::string describe(const std::vector<TargetName>& names);

}  // namespace rockfdem::workflows::study
