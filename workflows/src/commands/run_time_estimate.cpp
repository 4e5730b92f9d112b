#include "commands/run_time_estimate.hpp"

namespace rockfdem::workflows {

RunTimeFigures run_time(const RunTimeInputs& in) {
  RunTimeFigures r;
  const auto factor = [&](double fracture, double joints) {
    return (1 + (fracture - 1) * in.fracture_share) * (in.joints ? joints : 1.0);
  };
  // The joints' cost was measured on a rock failing at once, its blocks
  // in contact along the joints: it is not raised twice.
  const bool at_once = in.fails_at_once && !in.joints;
  r.expected_step_factor =
      factor(at_once ? kFailsAtOnceCost : kExpectedFractureCost, kExpectedJointCost);
  r.worst_step_factor = factor(kWorstFractureCost, kWorstJointCost);
  r.least = in.fixed_seconds;
  r.estimate = in.fixed_seconds + in.expected_steps * in.seconds_per_step * r.expected_step_factor;
  r.bound =
      kRunTimeMargin * (in.fixed_seconds + in.steps * in.seconds_per_step * r.worst_step_factor);
  return r;
}

}  // namespace rockfdem::workflows
