// The explicit steps `rockfdem check` expects a run to take, stage by
// stage, and the caps that bound them (docs/workflow.md, "check";
// docs/benchmarks.md, "The run-time estimate against every shipped scene").
//
// A stage that ends at a criterion (an unbalanced-force ratio, a grout
// trigger) ends when the model has relaxed, and a damped model relaxes in
// a number of wave transits, not in a share of whatever cap the scene
// sets. The transit is counted in steps from the mesh and the step:
//
//   transit = sum over the element layers from the opening to the box's
//             side of (layer width / (c_eff dt)),
//
// where c_eff is the P-wave speed the step sees: with quasi-static mass
// scaling every element is slowed to the coarsest one's step, so each
// layer takes h_far / (c_p dt) steps whatever its size; without, a layer
// of width dx takes dx / (c_p dt). A stage with a ratio criterion then
// settles in
//
//   n = kSettleTransits x transit x ln(1 / ratio) / ln(1000)
//
// (an exponentially damped residual falls by a fixed factor per transit),
// and where the rock around the opening fails (its wall stress beyond the
// rock's strength, below) the breaking goes on for kFailureTransits more,
// spent by the stages in their order (soften stages at their caps spend
// most of it before the support goes in). A stage takes no fewer than
// `hold` output intervals, is rounded up to an output and kept to its cap;
// a grout stage fires after kGroutTransits. The counts are fitted on the
// shipped tunnels' runs (docs/benchmarks.md).
#pragma once

#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Transits to settle at an unbalanced-force ratio of 1e-3 (the elastic
/// test tunnel 16 at 1e-3, kirsch-circular over 41; the equilibrium
/// stages of the default, the mudstone and the calibrated tunnels 27-33),
/// and the failure's (after a one-shot hand-off the seed's rock took
/// 77-113 transits in all to equilibrium or to being found unstable, the
/// progressive default 84 from its hand-off). A grout trigger counting
/// breaks since the support fired after 10-13 transits.
inline constexpr double kSettleTransits = 25.0;
inline constexpr double kFailureTransits = 65.0;
inline constexpr double kGroutTransits = 12.0;
/// A specimen loaded to its peak and stopped after it (loading.stop_after_peak
/// > 0): the four shipped ones ended at 0.51-0.79 of their steps.
inline constexpr double kSpecimenShare = 0.7;

/// The steps a P-wave takes from a tunnel's opening to the box's side on a
/// step dt [s] with the rock's P-wave speed cp [m/s]; 0 for specimens and
/// .msh models (whose grading check does not know).
double transit_steps(const Scene& s, double dt, double cp);

/// The local element size gmsh aims for at a distance d [m] from the
/// opening: size_near within the fracture zone, then graded linearly to
/// size_far over the grading distance.
double local_size(const mesh::MeshSpec& m, double d);

/// Whether the rock fails at the opening: a fracture zone, and the wall
/// stress at a circular opening, 3 sigma_max - sigma_min (Kirsch), above
/// the rock's UCS (Mohr-Coulomb of its c and phi).
bool rock_fails_at_opening(const Scene& s);

/// Whether it fails all at once: the hand-off releases the excavation's
/// load in one step (no soften stage), so the ground breaks into blocks
/// that stay in contact (the one-shot, unsupported and paper-support
/// tunnels), not crack by crack.
bool fails_at_once(const Scene& s);

/// Whether the scene runs stages (tunnels, .msh models) rather than a
/// specimen's single loading.
bool staged(const Scene& s);

/// Explicit steps at the caps: the stages' max_steps (with the hand-off
/// step) or the specimen's steps.
double explicit_steps(const Scene& s);

/// The steps expected from the transit (above); a stage with a criterion
/// falls back to half its cap where the transit is not known.
double expected_steps(const Scene& s, double transit);

}  // namespace rockfdem::workflows
