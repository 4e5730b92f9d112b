#include "outputs/loading_frame.hpp"

namespace rockfdem::workflows {

std::optional<LoadingStrain> loading_strain(const Scene& s) {
  const InsituSettings& in = s.insitu;
  const auto rock = s.materials.find(mesh::kRock);
  if (rock == s.materials.end() || rock->second.young <= 0) return std::nullopt;
  if (in.sigma_h == 0 && in.sigma_v == 0) return std::nullopt;
  if (in.angle_deg != 0 || in.unit_weight != 0 || s.engine.gravity != 0) return std::nullopt;
  const double E = rock->second.young, nu = rock->second.poisson;
  // Hooke's law inverted: plane strain (eps_zz = 0) or plane stress.
  const double a = s.plane_stress ? 1 : 1 - nu * nu;
  const double b = s.plane_stress ? nu : nu * (1 + nu);
  const mesh::DomainSpec& d = s.mesh.domain;
  LoadingStrain e;
  e.xx = (a * in.sigma_h - b * in.sigma_v) / E;
  e.yy = (a * in.sigma_v - b * in.sigma_h) / E;
  e.base_y = d.center_y - d.height / 2;
  e.centre_x = d.center_x;
  return e;
}

std::array<double, 2> loading_displacement(const LoadingStrain& e, double x, double y) {
  return {-e.xx * (x - e.centre_x), -e.yy * (y - e.base_y)};
}

}  // namespace rockfdem::workflows
