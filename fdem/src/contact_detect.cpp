// Contact set-up and broad phase: which triangles can touch, and which pairs
// of them are close enough to be checked by the narrow phase.
//
// Candidates are the active triangles with a free edge: an outer boundary
// edge, an edge next to an inactive triangle (the excavation boundary once
// the core is removed) or an edge whose crack element is broken. A triangle
// without one lies inside an intact piece and cannot be reached without a
// free-surface triangle being penetrated first. Two candidates are never a
// pair when they share an engine node (non-fracture regions), share an edge
// with an intact crack element, or share one mesh vertex whose two nodes are
// joined by a chain of intact crack elements around it (the same piece
// there). So an intact body has candidates on its outline but no pairs, and
// the narrow phase does nothing.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "engine_data.hpp"
#include "parallel.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::fdem::detail {
namespace {

int vertex_of(const EngineData& d, int t, int k) { return d.nodes.vertex[d.tris.nodes[3 * t + k]]; }

/// Neighbour across each triangle edge, from the mesh vertices of its nodes.
void build_edge_neighbours(EngineData& d) {
  const int nt = static_cast<int>(d.tris.size());
  struct Use {
    std::uint64_t key;
    int tri, local;
  };
  std::vector<Use> uses;
  uses.reserve(3 * nt);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(vertex_of(d, t, k));
      const auto b = static_cast<std::uint64_t>(vertex_of(d, t, (k + 1) % 3));
      uses.push_back({(std::max(a, b) << 32) | std::min(a, b), t, k});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& p, const Use& q) {
    return p.key != q.key ? p.key < q.key : p.tri < q.tri;
  });
  ContactData& c = d.contact;
  c.edge_nbr.assign(3 * nt, -1);
  c.edge_crack.assign(3 * nt, -1);
  for (std::size_t i = 0; i + 1 < uses.size(); ++i)
    if (uses[i].key == uses[i + 1].key) {
      c.edge_nbr[3 * uses[i].tri + uses[i].local] = uses[i + 1].tri;
      c.edge_nbr[3 * uses[i + 1].tri + uses[i + 1].local] = uses[i].tri;
    }
  for (std::size_t e = 0; e < d.cracks.size(); ++e)
    for (int side = 0; side < 2; ++side) {
      const int t = d.cracks.tri[2 * e + side], other = d.cracks.tri[2 * e + 1 - side];
      for (int k = 0; k < 3; ++k)
        if (c.edge_nbr[3 * t + k] == other) c.edge_crack[3 * t + k] = static_cast<int>(e);
    }
}

bool free_edge(const EngineData& d, int t, int k) {
  const int nbr = d.contact.edge_nbr[3 * t + k];
  if (nbr < 0 || !d.tris.active[nbr]) return true;
  const int crack = d.contact.edge_crack[3 * t + k];
  return crack >= 0 && d.cracks.state[crack] == std::uint8_t(CrackState::kBroken);
}

