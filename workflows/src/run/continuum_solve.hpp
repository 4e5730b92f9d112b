// The continuum counterpart's solves: the scene's construction sequence
// solved by deal.II, elastic or Mohr-Coulomb (insitu.continuum), and with
// the post-peak strength. The run solves them before it builds the engine
// and compares once its stages are done (outputs/continuum_counterpart.hpp):
// the solves' matrices and preconditioners then reuse the memory the
// engine takes later, and the run's peak is the larger of the two, not
// their sum.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "outputs/continuum_counterpart.hpp"
#include "outputs/monitors.hpp"
#include "record/run_context.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Solves the scene's sequence as a continuum (outputs/continuum_counterpart.hpp).
ContinuumStates solve_continuum_counterpart(const Scene& scene, const mesh::Mesh& m);

/// Solves the scene's sequence with the post-peak strength (outputs/continuum_counterpart.hpp).
/// Throws InputError when the scene's strengths cannot be posed that way
/// (residual friction above the peak's or below the dilation angle). The
/// run calls it only when insitu.continuum_post_peak asks: where there is
/// no equilibrium it costs many failing Newton steps (39 s on a 0.3 m mesh
/// of a 3 m tunnel, over 10 min at 0.15 m).
PostPeakCounterpart solve_post_peak_counterpart(const Scene& scene, const mesh::Mesh& m);

/// The continuum solves a tunnel run compares its end state with; a member
/// left empty was not asked for or could not be solved.
struct ContinuumReferences {
  std::optional<insitu::InsituField> open_hole;  ///< alpha = 0, no lining (scenes without a ring)
  std::optional<ContinuumStates> counterpart;
  std::optional<PostPeakCounterpart> post_peak;
  std::vector<std::string> skipped;  ///< why a solve failed, for summary "skipped"
};

/// The solves compare_with_continuum_counterpart and the open-hole
/// comparison need, for a scene whose stages remove the core (none
/// otherwise: nothing would be compared). `scene` has the alphas solved.
ContinuumReferences solve_continuum_references(const Scene& scene, const RunContext& ctx,
                                               const mesh::Mesh& m);

/// The counterpart `solved` compared (compare_with_counterpart) for a
/// finished tunnel run, into summary
/// "continuum_comparison"; a counterpart that cannot be solved (e.g. the
/// Mohr-Coulomb ground collapses) is noted in "skipped" and the run goes on.
void compare_with_continuum_counterpart(const Scene& scene, const RunContext& ctx,
                                        const mesh::Mesh& m, const fdem::Engine& e,
                                        const insitu::InsituField& fdem_handoff,
                                        const ContinuumReferences& solved,
                                        const std::vector<Monitor>& monitors,
                                        const std::vector<char>& bolted, RunRecord& summary);

}  // namespace rockfdem::workflows
