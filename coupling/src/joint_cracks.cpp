// Joint elements found by their mesh edge (engine nodes back to mesh
// vertices), in a sorted list: no hashing order in the results.
#include "rockfdem/coupling/joint_cracks.hpp"

#include <algorithm>
#include <array>
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

}  // namespace rockfdem::coupling
