// Engine nodes, crack elements and the force-slot incidence.
//
// Node rule: around one mesh vertex, all triangles that do not allow
// fracture share a single engine node; every fracture triangle gets its own.
// A crack element sits on each interior edge with a fracture triangle on at
// least one side, so it always joins two distinct node pairs.
#include "topology.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "energy.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::fdem::detail {
namespace {

bool allows_fracture(const ModelInput& in, std::size_t t) {
  return !in.fracture.empty() && in.fracture[t] != 0;
}

/// Nodes are numbered in order of first use while walking the triangles, so
/// a triangle's nodes lie close together in memory.
void build_nodes(const ModelInput& in, EngineData& d) {
  const std::size_t nv = in.x.size(), nt = in.triangles.size();
  std::vector<int> shared(nv, -1);
  Nodes& n = d.nodes;
  d.tris.nodes.resize(3 * nt);
  auto new_node = [&](int v) {
    n.vertex.push_back(v);
    return static_cast<int>(n.vertex.size() - 1);
  };
  for (std::size_t t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = in.triangles[t][k];
      int id;
      if (allows_fracture(in, t)) {
        id = new_node(v);
      } else {
        if (shared[v] < 0) shared[v] = new_node(v);
        id = shared[v];
      }
      d.tris.nodes[3 * t + k] = id;
    }
  }
  n.vertex.shrink_to_fit();  // grown by push_back: up to half of it unused
  const std::size_t nn = n.vertex.size();
  n.pos.resize(2 * nn);
  n.vel.assign(2 * nn, 0.0);
  n.mass.assign(nn, 0.0);
  n.vertex_pos.resize(2 * nv);
  for (std::size_t v = 0; v < nv; ++v) {
    n.vertex_pos[2 * v] = in.x[v];
    n.vertex_pos[2 * v + 1] = in.y[v];
  }
  for (std::size_t i = 0; i < nn; ++i) {
    const int v = n.vertex[i];
    const double ux = in.initial_displacement.empty() ? 0.0 : in.initial_displacement[v][0];
    const double uy = in.initial_displacement.empty() ? 0.0 : in.initial_displacement[v][1];
    n.pos[2 * i] = in.x[v] + ux;
    n.pos[2 * i + 1] = in.y[v] + uy;
  }
}

void build_triangles(const ModelInput& in, EngineData& d) {
  const std::size_t nt = in.triangles.size();
  Triangles& tr = d.tris;
  tr.ref_inv.resize(4 * nt);
  tr.area0.resize(nt);
  tr.alpha.assign(nt, 1.0);
  tr.active.assign(nt, 1);
  tr.material.resize(nt);
  tr.eta.assign(nt, 0.0);
  for (std::size_t t = 0; t < nt; ++t) {
    tr.material[t] = static_cast<std::uint16_t>(in.material[t]);
    set_reference_to_current(d, t);
  }
  if (!in.initial_stress.empty()) {
    tr.sigma0.resize(3 * nt);
    for (std::size_t t = 0; t < nt; ++t)
      for (int k = 0; k < 3; ++k) tr.sigma0[3 * t + k] = in.initial_stress[t][k];
  }
}

/// One entry per (triangle, local edge): the undirected vertex pair as a key.
struct EdgeUse {
  std::uint64_t key;
  int tri, local;
};

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

/// Local corner of vertex v in triangle t.
int corner_of(const ModelInput& in, int t, int v) {
  for (int k = 0; k < 3; ++k)
    if (in.triangles[t][k] == v) return k;
  return -1;
}

/// Crack element between triangle t1 (edge a->b counter-clockwise in t1)
/// and t2: nodes 0,1 are t1's at a, b; node 3 faces 0 and node 2 faces 1.
void add_crack(const ModelInput& in, EngineData& d, int t1, int k1, int t2) {
  const int a = in.triangles[t1][k1], b = in.triangles[t1][(k1 + 1) % 3];
  const auto& tn = d.tris.nodes;
  Cracks& c = d.cracks;
  c.nodes.push_back(tn[3 * t1 + k1]);
  c.nodes.push_back(tn[3 * t1 + (k1 + 1) % 3]);
  c.nodes.push_back(tn[3 * t2 + corner_of(in, t2, b)]);
  c.nodes.push_back(tn[3 * t2 + corner_of(in, t2, a)]);
  const Material& m1 = in.materials[in.material[t1]];
  const Material& m2 = in.materials[in.material[t2]];
  // Between two materials the weaker (lower tensile strength) governs.
  const int mat = m2.tensile_strength < m1.tensile_strength ? in.material[t2] : in.material[t1];
  c.material.push_back(static_cast<std::uint16_t>(mat));
}

