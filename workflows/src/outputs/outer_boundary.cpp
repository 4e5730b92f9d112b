#include "outputs/outer_boundary.hpp"

#include <cmath>
#include <cstdio>

#include "rockfdem/error.hpp"

namespace rockfdem::workflows {

RigidFit rigid_fit(const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& ux, const std::vector<double>& uy) {
  RigidFit f;
  const std::size_t n = x.size();
  if (n == 0) return f;
  double cx = 0, cy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    cx += x[i];
    cy += y[i];
    f.tx += ux[i];
    f.ty += uy[i];
  }
  cx /= double(n);
  cy /= double(n);
  f.tx /= double(n);
  f.ty /= double(n);
  // With the translation removed, theta minimises sum |u - theta k x r|^2:
  // theta = sum (r x u) / sum |r|^2.
  double moment = 0, inertia = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double rx = x[i] - cx, ry = y[i] - cy;
    moment += rx * (uy[i] - f.ty) - ry * (ux[i] - f.tx);
    inertia += rx * rx + ry * ry;
  }
  f.rotation = inertia > 0 ? moment / inertia : 0.0;
  return f;
}

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
