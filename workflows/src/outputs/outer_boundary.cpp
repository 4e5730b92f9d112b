#include "outputs/outer_boundary.hpp"

#include <cmath>

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

}  // namespace rockfdem::workflows
