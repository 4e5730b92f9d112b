#include "outputs/ground_reaction.hpp"

#include <cmath>

namespace rockfdem::workflows {

std::optional<double> core_pressure(const mesh::Mesh& m, const insitu::InsituField& f, int vertex,
                                    double nx, double ny) {
  double sum = 0;
  int n = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    // A ring not yet installed is softened with the core: it is the opening.
    const bool opening =
        m.zone[t] == mesh::kCore || (m.zone[t] == mesh::kLining && !f.lining_installed);
    if (!opening || !f.active[t]) continue;
    const auto& v = m.triangles[t];
    if (v[0] != vertex && v[1] != vertex && v[2] != vertex) continue;
    const insitu::Stress& s = f.stress[t];
    sum -= nx * nx * s.sxx + 2 * nx * ny * s.sxy + ny * ny * s.syy;
    ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

double insitu_normal_stress(const InsituSettings& s, double nx, double ny) {
  const double a = s.angle_deg * M_PI / 180;
  const double c = nx * std::cos(a) + ny * std::sin(a);  // along sigma_h
  return s.sigma_h * c * c + s.sigma_v * (1 - c * c);
}

}  // namespace rockfdem::workflows
