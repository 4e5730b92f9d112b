// The realisations of one calibration point (calibrate --realisations N:
// the same free values with heterogeneity seeds 1..N) merged into the one
// result the targets are fitted to.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "study/ensemble_stats.hpp"
#include "study/study_run.hpp"

namespace rockfdem::workflows::study {

struct Realisations {
  /// status: `completed` where every realisation completed, else the first
  /// other one's (its reason, named, is the message); figures: the means;
  /// wall time: the sum. A single run is its own result.
  VariantResult result;
  /// The realisations the figures are taken from: the completed ones; where
  /// none completed, the ones that stopped before their criteria held
  /// (unstable, not_at_equilibrium), as a single run's figures are taken;
  /// failed and refused runs never. 0: no figures.
  std::size_t n = 0;
  std::map<std::string, SampleStats> stats;  ///< per numeric figure, over those n
};

Realisations merge_realisations(const std::string& name, const std::vector<VariantResult>& runs);

}  // namespace rockfdem::workflows::study