/// Per node, a label shared by the nodes its vertex's intact crack elements
/// join (union-find, serial and in element order: deterministic).
void build_components(EngineData& d) {
  std::vector<int>& parent = d.contact.component;
  const int nn = static_cast<int>(d.nodes.size());
  parent.resize(nn);
  for (int i = 0; i < nn; ++i) parent[i] = i;
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::size_t e = 0; e < d.cracks.size(); ++e) {
    if (!d.cracks.active[e] || d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
    const int* nd = &d.cracks.nodes[4 * e];
    for (int end = 0; end < 2; ++end) {
      const int a = find(nd[end]), b = find(nd[3 - end]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  for (int i = 0; i < nn; ++i) parent[i] = find(i);
}

void build_candidates(EngineData& d) {
  ContactData& c = d.contact;
  c.candidates.clear();
  for (int t = 0; t < static_cast<int>(d.tris.size()); ++t) {
    if (!d.tris.active[t]) continue;
    if (free_edge(d, t, 0) || free_edge(d, t, 1) || free_edge(d, t, 2)) c.candidates.push_back(t);
  }
  build_components(d);
  // Nodes whose displacement decides when to detect again.
  c.watch_nodes.clear();
  for (int t : c.candidates)
    for (int k = 0; k < 3; ++k) c.watch_nodes.push_back(d.tris.nodes[3 * t + k]);
  std::sort(c.watch_nodes.begin(), c.watch_nodes.end());
  c.watch_nodes.erase(std::unique(c.watch_nodes.begin(), c.watch_nodes.end()),
                      c.watch_nodes.end());
}

/// True when an edge normal of either triangle separates them by more than
/// `gap`. For convex polygons the largest such separation never exceeds the
/// true distance, so no pair that could touch is lost; it drops the pairs
/// whose boxes touch only diagonally (the alternating-diagonal mesh puts
/// such free-surface triangles at every corner).
bool separated(const EngineData& d, int a, int b, double gap) {
  const double* p = d.nodes.pos.data();
  const int* tri[2] = {&d.tris.nodes[3 * a], &d.tris.nodes[3 * b]};
  for (int side = 0; side < 2; ++side) {
    const int* own = tri[side];
    const int* other = tri[1 - side];
    for (int k = 0; k < 3; ++k) {
      const int i = own[k], j = own[(k + 1) % 3];
      // Outward normal of edge i->j (counter-clockwise), unnormalised.
      const double nx = p[2 * j + 1] - p[2 * i + 1], ny = p[2 * i] - p[2 * j];
      const double len = std::sqrt(nx * nx + ny * ny);
      const double base = nx * p[2 * i] + ny * p[2 * i + 1];
      double nearest = 1e300;
      for (int q = 0; q < 3; ++q)
        nearest = std::min(nearest, nx * p[2 * other[q]] + ny * p[2 * other[q] + 1] - base);
      if (nearest > gap * len) return true;
    }
  }
  return false;
}

/// Pair filter on candidate indices: see the file comment.
bool may_touch(const void* context, int i, int j) {
  const EngineData& d = *static_cast<const EngineData*>(context);
  const int a = d.contact.candidates[i], b = d.contact.candidates[j];
  const int* na = &d.tris.nodes[3 * a];
  const int* nb = &d.tris.nodes[3 * b];
  int shared = 0, ka = -1, kb = -1;
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      if (na[p] == nb[q]) return false;
      if (d.nodes.vertex[na[p]] == d.nodes.vertex[nb[q]]) {
        ++shared;
        ka = p;
        kb = q;
      }
    }
  if (shared >= 2) {  // an edge: a pair only once its crack element broke
    for (int k = 0; k < 3; ++k)
      if (d.contact.edge_nbr[3 * a + k] == b) {
        const int crack = d.contact.edge_crack[3 * a + k];
        return crack >= 0 && d.cracks.state[crack] == std::uint8_t(CrackState::kBroken);
      }
    return false;
  }
  if (shared == 1 && d.contact.component[na[ka]] == d.contact.component[nb[kb]]) return false;
  return !separated(d, a, b, d.contact.buffer);
}

void build_boxes(EngineData& d) {
  ContactData& c = d.contact;
  const double grow = 0.5 * c.buffer;
  c.boxes.resize(4 * c.candidates.size());
  const double* p = d.nodes.pos.data();
  for (std::size_t i = 0; i < c.candidates.size(); ++i) {
    const int* nd = &d.tris.nodes[3 * c.candidates[i]];
    double* b = &c.boxes[4 * i];
    b[0] = std::min({p[2 * nd[0]], p[2 * nd[1]], p[2 * nd[2]]}) - grow;
    b[1] = std::min({p[2 * nd[0] + 1], p[2 * nd[1] + 1], p[2 * nd[2] + 1]}) - grow;
    b[2] = std::max({p[2 * nd[0]], p[2 * nd[1]], p[2 * nd[2]]}) + grow;
    b[3] = std::max({p[2 * nd[0] + 1], p[2 * nd[1] + 1], p[2 * nd[2] + 1]}) + grow;
  }
}

/// Friction springs of pairs found again keep their state (both lists are
/// sorted, so one merge walk). Returns the stored energy of the old pairs
/// not found again minus that of the new pairs: what the detection itself
/// changed. New pairs can start overlapping (the faces of a crack element
/// broken in compression); dropped ones are mostly apart, but a re-joined
/// crack's faces stop being a pair wherever they are.
double carry_friction(EngineData& d) {
  ContactData& c = d.contact;
  c.friction.assign(6 * c.pairs.size(), 0.0);
  const Placement at = half_step_placement(d);
  double change = 0.0;
  std::size_t o = 0;
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    for (; o < c.old_pairs.size() && c.old_pairs[o] < c.pairs[i]; ++o)
      change += contact_pair_energy(d, c.old_pairs[o][0], c.old_pairs[o][1],
                                    &c.old_friction[6 * o], at);
    if (o < c.old_pairs.size() && c.old_pairs[o] == c.pairs[i]) {
      std::copy_n(&c.old_friction[6 * o], 6, &c.friction[6 * i]);
      ++o;
    } else {
      change -= contact_pair_energy(d, i, at);
    }
  }
  for (; o < c.old_pairs.size(); ++o)
    change += contact_pair_energy(d, c.old_pairs[o][0], c.old_pairs[o][1],
                                  &c.old_friction[6 * o], at);
  return change;
}

/// CSR contact triangle -> (2 pair + side), in ascending pair order.
void build_gather(EngineData& d) {
  ContactData& c = d.contact;
  c.gather_tri.clear();
  for (const auto& p : c.pairs) {
    c.gather_tri.push_back(p[0]);
    c.gather_tri.push_back(p[1]);
  }
  std::sort(c.gather_tri.begin(), c.gather_tri.end());
  c.gather_tri.erase(std::unique(c.gather_tri.begin(), c.gather_tri.end()), c.gather_tri.end());
  auto index = [&](int t) {
    return static_cast<int>(std::lower_bound(c.gather_tri.begin(), c.gather_tri.end(), t) -
                            c.gather_tri.begin());
  };
  c.gather_start.assign(c.gather_tri.size() + 1, 0);
  for (const auto& p : c.pairs) {
    ++c.gather_start[index(p[0]) + 1];
    ++c.gather_start[index(p[1]) + 1];
  }
  for (std::size_t g = 0; g < c.gather_tri.size(); ++g) c.gather_start[g + 1] += c.gather_start[g];
  c.gather_entry.resize(2 * c.pairs.size());
  c.grid.offset.assign(c.gather_start.begin(), c.gather_start.end() - 1);
  for (std::size_t p = 0; p < c.pairs.size(); ++p)
    for (int side = 0; side < 2; ++side)
      c.gather_entry[c.grid.offset[index(c.pairs[p][side])]++] = static_cast<int>(2 * p + side);
}

}  // namespace

