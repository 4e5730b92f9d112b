// The typed figures of a tunnel run's continuum comparisons, once the core
// is removed: FDEM against the open excavation's field ("comparison") and
// against the continuum counterpart of the construction sequence
// ("continuum_comparison"). summary.cpp writes them (docs/workflow.md).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rockfdem::workflows {

/// The region both comparisons cover ("region").
constexpr const char* kComparisonRegion = "rock within 5 half-spans of the opening's centre";

/// "comparison": the engine's final stresses against the implicit field of
/// the open excavation (alpha = 0) and, for a circular opening without
/// lining in uniform stress, Kirsch.
struct ContinuumComparison {
  std::size_t triangles = 0;  ///< the rock triangles compared
  double fdem_vs_insitu_rel_l2 = 0;
  std::optional<double> fdem_vs_kirsch_rel_l2;  ///< none: no closed form (null)
};

/// A key point's displacement in both [mm] (x, y)
/// ("continuum_comparison"."key_points".NAME).
struct CounterpartKeyPoint {
  std::array<double, 2> fdem_end_mm{}, continuum_end_mm{}, fdem_handoff_mm{};
  std::optional<std::array<double, 2>> continuum_handoff_mm;  ///< none: no hand-off (null)
};

/// A Mohr-Coulomb counterpart's yielded ground.
struct CounterpartYield {
  std::size_t triangles = 0;              ///< "yielded_triangles": ever flowed
  std::map<std::string, double> depth_m;  ///< "yielded_depth_m" per ray; empty: no key
};

/// One point of the Mohr-Coulomb ground reaction curve: the unsupported
/// release to lambda, per key point the inward radial displacement [mm]
/// and the fictitious support pressure (1 - lambda) p0 [Pa] there
/// ("continuum_comparison"."ground_reaction"[i]).
struct ContinuumGroundReactionPoint {
  double lambda = 0;
  struct AtKeyPoint {
    double radial_mm = 0, pressure_Pa = 0;
  };
  std::map<std::string, AtKeyPoint> key_points;
};

/// "continuum_comparison": the FDEM state against the continuum solution
/// of the scene's construction sequence.
struct CounterpartComparison {
  std::string model;  ///< "elastic" or "mohr_coulomb"
  std::vector<double> sequence_alpha;
  double solve_seconds = 0;
  std::optional<double> lining_alpha;  ///< none: no lining (null)
  double stress_rel_l2_end = 0;
  std::optional<double> stress_rel_l2_handoff;  ///< none: no hand-off state (null)
  std::map<std::string, CounterpartKeyPoint> key_points;
  std::optional<CounterpartYield> yield;  ///< Mohr-Coulomb only
  /// Mohr-Coulomb only: the unsupported release, to lambda = 1 or as far as
  /// the ground stands (its last lambda).
  std::vector<ContinuumGroundReactionPoint> ground_reaction;
};

/// The Mohr-Coulomb counterpart with the FDEM's post-peak strength: the
/// rock's c and phi until it yields, then c = 0 and phi =
/// residual_friction_angle at once (elastic-brittle-plastic: a broken FDEM
/// contact keeps friction only). Without cohesion an unsupported opening
/// has no equilibrium in the closed form (Brown et al. 1983: R_pl grows as
/// pi^(-1/(k_r - 1)) as the support pressure pi -> 0); here "none" is a
/// release step that does not converge or a plastic zone that reaches the
/// model's outer boundary.
/// ("continuum_post_peak", insitu.continuum_post_peak = true.)
struct PostPeakCounterpart {
  bool equilibrium = false;
  double alpha = 1;           ///< the end of the sequence (converged) [-]
  std::size_t n_yielded = 0;  ///< triangles that flowed (converged)
  double residual_friction_deg = 0;
  std::string reason;  ///< why there is no equilibrium
  double seconds = 0;  ///< wall time of the solve
};

}  // namespace rockfdem::workflows
