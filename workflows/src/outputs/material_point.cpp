#include "outputs/material_point.hpp"

#include <algorithm>

namespace rockfdem::workflows {
namespace {

// Points on a shared edge are in both triangles: a relative tolerance on
// the barycentric coordinates keeps rounding from losing them.
constexpr double kOnEdge = 1e-10;

// Preference among triangles containing the point: rock first.
int rank(int zone) {
  switch (zone) {
    case mesh::kRock:
      return 0;
    case mesh::kLining:
      return 1;
    default:
      return 2;
  }
}

// Barycentric coordinates of (x, y) in triangle t (the CST shape functions).
std::array<double, 3> barycentric(const mesh::Mesh& m, std::size_t t, double x, double y) {
  const auto& v = m.triangles[t];
  const double x0 = m.x[v[0]], y0 = m.y[v[0]], x1 = m.x[v[1]], y1 = m.y[v[1]];
  const double x2 = m.x[v[2]], y2 = m.y[v[2]];
  const double area2 = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
  const double n1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / area2;
  const double n2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / area2;
  return {1 - n1 - n2, n1, n2};
}

}  // namespace

std::optional<MaterialPoint> locate(const mesh::Mesh& m, const fdem::Engine& e, double x,
                                    double y) {
  std::optional<MaterialPoint> found;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const std::array<double, 3> w = barycentric(m, t, x, y);
    if (*std::min_element(w.begin(), w.end()) < -kOnEdge) continue;
    const int zone = m.zone.empty() ? int(mesh::kRock) : int(m.zone[t]);
    if (found && rank(zone) >= rank(found->zone)) continue;
    found = MaterialPoint{int(t), zone, {}, w, x, y};
    // The engine's nodes of t in the order of the mesh's vertices.
    const std::array<int, 3> nodes = e.triangle_nodes(t);
    for (int k = 0; k < 3; ++k)
      for (int node : nodes)
        if (e.node_vertex()[node] == m.triangles[t][k]) found->nodes[k] = node;
  }
  return found;
}

std::array<double, 2> interpolate(const MaterialPoint& p, const NodeDisplacement& u) {
  std::array<double, 2> out{0, 0};
  for (int k = 0; k < 3; ++k) {
    const std::array<double, 2> d = u(p.nodes[k]);
    out[0] += p.weights[k] * d[0];
    out[1] += p.weights[k] * d[1];
  }
  return out;
}

}  // namespace rockfdem::workflows
