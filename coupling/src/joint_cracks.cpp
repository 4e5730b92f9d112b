// Joint elements found by their mesh edge (engine nodes back to mesh
// vertices), in a sorted list: no hashing order in the results.
#include "rockfdem/coupling/joint_cracks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace rockfdem::coupling {

std::vector<std::int32_t> joint_crack_traces(const fdem::Engine& e, const mesh::Mesh& m) {
  std::vector<std::array<int, 3>> edges;  // (low vertex, high vertex, trace)
  edges.reserve(m.joint_edges.size());
  for (const mesh::JointEdge& j : m.joint_edges)
    edges.push_back({std::min(j.a, j.b), std::max(j.a, j.b), j.trace});
  std::sort(edges.begin(), edges.end());
  std::vector<std::int32_t> out(e.n_cracks(), 0);
  if (edges.empty()) return out;
  const std::vector<int>& vertex = e.node_vertex();
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto nodes = e.crack_nodes(c);
    const int a = vertex[nodes[0]], b = vertex[nodes[1]];
    const std::array<int, 3> key{std::min(a, b), std::max(a, b), -1};
    const auto it = std::upper_bound(edges.begin(), edges.end(), key);
    if (it != edges.end() && (*it)[0] == key[0] && (*it)[1] == key[1]) out[c] = (*it)[2] + 1;
  }
  return out;
}

JointCounts count_joint_cracks(const fdem::Engine& e, const std::vector<std::int32_t>& traces) {
  JointCounts n;
  for (std::size_t c = 0; c < traces.size(); ++c) {
    if (!traces[c]) continue;
    ++n.elements;
    const auto tri = e.crack_triangles(c);
    if (!e.active(tri[0]) || !e.active(tri[1])) continue;
    ++n.active;
    const double d = e.crack_damage(c);
    n.residual += d >= 1.0;
    n.yielding += d > 0.0 && d < 1.0;
  }
  return n;
}

double crack_normal_opening(const fdem::Engine& e, std::size_t c) {
  const std::vector<double>& p = e.positions();
  const auto n = e.crack_nodes(c);
  const auto at = [&](int k) { return std::array<double, 2>{p[2 * k], p[2 * k + 1]}; };
  const auto a = at(n[0]), b = at(n[1]);
  const double tx = b[0] - a[0], ty = b[1] - a[1], length = std::hypot(tx, ty);
  if (!(length > 0)) return 0;
  double nx = -ty / length, ny = tx / length;
  // Away from the first face's triangle: its centroid lies on the other side.
  const auto tri = e.triangle_nodes(std::size_t(e.crack_triangles(c)[0]));
  double cx = 0, cy = 0;
  for (const int k : tri) cx += p[2 * k] / 3, cy += p[2 * k + 1] / 3;
  if ((cx - a[0]) * nx + (cy - a[1]) * ny > 0) nx = -nx, ny = -ny;
  const auto d = at(n[3]), q = at(n[2]);
  return 0.5 * ((d[0] - a[0] + q[0] - b[0]) * nx + (d[1] - a[1] + q[1] - b[1]) * ny);
}

JointState joint_state(const fdem::Engine& e, std::size_t c, double opened) {
  if (crack_normal_opening(e, c) > opened) return JointState::kOpened;
  return e.crack_damage(c) > 0.0 ? JointState::kSliding : JointState::kIntact;
}

}  // namespace rockfdem::coupling