void build_cracks(const ModelInput& in, EngineData& d) {
  const std::size_t nt = in.triangles.size();
  std::vector<EdgeUse> uses;
  uses.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      uses.push_back(
          {edge_key(in.triangles[t][k], in.triangles[t][(k + 1) % 3]), static_cast<int>(t), k});
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& p, const EdgeUse& q) {
    return p.key != q.key ? p.key < q.key : p.tri < q.tri;
  });
  // Pairs (first triangle, its local edge, second triangle), then sorted by
  // the first triangle so crack elements follow the triangle order.
  std::vector<std::array<int, 3>> pairs;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i > 2)
      throw InputError("fdem model input: edge shared by " + std::to_string(j - i) +
                       " triangles (first: triangle " + std::to_string(uses[i].tri) +
                       "); the mesh must be a manifold");
    if (j - i == 2) {
      const EdgeUse& p = uses[i];
      const EdgeUse& q = uses[i + 1];
      if (allows_fracture(in, p.tri) || allows_fracture(in, q.tri))
        pairs.push_back({p.tri, p.local, q.tri});
    }
    i = j;
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& p : pairs) add_crack(in, d, p[0], p[1], p[2]);
  d.cracks.nodes.shrink_to_fit();  // grown by push_back: up to half of it unused
  d.cracks.material.shrink_to_fit();
  const std::size_t nc = d.cracks.size();
  d.cracks.damage.assign(3 * nc, 0.0);
  d.cracks.state.assign(nc, 0);
  d.cracks.mode.assign(nc, 0);
  d.cracks.active.assign(nc, 1);
  d.cracks.broken_step.assign(nc, -1);
  d.cracks.broke_in_block.assign((nc + kEnergyBlock - 1) / kEnergyBlock, 0);
}

/// CSR node -> slot entries, filled by walking the element corners
/// (triangles', then crack elements' nodes 0-3) in order so that each
/// node's list is sorted: the gather order is fixed once and for all.
/// Crack corner j of element c takes slot 2c + 0, 2c + 1, 2c + 1, 2c + 0
/// (j = 0..3), negated for j = 2, 3.
void build_slot_incidence(EngineData& d) {
  const std::size_t nn = d.nodes.size(), nt = d.tris.size(), nc = d.cracks.size();
  const std::size_t n_corners = 3 * nt + 4 * nc, n_slots = 3 * nt + 2 * nc;
  // Entries are 2 slot + sign in an int.
  if (n_corners > std::size_t(INT32_MAX) || 2 * n_slots + 1 > std::size_t(INT32_MAX))
    throw InputError("fdem model input: " + std::to_string(nt) + " triangles and " +
                     std::to_string(nc) +
                     " crack elements exceed the engine's 32-bit force-slot indices (at most " +
                     std::to_string(INT32_MAX / 2) + " slots); use a coarser mesh");
  std::vector<int> corner_node(n_corners), entry(n_corners);
  for (std::size_t s = 0; s < 3 * nt; ++s) {
    corner_node[s] = d.tris.nodes[s];
    entry[s] = static_cast<int>(2 * s);
  }
  const int crack_slot[4] = {0, 1, 1, 0}, negated[4] = {0, 0, 1, 1};
  for (std::size_t k = 0; k < 4 * nc; ++k) {
    const std::size_t slot = 3 * nt + 2 * (k / 4) + crack_slot[k % 4];
    corner_node[3 * nt + k] = d.cracks.nodes[k];
    entry[3 * nt + k] = static_cast<int>(2 * slot) + negated[k % 4];
  }
  auto& start = d.nodes.slot_start;
  start.assign(nn + 1, 0);
  for (int node : corner_node) ++start[node + 1];
  for (std::size_t i = 0; i < nn; ++i) start[i + 1] += start[i];
  auto& index = d.nodes.slot_index;
  index.resize(n_corners);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t k = 0; k < n_corners; ++k) index[fill[corner_node[k]]++] = entry[k];
  d.slots.assign(2 * n_slots, 0.0);
}

}  // namespace

void set_reference_to_current(EngineData& d, std::size_t t) {
  const int* nd = &d.tris.nodes[3 * t];
  const double* p = d.nodes.pos.data();
  const double a = p[2 * nd[1]] - p[2 * nd[0]], c = p[2 * nd[1] + 1] - p[2 * nd[0] + 1];
  const double b = p[2 * nd[2]] - p[2 * nd[0]], e = p[2 * nd[2] + 1] - p[2 * nd[0] + 1];
  const double det = a * e - b * c;  // F0 = [[a, b], [c, e]]
  if (!(det > 0))
    throw InputError("fdem: triangle " + std::to_string(t) +
                     " is inverted or degenerate in its reference configuration (2A = " +
                     std::to_string(det) + ")");
  double* g = &d.tris.ref_inv[4 * t];
  g[0] = e / det;
  g[1] = -b / det;
  g[2] = -c / det;
  g[3] = a / det;
  d.tris.area0[t] = 0.5 * det;
}

void build_topology(const ModelInput& in, EngineData& d) {
  build_nodes(in, d);
  build_triangles(in, d);
  build_cracks(in, d);
  build_slot_incidence(d);
}

}  // namespace rockfdem::fdem::detail
