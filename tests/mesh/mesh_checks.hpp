// Independent checks on a Mesh record used by the mesh tests: areas by zone,
// centroids, edge incidence, and the chord-error bound of meshed arcs.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh::checks {

inline double zone_area(const Mesh& m, int zone) {
  double a = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (zone == 0 || m.zone[t] == zone) a += signed_area(m, t);
  return a;
}

struct Point {
  double x, y;
};

inline Point centroid(const Mesh& m, std::size_t t) {
  const auto& [a, b, c] = m.triangles[t];
  return {(m.x[a] + m.x[b] + m.x[c]) / 3, (m.y[a] + m.y[b] + m.y[c]) / 3};
}

using EdgeKey = std::pair<int, int>;
inline EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// Every triangle edge -> the triangles that have it.
inline std::map<EdgeKey, std::vector<std::size_t>> edge_triangles(const Mesh& m) {
  std::map<EdgeKey, std::vector<std::size_t>> out;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      out[key(m.triangles[t][k], m.triangles[t][(k + 1) % 3])].push_back(t);
  return out;
}

inline double edge_length(const Mesh& m, int a, int b) {
  return std::hypot(m.x[a] - m.x[b], m.y[a] - m.y[b]);
}

/// Upper bound of the area an inscribed polygon loses against the outline's
/// arcs when no chord is longer than h: a chord over angle phi cuts off
/// R^2 (phi - sin phi) / 2, which per unit angle grows with phi, so chords
/// of the longest angle theta = 2 asin(h / 2R) lose the most: the bound is
/// (arc angle / theta) * R^2 (theta - sin theta) / 2 per arc.
inline double chord_loss_bound(const Outline& o, double h) {
  double bound = 0;
  for (const OutlinePiece& p : o.pieces) {
    if (!p.is_arc) continue;
    const double r = p.radius, theta = 2 * std::asin(std::min(1.0, h / (2 * r)));
    bound += (p.a1 - p.a0) / theta * r * r * (theta - std::sin(theta)) / 2;
  }
  return bound;
}

}  // namespace rockfdem::mesh::checks
