#include "outputs/face_distance.hpp"

#include <cmath>

#include "outputs/support_lines.hpp"
#include "rockfdem/insitu/plastic.hpp"

namespace rockfdem::workflows {

double ldp_displacement_fraction(double x_star, double r_star) {
  const double u0 = std::exp(-0.15 * r_star) / 3;
  if (x_star <= 0) return u0 * std::exp(x_star);
  return 1 - (1 - u0) * std::exp(-3 * x_star / (2 * r_star));
}

double ldp_plastic_radius(const Scene& scene, double radius) {
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  if (!(rock.cohesion > 0)) return radius;
  insitu::PlasticRingCase c;
  c.a = radius;
  c.p0 = 0.5 * (scene.insitu.sigma_h + scene.insitu.sigma_v);
  c.E = rock.young;
  c.nu = rock.poisson;
  c.strength = {rock.cohesion, rock.friction_angle, 0};
  return insitu::plastic_ring(c).plastic_radius;
}

double alpha_at_fraction(const std::vector<double>& alphas, const std::vector<double>& u,
                         double fraction) {
  const double target = fraction * u.back();
  for (std::size_t i = 1; i < alphas.size(); ++i) {
    if (u[i] < target) continue;
    if (!(u[i] > u[i - 1])) return alphas[i];  // a flat stretch: nothing to interpolate
    const double s = (target - u[i - 1]) / (u[i] - u[i - 1]);
    return alphas[i - 1] + s * (alphas[i] - alphas[i - 1]);
  }
  return alphas.back();
}

double mean_wall_displacement(const mesh::Mesh& m, const insitu::InsituField& f, double cx,
                              double cy) {
  std::vector<std::uint8_t> rock(m.n_vertices(), 0), opening(m.n_vertices(), 0);
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (const int v : m.triangles[t])
      (m.zone[t] == mesh::kRock ? rock : opening)[std::size_t(v)] = 1;
  double sum = 0;
  int n = 0;
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    if (!rock[v] || !opening[v]) continue;
    const double dx = cx - m.x[v], dy = cy - m.y[v], d = std::hypot(dx, dy);
    sum += (f.ux[v] * dx + f.uy[v] * dy) / d;
    ++n;
  }
  return n ? sum / n : 0.0;
}

double wall_displacement(const mesh::Mesh& m, const insitu::InsituField& f) {
  const EquivalentOpening o = equivalent_opening(m);
  return mean_wall_displacement(m, f, o.cx, o.cy);
}

FaceDistanceFigures face_distance_installation(const Scene& scene, const mesh::Mesh& m,
                                               const std::vector<ImplicitSample>& curve) {
  const EquivalentOpening o = equivalent_opening(m);
  FaceDistanceFigures f;
  f.face_distance_m = *scene.insitu.install_at_face_distance;
  f.radius_m = o.radius;
  f.plastic_radius_m = std::max(o.radius, ldp_plastic_radius(scene, o.radius));
  f.x_star = f.face_distance_m / o.radius;
  f.r_star = f.plastic_radius_m / o.radius;
  f.u_star = ldp_displacement_fraction(f.x_star, f.r_star);
  std::vector<double> alphas, u;
  for (const ImplicitSample& field : curve) {
    alphas.push_back(field.alpha);
    u.push_back(field.wall_displacement);
  }
  f.alpha = alpha_at_fraction(alphas, u, f.u_star);
  return f;
}

}  // namespace rockfdem::workflows
