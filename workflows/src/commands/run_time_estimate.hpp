// `rockfdem check`'s run time from its probe: an estimate, the range it
// may fall in and a bound (docs/workflow.md, "check"; the constants are
// measured in docs/benchmarks.md, "check's bounds against runs").
//
//   fixed   start-up, meshing, implicit solves, outputs, stage changes,
//           the pictures and report at the end
//   steps   the explicit steps (n_expected, or at their caps n_caps), each
//           at the probe's cost
//           (an unloaded, intact model without in-situ stress), raised for
//           fracture on the share f of triangles that may fracture and,
//           with joints, for the joints the run loads in contact:
//   estimate = fixed + n_expected t_step (1 + (c_expected - 1) f) j_expected
//              (c_expected: kFailsAtOnceCost where the rock fails at
//              once, without joints: theirs counts its blocks in contact)
//   bound    = margin (fixed + n_caps t_step (1 + (c_worst - 1) f) j_worst)
//   least    = fixed: stages that end at a criterion (equilibrium, a grout
//              trigger) may end long before their caps.
// Runs that reach equilibrium stop short of their caps: the expected
// steps count the model's wave transits (expected_steps.hpp).
#pragma once

namespace rockfdem::workflows {

struct RunTimeInputs {
  double fixed_seconds = 0;     ///< everything but the explicit steps [s]
  double seconds_per_step = 0;  ///< the probe's, intact [s]
  double steps = 0;             ///< explicit steps at their caps
  double expected_steps = 0;    ///< those the run is expected to take
  double fracture_share = 0;    ///< triangles that may fracture, of all
  bool joints = false;          ///< the mesh has joint traces
  bool fails_at_once = false;   ///< the rock fails at once (expected_steps.hpp)
};

struct RunTimeFigures {
  double least = 0, estimate = 0, bound = 0;  ///< [s]
  /// A step's cost over the probe's, expected and at worst.
  double expected_step_factor = 0, worst_step_factor = 0;
};

/// A step's cost after fracture over the probe's intact one, on the share
/// that may fracture: expected (whole runs' fdem time per step over the
/// probe's just before them, on the shared 2-core machine, two rounds,
/// docs/benchmarks.md: 0.43-1.51 for the specimens and the tunnels whose
/// rock breaks crack by crack, geometric mean 0.95; 1.75-2.39 at a share
/// of 0.62 for those that fail at once, whose broken blocks stay in
/// contact: 2.1) and at worst (a confined specimen fell to 0.24 of its
/// intact throughput). With joints, the jointed tunnel's steps cost 2.7
/// and 10 times the probe's (its joints loaded in contact, the probe's
/// not; the second under a load that rose while it ran). The bound's
/// margin on the whole.
inline constexpr double kExpectedFractureCost = 1.0;
inline constexpr double kFailsAtOnceCost = 2.8;
inline constexpr double kWorstFractureCost = 4.0;
inline constexpr double kExpectedJointCost = 3.5;
inline constexpr double kWorstJointCost = 12.0;
inline constexpr double kRunTimeMargin = 1.5;

RunTimeFigures run_time(const RunTimeInputs& in);

}  // namespace rockfdem::workflows
