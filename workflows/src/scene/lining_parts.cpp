#include "scene/lining_parts.hpp"

#include <limits>

#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {

double invert_top(const Scene& s) {
  return s.invert ? mesh::invert_part_top(s.mesh.tunnel) : -std::numeric_limits<double>::infinity();
}

std::vector<char> invert_triangles(const Scene& s, const mesh::Mesh& m) {
  std::vector<char> out(m.n_triangles(), 0);
  const double top = invert_top(s);
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kLining) continue;
    const auto& v = m.triangles[t];
    const double yc =
        (m.y[std::size_t(v[0])] + m.y[std::size_t(v[1])] + m.y[std::size_t(v[2])]) / 3;
    out[t] = yc < top;
  }
  return out;
}

}  // namespace rockfdem::workflows
