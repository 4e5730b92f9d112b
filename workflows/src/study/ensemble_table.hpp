// ensemble.csv of a sweep that varies a heterogeneity seed: the variants
// that agree on every other varied key are realisations of one rock, and
// each figure gets its mean, spread and 95% interval over them.
#pragma once

#include <string>
#include <vector>

#include "study/ensemble_stats.hpp"
#include "study/study_run.hpp"

namespace rockfdem::workflows::study {

/// Whether varying `key` draws another realisation of the same rock: its
/// last component is heterogeneity_seed (materials.rock.heterogeneity_seed).
bool is_seed_key(const std::string& key);

/// One figure over one group of realisations.
struct EnsembleRow {
  std::vector<std::string> group;  ///< the group's values of the keys that are not seeds
  std::string figure;
  std::size_t realisations = 0;  ///< variants in the group
  std::size_t excluded = 0;      ///< finished, but not `completed`
  std::size_t pending = 0;       ///< not finished yet
  SampleStats stats;             ///< over the completed realisations with the figure
};

/// The groups in the order of their first variant, each with one row per
/// figure; `keys` are the varied keys in the order of each variant's
/// settings, `results` the variants' results (status "pending": not run).
std::vector<EnsembleRow> ensemble_rows(const std::vector<std::string>& keys,
                                       const std::vector<Variant>& variants,
                                       const std::vector<VariantResult>& results,
                                       const std::vector<std::string>& figures);

/// The figure columns of sweep.csv that have statistics: all but the state
/// hash, a checksum rather than a quantity.
std::vector<std::string> ensemble_figures(const std::vector<std::string>& figure_columns);

/// Writes the rows atomically, long format: the keys that are not seeds,
/// figure, realisations, n, excluded, pending, mean, std, ci95_low,
/// ci95_high, min, max (undefined statistics as empty cells).
void write_ensemble_table(const std::string& path, const std::vector<std::string>& keys,
                          const std::vector<EnsembleRow>& rows);

}  // namespace rockfdem::workflows::study
