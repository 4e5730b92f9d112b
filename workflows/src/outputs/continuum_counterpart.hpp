// The continuum counterpart of a tunnel run: the scene's construction
// sequence solved by deal.II, elastic or Mohr-Coulomb (insitu.continuum;
// the solves are the run's, run/continuum_solve.hpp), and its comparison
// with the FDEM state (summary "continuum_comparison", continuum_profiles.csv
// and .png; docs/workflow.md).
//
// The sequence: the implicit stage's alphas, the soften stages' alphas, 0 at
// remove_core; the lining (where the scene installs one) joins stress-free
// at the alpha of its stage, as the engine's lining stage does. Elastic: the
// in-situ solver with the lining active from that alpha. Mohr-Coulomb: the
// release lambda = 1 - alpha of the in-situ wall traction. Bolts have no
// counterpart.
#pragma once

#include <string>
#include <vector>

#include "outputs/monitors.hpp"
#include "record/continuum_figures.hpp"
#include "record/run_context.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

struct ContinuumStates {
  std::string model;            ///< "elastic" or "mohr_coulomb"
  insitu::InsituField handoff;  ///< at the implicit stage's last alpha
  /// The run hands over that very field ("last" rule) and holds it whole:
  /// `handoff` then keeps its alpha alone, not a second copy of its arrays.
  bool handoff_is_runs = false;
  insitu::InsituField end;            ///< core removed, support (lining) in
  std::vector<double> alphas;         ///< the sequence solved
  double lining_alpha = -1;           ///< alpha at which the lining joined; -1: none
  std::vector<std::uint8_t> yielded;  ///< Mohr-Coulomb: per triangle, ever flowed
  std::size_t n_yielded = 0;
  double seconds = 0;  ///< wall time of the solve
  /// The hand-off's arrays: `handoff`'s, or `runs` (the run's hand-off field).
  const insitu::InsituField& handoff_field(const insitu::InsituField& runs) const {
    return handoff_is_runs ? runs : handoff;
  }
};

/// FDEM (the hand-off field and the engine's final state) against the
/// continuum: relative L2 of the stresses near the opening at the hand-off
/// and at the end, the key points' displacements, and radial and tangential
/// stress along rays from the opening through the key points
/// (continuum_profiles.csv, and continuum_profiles.png when `plots`).
/// Rock only: the triangles of bolt strips (`bolted`, per triangle; empty
/// where there are none) carry the steel's scaled stress, which the
/// continuum has no counterpart of. Returns the figures of summary
/// "continuum_comparison".
CounterpartComparison compare_with_counterpart(
    const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
    const insitu::InsituField& fdem_handoff, const ContinuumStates& c,
    const std::vector<Monitor>& monitors, const std::vector<char>& bolted, const std::string& dir,
    RunRecord& summary, bool quiet);

}  // namespace rockfdem::workflows
