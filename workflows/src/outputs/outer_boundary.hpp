// The outer boundary's rigid motion: a model loaded by tractions alone has
// three zero-energy modes (two translations and a rotation); damping slows
// them but does not remove them, and once a ring around the opening is
// fully broken the outer block can turn on it. The least-squares rigid fit
// of the boundary's displacements measures that motion; the run reports it
// and the stage loop stops it when it exceeds kRigidRotationLimitDeg
// (run/rigid_rotation_guard.hpp).
#pragma once

#include <array>
#include <vector>

namespace rockfdem::workflows {

/// Rotation above which the outer boundary is turning as a rigid body [deg].
/// Elastic deformation of a loaded box gives a fitted rotation many orders
/// below it; the collapse it guards against passed it within 20,000 steps.
constexpr double kRigidRotationLimitDeg = 0.01;

struct RigidFit {
  double tx = 0, ty = 0;  ///< mean translation [m]
  double rotation = 0;    ///< counter-clockwise [rad], about the points' centroid
};

/// The rigid motion t + theta k x (p - c) closest (least squares) to the
/// displacements (ux, uy) of the points (x, y); all vectors of one size.
RigidFit rigid_fit(const std::vector<double>& x, const std::vector<double>& y,
                   const std::vector<double>& ux, const std::vector<double>& uy);

}  // namespace rockfdem::workflows
