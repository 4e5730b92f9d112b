// Where each support line meets the ground reaction curve: the
// convergence-confinement method's equilibrium (Carranza-Torres and
// Fairhurst 2000) on the run's own curves, for report.md and summary.json
// ("convergence_confinement"."equilibrium"). Figures only: no engine.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "record/continuum_figures.hpp"
#include "record/run_figures.hpp"

namespace rockfdem::workflows {

/// The ground's curve on the equivalent circle: the key points' mean radial
/// displacement [mm] against their mean pressure on the opening [Pa], in
/// order of falling pressure.
struct GroundCurve {
  std::string source;  ///< "mohr_coulomb" (the counterpart's) or "elastic" (the implicit stage's)
  std::vector<double> radial_mm, pressure_Pa;
  /// The elastic curve is straight in pressure: it is carried on from its
  /// last two points to p = 0 when it stops above (the implicit stage ends
  /// at its smallest alpha). A Mohr-Coulomb curve ends where the ground does.
  bool extended_to_zero = false;
};

/// The Mohr-Coulomb counterpart's release when the run has one, else the
/// implicit stage's points; none with fewer than two points.
std::optional<GroundCurve> ground_curve(const std::vector<GroundReactionPoint>& implicit,
                                        const std::optional<CounterpartComparison>& counterpart);

/// One line's meeting with the curve.
struct SupportEquilibrium {
  std::string name;  ///< the support line's
  bool found = false;
  double radial_mm = 0;    ///< the wall's, from the in-situ state
  double pressure_Pa = 0;  ///< the support's then
  /// p_max over the pressure (none: not loaded); 1 on the line's plateau.
  std::optional<double> factor_of_safety;
  std::string note;  ///< what the meeting means, or why there is none
};

/// For each of c.support, the first u >= the installation's where the
/// ground's pressure falls to the line's, p = min(K (u - u_install), p_max).
std::vector<SupportEquilibrium> support_equilibria(const ConvergenceConfinementFigures& c,
                                                   const GroundCurve& g);

/// The ground's curve and each support line's meeting with it
/// (RunRecord::support_equilibria): found once, when the run records its
/// convergence-confinement figures, and read by report.md and summary.json.
struct SupportEquilibria {
  GroundCurve ground;
  std::vector<SupportEquilibrium> lines;  ///< one per c.support, in its order
};

/// ground_curve, then support_equilibria on it; none without a curve.
std::optional<SupportEquilibria> meet_ground_curve(
    const ConvergenceConfinementFigures& c, const std::vector<GroundReactionPoint>& implicit,
    const std::optional<CounterpartComparison>& counterpart);

}  // namespace rockfdem::workflows
