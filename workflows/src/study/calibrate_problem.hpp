// The calibration problem: free scene numbers scaled to [0, 1], runs as
// study variants, and the objective
//
//   F(x) = sum_i w_i ((s_i(x) - t_i) / t_i)^2
//
// over the targets t_i (key-point displacements in mm, specimen stresses in
// MPa) and the runs' figures s_i. With --realisations N each point runs the
// heterogeneity seeds 1..N and s_i is the mean of their figures
// (realisations.hpp). Every point is recorded in order.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/workflows/cli.hpp"
#include "study/realisations.hpp"
#include "study/study_run.hpp"

namespace rockfdem::workflows::study {

/// One point the optimiser (or the sensitivity step) asked for.
struct Evaluation {
  std::vector<double> x;       ///< scaled parameters, in [0, 1]
  Variant variant;             ///< the free keys' values (without a seed)
  VariantResult result;        ///< its run, or its realisations merged
  double objective = 0;        ///< F; kFailedObjective where a target is missing
  std::size_t n = 1;           ///< the runs its figures are the mean of (Realisations::n)
  std::vector<double> spread;  ///< per target: their standard deviation (NaN for n < 2)
};

class CalibrationProblem {
 public:
  /// A failed run, or one without a target's figure, scores this.
  static constexpr double kFailedObjective = 1e3;
  /// A run that stopped before its criteria held (`unstable`,
  /// `not_at_equilibrium`) scores this plus its misfit: its figures are not
  /// equilibrium figures, so any run that met its criteria with a misfit
  /// below this ranks ahead of it, and among such runs the search still
  /// follows the misfit. So does a point any of whose realisations did not
  /// complete, with the misfit of the completed ones' mean.
  static constexpr double kNotAtEquilibriumObjective = 1e2;
  /// Whether a run's figures are answers the targets may be fitted to.
  static bool met_its_criteria(const VariantResult& r);

  CalibrationProblem(const CommandLine& cli, std::vector<FreeKey> free,
                     std::vector<Target> targets);
  const std::vector<FreeKey>& free() const { return free_; }
  const std::vector<Target>& targets() const { return targets_; }
  /// --realisations N: N; 0 without the flag (one run per point).
  std::size_t realisations() const { return seeds_.values.size(); }
  /// The parameter values at scaled x.
  std::vector<double> values(const std::vector<double>& x) const;
  Variant variant(const std::vector<double>& x) const;
  /// The scaled start: each key's value in the scene where it lies in its
  /// bounds, the middle of the bounds otherwise.
  std::vector<double> start(const Scene& scene) const;
  /// Runs the points (spread over the ranks; call on every rank: rank 0
  /// passes the points, the others wait in serve()), records them and
  /// returns their evaluations on rank 0.
  std::vector<Evaluation> evaluate(const std::vector<std::vector<double>>& points);
  /// The other ranks: run batches until rank 0 calls finish().
  void serve();
  void finish();
  const std::vector<Evaluation>& record() const { return record_; }
  /// The figure `target` names in a run, or NaN.
  static double figure(const VariantResult& r, const Target& target);

 private:
  std::vector<Evaluation> run_batch(const std::vector<std::vector<double>>& points);
  /// The point's runs: the variant, or its realisations.
  std::vector<Variant> runs_of(const Variant& v) const;
  Evaluation evaluation(const std::vector<double>& x, const std::vector<VariantResult>& runs) const;
  double objective(const Realisations& m) const;
  CommandLine cli_;
  std::vector<FreeKey> free_;
  std::vector<Target> targets_;
  VariedKey seeds_;  ///< --realisations: the seeds; no values without it
  std::vector<Evaluation> record_;
};

}  // namespace rockfdem::workflows::study
