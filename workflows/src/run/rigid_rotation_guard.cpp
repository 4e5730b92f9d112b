#include "run/rigid_rotation_guard.hpp"

#include <cmath>
#include <cstdio>

#include "rockfdem/error.hpp"

namespace rockfdem::workflows {

void check_rigid_rotation(const RigidFit& fit, bool rollers, long step) {
  const double deg = fit.rotation * 180 / M_PI;
  if (rollers || !(std::abs(deg) > kRigidRotationLimitDeg)) return;
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "fdem: step %ld: the outer boundary turned %.3g deg as a rigid body (limit "
                "%g deg): the box, loaded by tractions alone, has a rigid-body mode and is "
                "rotating on the broken ground around the opening; keep insitu.rollers = true",
                step, deg, kRigidRotationLimitDeg);
  throw NumericalError(msg);
}

}  // namespace rockfdem::workflows
