// The stage loop's guard against a box turning as a rigid body: the
// outputs measure the outer boundary's rotation (outputs/outer_boundary.hpp),
// the run decides whether it may go on.
#pragma once

#include "outputs/outer_boundary.hpp"

namespace rockfdem::workflows {

/// Throws rockfdem::NumericalError naming `step` and the angle when a box
/// loaded by tractions alone (`rollers` false) has turned by more than
/// kRigidRotationLimitDeg; rollers leave no rigid mode, so nothing to stop.
void check_rigid_rotation(const RigidFit& fit, bool rollers, long step);

}  // namespace rockfdem::workflows
