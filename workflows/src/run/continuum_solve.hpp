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

/// The elastic counterpart solved in the implicit stage's own solve: its
/// construction sequence begins with the implicit stage's alphas and the
/// same problem (the lining, where it joins, only below the last of them),
/// so the implicit stage goes on to its end instead of the counterpart
/// solving those alphas again. `take` is called with every field of that
/// solve, in order, before the implicit stage's own sampling: it copies the
/// counterpart's hand-off (the implicit stage's last alpha) unless the run
/// hands over that field itself (`handoff_is_runs`), keeps the end's arrays
/// and frees the rest of the tail's.
struct CounterpartTail {
  ContinuumStates states;  ///< seconds: the tail's alone
  std::size_t implicit_alphas = 0, seen = 0;
  bool handoff_is_runs = false;  ///< the scene's rule hands over the last alpha's field
  void take(insitu::InsituField& f);
};

/// The tail for the implicit stage's `spec` (its alphas and lining extended
/// to the whole sequence), or none: no core removed (no counterpart), a
/// Mohr-Coulomb counterpart, or a sequence that does not continue the
/// implicit stage's.
std::optional<CounterpartTail> counterpart_tail(const Scene& scene, insitu::InsituSpec& spec);

/// The solves compare_with_continuum_counterpart and the open-hole
/// comparison need, for a scene whose stages remove the core (none
/// otherwise: nothing would be compared). `scene` has the alphas solved;
/// `counterpart`, when given, was solved already (CounterpartTail).
ContinuumReferences solve_continuum_references(
    const Scene& scene, const RunContext& ctx, const mesh::Mesh& m,
    std::optional<ContinuumStates> counterpart = std::nullopt);

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
