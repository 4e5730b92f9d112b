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
// of width dx takes dx / (c_p dt). A stage with a ratio criterion is then
// expected to take
//
//   n = transits x transit x ln(1 / ratio) / ln(1000),
//
// (an exponentially damped residual falls by a fixed factor per transit),
// no fewer than `hold` output intervals, rounded up to an output and at
// most its cap; a grout stage fires after grout transits. The transit
// counts are fitted on the shipped tunnels (the constants below).
#pragma once

#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Transits a stage takes to an unbalanced-force ratio of 1e-3, fitted on
/// the shipped tunnels' runs (docs/benchmarks.md): geometric means of the
/// stages' steps over their transits. A model that fractures relaxes
/// through its cracking (the default's equilibrium stage 27 transits, the
/// one-shot's 113, the unsupported tunnel's until it was found unstable
/// 93); an elastic one as a damped wave (the elastic test tunnel 16 at
/// 1e-3, kirsch-circular over 41). A grout trigger fired after 10-13
/// transits where it counts breaks since the support.
inline constexpr double kFractureTransits = 55.0;
inline constexpr double kElasticTransits = 25.0;
inline constexpr double kGroutTransits = 12.0;
/// A specimen loaded to its peak and stopped after it (loading.stop_after_peak
/// > 0) ended at 0.55-0.79 of its steps: the expected share.
inline constexpr double kSpecimenShare = 0.7;

/// The steps a P-wave takes from a tunnel's opening to the box's side on a
/// step dt [s] with the rock's P-wave speed cp [m/s]; 0 for specimens and
/// .msh models (whose grading check does not know).
double transit_steps(const Scene& s, double dt, double cp);

/// The local element size gmsh aims for at a distance d [m] from the
/// opening: size_near within the fracture zone, then graded linearly to
/// size_far over the grading distance.
double local_size(const mesh::MeshSpec& m, double d);

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