void contact_setup(EngineData& d) {
  ContactData& c = d.contact;
  build_edge_neighbours(d);
  double e_max = 0;
  c.mu.clear();
  constexpr double kPi = 3.14159265358979323846;
  for (const Material& m : d.materials) {
    e_max = std::max(e_max, m.young);
    c.mu.push_back(std::tan(m.residual_friction_deg * kPi / 180.0));
  }
  c.penalty = c.settings.penalty > 0 ? c.settings.penalty : e_max;
  double sum = 0;
  const double* p = d.nodes.mesh_pos.data();
  for (std::size_t t = 0; t < d.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = d.tris.nodes[3 * t + k], b = d.tris.nodes[3 * t + (k + 1) % 3];
      sum += std::hypot(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]);
    }
  const double mean_edge = d.tris.size() ? sum / (3.0 * d.tris.size()) : 1.0;
  c.buffer = c.settings.buffer > 0 ? c.settings.buffer : 0.25 * mean_edge;
  c.dirty = c.topology_dirty = true;
}

void contact_detect(EngineData& d) {
  ContactData& c = d.contact;
  if (c.topology_dirty) build_candidates(d);
  c.topology_dirty = false;
  build_boxes(d);
  std::swap(c.old_pairs, c.pairs);
  std::swap(c.old_friction, c.friction);
  grid_pairs(c.boxes, may_touch, &d, d.threads, c.grid, c.grid.found);
  c.pairs.resize(c.grid.found.size());
  for (std::size_t i = 0; i < c.pairs.size(); ++i)
    c.pairs[i] = {c.candidates[c.grid.found[i][0]], c.candidates[c.grid.found[i][1]]};
  // The broken faces' handover to contact: booked with the fracture energy
  // that released the crack's compressive penalty (energy.hpp).
  const double handover = carry_friction(d);
  if (d.energy.started) d.energy.fracture += handover;
  c.pair_force.resize(12 * c.pairs.size());
  c.energy_partial.resize(2 * ((c.pairs.size() + kPairBlock - 1) / kPairBlock));
  build_gather(d);
  c.watch_pos.resize(2 * c.watch_nodes.size());
  for (std::size_t i = 0; i < c.watch_nodes.size(); ++i) {
    c.watch_pos[2 * i] = d.nodes.pos[2 * c.watch_nodes[i]];
    c.watch_pos[2 * i + 1] = d.nodes.pos[2 * c.watch_nodes[i] + 1];
  }
  c.dirty = false;
  ++c.detections;
}

double contact_omega2(const EngineData& d) {
  double min_rho_h2 = 1e300;
  const double* p = d.nodes.mesh_pos.data();
  for (std::size_t t = 0; t < d.tris.size(); ++t) {
    if (!d.tris.active[t]) continue;
    double longest = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = d.tris.nodes[3 * t + k], b = d.tris.nodes[3 * t + (k + 1) % 3];
      longest = std::max(longest, std::hypot(p[2 * b] - p[2 * a], p[2 * b + 1] - p[2 * a + 1]));
    }
    const double h = 2.0 * d.tris.area0[t] / longest;
    min_rho_h2 = std::min(min_rho_h2, d.materials[d.tris.material[t]].density * h * h);
  }
  // A sticking friction spring is as stiff as the normal penalty.
  const double springs = d.contact.settings.friction ? 2.0 : 1.0;
  return springs * 36.0 * d.contact.penalty / min_rho_h2;
}

}  // namespace rockfdem::fdem::detail
