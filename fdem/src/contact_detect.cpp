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
#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// What lies across a triangle edge: its crack element and the other
/// triangle, each -1 where there is none.
struct Across {
  int crack = -1, tri = -1;
};

/// Across edge k of triangle t (corners k -> k+1), from the force slots of
/// its first corner's node a, b the second's: a crack element on the edge
/// has a as its node 0 (t its first triangle, b its node 1) or as its
/// node 2 (t its second, b its node 3); without one (no fracture on either
/// side) the neighbour shares both nodes.
Across across_edge(const EngineData& d, int t, int k) {
  const int a = d.tris.nodes[3 * t + k], b = d.tris.nodes[3 * t + (k + 1) % 3];
  const Nodes& n = d.nodes;
  const Cracks& c = d.cracks;
  const int slot0 = static_cast<int>(d.crack_slot0());
  for (int q = n.slot_start[a]; q < n.slot_start[a + 1]; ++q) {
    const int entry = n.slot_index[q], s = entry_slot(entry);
    if (s < slot0) {
      const int u = s / 3, *nu = &d.tris.nodes[3 * u];
      if (u != t && (nu[0] == b || nu[1] == b || nu[2] == b)) return {-1, u};
      continue;
    }
    const int e = (s - slot0) / 2, j = (s - slot0) % 2, side = entry & 1;
    if (j == side && c.nodes[4 * e + 1 + 2 * side] == b) return {e, d.crack_triangle(e, 1 - side)};
  }
  return {};
}

/// Calls f(slot) for each force slot of the nodes at mesh vertex v: the
/// triangles and crack elements with a corner or an end there, from the
/// node incidence the gather uses (no lists of their own).
template <class F>
void each_slot_at(const EngineData& d, int v, F f) {
  const Nodes& n = d.nodes;
  for (int i = d.vertex_node_start[v]; i < d.vertex_node_start[v + 1]; ++i) {
    const int node = d.vertex_nodes[i];
    for (int k = n.slot_start[node]; k < n.slot_start[node + 1]; ++k)
      f(entry_slot(n.slot_index[k]));
  }
}

bool free_edge(const EngineData& d, int t, int k) {
  const Across x = across_edge(d, t, k);
  if (x.tri < 0 || !d.tris.active[x.tri]) return true;
  return x.crack >= 0 && d.cracks.state[x.crack] == std::uint8_t(CrackState::kBroken);
}

/// Whether nodes x and y of one mesh vertex are joined by a chain of
/// intact crack elements around it: a union-find over that vertex's nodes
/// and the crack ends there (from the nodes' force slots), run when asked;
/// a vertex has a few nodes.
bool joined_at_vertex(const EngineData& d, int x, int y) {
  if (x == y) return true;
  const int v = d.nodes.vertex[x];
  const int n0 = d.vertex_node_start[v], k = d.vertex_node_start[v + 1] - n0;
  const int* at = &d.vertex_nodes[n0];
  constexpr int kSmall = 64;
  int small[kSmall];
  thread_local std::vector<int> large;  // grown once for a vertex of many nodes
  if (k > kSmall) large.resize(k);
  int* parent = k > kSmall ? large.data() : small;
  for (int i = 0; i < k; ++i) parent[i] = i;
  auto local = [&](int node) { return int(std::find(at, at + k, node) - at); };
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const Nodes& n = d.nodes;
  const int slot0 = static_cast<int>(d.crack_slot0());
  for (int i = 0; i < k; ++i)
    for (int q = n.slot_start[at[i]]; q < n.slot_start[at[i] + 1]; ++q) {
      const int s = entry_slot(n.slot_index[q]);
      if (s < slot0) continue;
      const int e = (s - slot0) / 2;
      if (!d.cracks.active[e] || d.cracks.state[e] == std::uint8_t(CrackState::kBroken)) continue;
      const int* nd = &d.cracks.nodes[4 * e];
      const int end = n.vertex[nd[0]] == v ? 0 : 1;  // joins nd[end] and nd[3 - end]
      const int a = find(i), b = find(local(nd[end] == at[i] ? nd[3 - end] : nd[end]));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  return find(local(x)) == find(local(y));
}

void build_candidates(EngineData& d) {
  ContactData& c = d.contact;
  c.candidates.clear();
  for (int t = 0; t < static_cast<int>(d.tris.size()); ++t) {
    if (!d.tris.active[t]) continue;
    if (free_edge(d, t, 0) || free_edge(d, t, 1) || free_edge(d, t, 2)) c.candidates.push_back(t);
  }
  // Nodes whose displacement decides when to detect again.
  c.watch_nodes.clear();
  for (int t : c.candidates)
    for (int k = 0; k < 3; ++k) c.watch_nodes.push_back(d.tris.nodes[3 * t + k]);
  std::sort(c.watch_nodes.begin(), c.watch_nodes.end());
  c.watch_nodes.erase(std::unique(c.watch_nodes.begin(), c.watch_nodes.end()), c.watch_nodes.end());
}

/// True when an edge normal of either triangle separates them by more than
/// `gap`. For convex polygons the largest such separation never exceeds the
/// true distance, so no pair that could touch is lost; it drops the pairs
/// whose boxes touch only diagonally (the alternating-diagonal mesh puts
/// such free-surface triangles at every corner).
bool separated(const EngineData& d, int a, int b, double gap) {
  double px[2][3], py[2][3];  // the corners at the detection
  for (int side = 0; side < 2; ++side)
    for (int k = 0; k < 3; ++k) {
      const int node = d.tris.nodes[3 * (side == 0 ? a : b) + k];
      px[side][k] = d.detected_position(node, 0);
      py[side][k] = d.detected_position(node, 1);
    }
  for (int side = 0; side < 2; ++side) {
    const int other = 1 - side;
    for (int k = 0; k < 3; ++k) {
      const int i = k, j = (k + 1) % 3;
      // Outward normal of edge i->j (counter-clockwise), unnormalised.
      const double nx = py[side][j] - py[side][i], ny = px[side][i] - px[side][j];
      const double len = std::sqrt(nx * nx + ny * ny);
      const double base = nx * px[side][i] + ny * py[side][i];
      double nearest = 1e300;
      for (int q = 0; q < 3; ++q)
        nearest = std::min(nearest, nx * px[other][q] + ny * py[other][q] - base);
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
      if (const Across x = across_edge(d, a, k); x.tri == b) {
        const int crack = x.crack;
        return crack >= 0 && d.cracks.state[crack] == std::uint8_t(CrackState::kBroken);
      }
    return false;
  }
  if (shared == 1 && joined_at_vertex(d, na[ka], nb[kb])) return false;
  return !separated(d, a, b, d.contact.buffer);
}

/// Triangle t's box at the detection positions, grown by half the buffer.
void triangle_box(const EngineData& d, int t, double* b) {
  const double grow = 0.5 * d.contact.buffer;
  const int* nd = &d.tris.nodes[3 * t];
  double x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = d.detected_position(nd[k], 0);
    y[k] = d.detected_position(nd[k], 1);
  }
  b[0] = std::min({x[0], x[1], x[2]}) - grow;
  b[1] = std::min({y[0], y[1], y[2]}) - grow;
  b[2] = std::max({x[0], x[1], x[2]}) + grow;
  b[3] = std::max({y[0], y[1], y[2]}) + grow;
}

void build_boxes(EngineData& d) {
  ContactData& c = d.contact;
  grow_to(c.boxes, 4 * c.candidates.size());
  for (std::size_t i = 0; i < c.candidates.size(); ++i)
    triangle_box(d, c.candidates[i], &c.boxes[4 * i]);
}

inline bool boxes_overlap(const double* a, const double* b) {
  return a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3];
}

/// Indices of all pairs in canonical order (in the breaks' scratch): the
/// sorted ones merged with the appended ones.
const std::vector<int>& canonical_order(ContactData& c) {
  std::vector<int>& order = c.breaks.merged;
  order.resize(c.pairs.size());
  const CanonicalOrder by_pair{c};
  std::size_t i = 0, j = 0, k = 0;
  const std::size_t ns = c.sorted_pairs, na = c.appended_order.size();
  while (i < ns || j < na) {
    const bool sorted = j == na || (i < ns && by_pair(int(i), c.appended_order[j]));
    order[k++] = sorted ? static_cast<int>(i++) : c.appended_order[j++];
  }
  return order;
}

/// Replaces the pairs by those the grid found (c.grid.found, candidate
/// indices, in canonical order). Friction springs of pairs found again keep
/// their state (both lists are sorted, so one merge walk); the new springs
/// are assembled in pair_force, scratch until the next contact pass writes
/// it, so that the old lists need no second copy. Returns the stored energy
/// of the old pairs not found again minus that of the new pairs: what the
/// detection itself changed. New pairs can start overlapping (the faces of
/// a crack element broken in compression); dropped ones are mostly apart,
/// but a re-joined crack's faces stop being a pair wherever they are.
double carry_friction(EngineData& d) {
  static constexpr double kNoSprings[6] = {};
  ContactData& c = d.contact;
  const auto& found = c.grid.found;
  const std::size_t n = found.size(), n_old = c.pairs.size();
  const std::vector<int>& old = canonical_order(c);  // the old pairs, one merge walk
  grow_to(c.pair_force, 12 * n);
  double* spring = c.pair_force.data();
  const Placement at = half_step_placement(d);
  double change = 0.0;
  auto dropped = [&](std::size_t k) {
    const int o = old[k];
    return contact_pair_energy(d, c.pairs[o][0], c.pairs[o][1], &c.friction[6 * o], at);
  };
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 2> p = {c.candidates[found[i][0]], c.candidates[found[i][1]]};
    for (; k < n_old && c.pairs[old[k]] < p; ++k) change += dropped(k);
    if (k < n_old && c.pairs[old[k]] == p) {
      std::copy_n(&c.friction[6 * old[k]], 6, &spring[6 * i]);
      ++k;
    } else {
      std::fill_n(&spring[6 * i], 6, 0.0);
      change -= contact_pair_energy(d, p[0], p[1], kNoSprings, at);
    }
  }
  for (; k < n_old; ++k) change += dropped(k);
  grow_to(c.pairs, n);
  for (std::size_t i = 0; i < n; ++i)
    c.pairs[i] = {c.candidates[found[i][0]], c.candidates[found[i][1]]};
  c.sorted_pairs = n;
  c.friction.assign(spring, spring + 6 * n);
  return change;
}

/// Index of triangle t in the (ascending) candidates, or -1.
int candidate_index(const ContactData& c, int t) {
  const auto it = std::lower_bound(c.candidates.begin(), c.candidates.end(), t);
  return it != c.candidates.end() && *it == t ? static_cast<int>(it - c.candidates.begin()) : -1;
}

/// Inserts the (ascending, new) triangles s.tris into the candidates with
/// their boxes, and their nodes into the watched nodes: one merge each.
/// The candidates and boxes merge in place from the back (every old entry
/// moves up or stays), so no second array of boxes is kept.
void insert_candidates(EngineData& d) {
  ContactData& c = d.contact;
  BreakScratch& s = c.breaks;
  std::size_t i = c.candidates.size(), j = s.tris.size();
  const std::size_t n = i + j;
  grow_to(c.candidates, n);
  grow_to(c.boxes, 4 * n);
  for (std::size_t k = n; j > 0; --k) {  // once the new ones are placed, the rest stays
    if (i > 0 && c.candidates[i - 1] > s.tris[j - 1]) {
      --i;
      c.candidates[k - 1] = c.candidates[i];
      std::copy_n(&c.boxes[4 * i], 4, &c.boxes[4 * (k - 1)]);
    } else {
      c.candidates[k - 1] = s.tris[--j];
      triangle_box(d, c.candidates[k - 1], &c.boxes[4 * (k - 1)]);
    }
  }
  s.ints.clear();
  for (int t : s.tris)
    for (int k = 0; k < 3; ++k) s.ints.push_back(d.tris.nodes[3 * t + k]);
  std::sort(s.ints.begin(), s.ints.end());
  s.merged.resize(c.watch_nodes.size() + s.ints.size());
  const auto end = std::merge(c.watch_nodes.begin(), c.watch_nodes.end(), s.ints.begin(),
                              s.ints.end(), s.merged.begin());
  s.merged.erase(std::unique(s.merged.begin(), end), s.merged.end());
  std::swap(c.watch_nodes, s.merged);
  // Watched from now on, from their positions at the detection.
  const double moved = std::sqrt(largest_drift2(d, s.ints.data(), long(s.ints.size())));
  c.drift_bound = std::max(c.drift_bound, bound_drift(moved, c.buffer));
}

/// Every pair the breakage may have allowed, as ascending triangle ids,
/// sorted and unique: a new candidate with any candidate whose box it
/// overlaps, the faces of each broken crack element, and all candidate
/// pairs around the vertices whose components split.
void trial_pairs(EngineData& d) {
  const ContactData& c = d.contact;
  BreakScratch& s = d.contact.breaks;
  s.trial.clear();
  auto add = [&](int a, int b) {
    if (a != b) s.trial.push_back({std::min(a, b), std::max(a, b)});
  };
  // The new candidates (a few, spread out) against every candidate's box, a
  // block of consecutive candidates at a time: candidates ascend in the
  // mesh's space-filling order, so a block covers a small region, and a
  // new box outside the block's hull overlaps none of its boxes.
  constexpr int kBoxBlock = 64;
  const int nc = static_cast<int>(c.candidates.size());
  const double* boxes = c.boxes.data();
  s.ints.clear();
  for (int t : s.tris) s.ints.push_back(candidate_index(c, t));
  for (int j0 = 0; j0 < nc; j0 += kBoxBlock) {
    const int j1 = std::min(nc, j0 + kBoxBlock);
    double hull[4] = {boxes[4 * j0], boxes[4 * j0 + 1], boxes[4 * j0 + 2], boxes[4 * j0 + 3]};
    for (int j = j0 + 1; j < j1; ++j) {
      hull[0] = std::min(hull[0], boxes[4 * j]);
      hull[1] = std::min(hull[1], boxes[4 * j + 1]);
      hull[2] = std::max(hull[2], boxes[4 * j + 2]);
      hull[3] = std::max(hull[3], boxes[4 * j + 3]);
    }
    for (int i : s.ints) {
      const double* box = &boxes[4 * i];
      if (!boxes_overlap(box, hull)) continue;
      for (int j = j0; j < j1; ++j)
        if (boxes_overlap(box, &boxes[4 * j])) add(c.candidates[i], c.candidates[j]);
    }
  }
  for (int e : s.cracks) add(d.crack_triangle(e, 0), d.crack_triangle(e, 1));
  const int slot0 = static_cast<int>(d.crack_slot0());
  for (int v : s.vertices) {
    s.ints.clear();  // the triangles with a corner at v, each once
    each_slot_at(d, v, [&](int slot) {
      if (slot < slot0) s.ints.push_back(slot / 3);
    });
    for (std::size_t i = 0; i < s.ints.size(); ++i)
      for (std::size_t j = i + 1; j < s.ints.size(); ++j) add(s.ints[i], s.ints[j]);
  }
  std::sort(s.trial.begin(), s.trial.end());
  s.trial.erase(std::unique(s.trial.begin(), s.trial.end()), s.trial.end());
}

/// Appends the accepted new pairs s.found (canonical order) to the pairs
/// with springs at zero and their entries to the gather; returns minus
/// their stored energy (the handover, as in carry_friction).
double append_pairs(EngineData& d) {
  ContactData& c = d.contact;
  BreakScratch& s = c.breaks;
  const std::size_t n0 = c.pairs.size(), m = s.found.size();
  grow_to(c.pairs, n0 + m);
  grow_to(c.friction, 6 * (n0 + m));
  std::copy(s.found.begin(), s.found.end(), c.pairs.begin() + static_cast<long>(n0));
  std::fill(c.friction.begin() + static_cast<long>(6 * n0), c.friction.end(), 0.0);
  const Placement at = half_step_placement(d);
  double change = 0.0;
  for (std::size_t q = n0; q < n0 + m; ++q) {
    change -= contact_pair_energy(d, q, at);
    append_pair_entries(c, q);
  }
  // The new indices (canonical among themselves) merged into the order, in
  // place from the back.
  std::size_t i = c.appended_order.size(), j = m, k = i + m;
  grow_to(c.appended_order, k);
  while (j > 0)
    if (i > 0 && s.found[j - 1] < c.pairs[c.appended_order[i - 1]]) {
      c.appended_order[--k] = c.appended_order[--i];
    } else {
      c.appended_order[--k] = static_cast<int>(n0 + --j);
    }
  return change;
}

/// Puts the pairs and their springs back in canonical order and rebuilds
/// the gather: the appended pairs lie in the order they broke, so a pair
/// loop and a gather over many of them would lose the locality the
/// canonical order gives (the space-filling order of the triangles).
void sort_pairs(EngineData& d) {
  ContactData& c = d.contact;
  const std::vector<int>& order = canonical_order(c);
  const std::size_t n = c.pairs.size();
  // The grid's result is scratch between detections, and about as long.
  std::vector<std::array<int, 2>>& pairs = c.grid.found;
  grow_to(pairs, n);
  grow_to(c.pair_force, 12 * n);  // scratch between contact passes
  double* spring = c.pair_force.data();
  for (std::size_t k = 0; k < n; ++k) {
    pairs[k] = c.pairs[order[k]];
    std::copy_n(&c.friction[6 * order[k]], 6, &spring[6 * k]);
  }
  std::copy(pairs.begin(), pairs.end(), c.pairs.begin());
  std::copy_n(spring, 6 * n, c.friction.begin());
  c.sorted_pairs = n;
  build_gather(d);
}

/// The crack elements broken in this step, the triangles that become
/// candidates and the vertices at their ends (unsorted). A few of many
/// crack elements broke: only the blocks the crack pass marked are looked
/// at.
void collect_breaks(EngineData& d) {
  const ContactData& c = d.contact;
  BreakScratch& s = d.contact.breaks;
  s.cracks.clear();
  s.tris.clear();
  s.vertices.clear();
  const long n_cracks = static_cast<long>(d.cracks.size());
  const std::int32_t* broken_step = d.cracks.broken_step.data();
  const auto step = static_cast<std::int32_t>(d.step);
  const std::vector<std::uint8_t>& marked = d.cracks.broke_in_block;
  for (std::size_t b = 0; b < marked.size(); ++b) {
    if (!marked[b]) continue;
    const int e0 = static_cast<int>(long(b) * kEnergyBlock);
    const int e1 = static_cast<int>(std::min(n_cracks, long(b + 1) * kEnergyBlock));
    for (int e = e0; e < e1; ++e) {
      if (broken_step[e] != step || d.cracks.state[e] != std::uint8_t(CrackState::kBroken))
        continue;
      s.cracks.push_back(e);
      for (int side = 0; side < 2; ++side) {
        const int t = d.crack_triangle(e, side);
        if (d.tris.active[t] && candidate_index(c, t) < 0) s.tris.push_back(t);
        s.vertices.push_back(d.nodes.vertex[d.cracks.nodes[4 * e + side]]);
      }
    }
  }
}

}  // namespace

void contact_setup(EngineData& d) {
  ContactData& c = d.contact;
  double e_max = 0;
  c.mu.clear();
  for (const Material& m : d.materials) {
    e_max = std::max(e_max, m.young);
    c.mu.push_back(std::tan(m.residual_friction_deg * kPi / 180.0));
  }
  c.penalty = c.settings.penalty > 0 ? c.settings.penalty : e_max;
  double sum = 0;
  const Nodes& n = d.nodes;
  for (std::size_t t = 0; t < d.tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = d.tris.nodes[3 * t + k], b = d.tris.nodes[3 * t + (k + 1) % 3];
      sum += std::hypot(n.mesh_position(b, 0) - n.mesh_position(a, 0),
                        n.mesh_position(b, 1) - n.mesh_position(a, 1));
    }
  const double mean_edge = d.tris.size() ? sum / (3.0 * d.tris.size()) : 1.0;
  // An eighth of the mean edge: bench_contact's table in docs/benchmarks.md
  // (pairs mostly neighbours when pressed; fewer far pairs when flying apart,
  // at a few detections per 1000 steps).
  c.buffer = c.settings.buffer > 0 ? c.settings.buffer : 0.125 * mean_edge;
  c.dirty = c.topology_dirty = true;
}

void contact_detect(EngineData& d) {
  ContactData& c = d.contact;
  if (c.topology_dirty) build_candidates(d);
  c.topology_dirty = false;
  // Boxes, the separation test and the drift check all start from here.
  c.detect_shift.resize(d.nodes.pos.size());
  const long nn = static_cast<long>(d.nodes.size());
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) if (nn > 65536)
  for (long i = 0; i < nn; ++i)
    for (int axis = 0; axis < 2; ++axis)
      c.detect_shift[2 * i + axis] =
          static_cast<float>(d.nodes.pos[2 * i + axis] - d.nodes.mesh_position(i, axis));
  // Not quite 0: the shifts are rounded to single precision.
  c.drift_bound = bound_drift(
      std::sqrt(largest_drift2(d, c.watch_nodes.data(), long(c.watch_nodes.size()))), c.buffer);
  build_boxes(d);
  grid_pairs(c.boxes, may_touch, &d, d.threads, c.grid, c.grid.found);
  // The broken faces' handover to contact: booked with the fracture energy
  // that released the crack's compressive penalty (energy.hpp).
  const double handover = carry_friction(d);
  if (d.energy.started) d.energy.fracture += handover;
  c.energy_partial.resize(2 * ((c.pairs.size() + kPairBlock - 1) / kPairBlock));
  build_gather(d);
  c.dirty = false;
  ++c.detections;
}

// Breakage without a full detection. The last detection (at positions x0,
// kept in detect_shift) found every candidate pair whose boxes, grown by half
// the buffer, overlap; it is repeated before any watched node has moved
// more than half the buffer from x0, so no other pair can touch before
// then. A broken crack element only adds: its two triangles may become
// candidates, the pair of its faces is no longer excluded, and the
// components at its two end vertices may split (which allows pairs of
// triangles that share only that vertex); no exclusion is added and no
// candidate lost. So the pair set of a full detection at x0 with the new
// crack states is the old one plus pairs that involve a new candidate, the
// faces' pair or two triangles around an end vertex, and contact_breaks
// tests exactly those, at x0, with the full detection's filter. The new
// candidates' nodes join the watched nodes with their x0 positions, so the
// drift check covers them from x0 as if they had been watched since the
// detection: the guarantee above holds for the grown set as it held for
// the old one. New pairs are appended (contact_gather.cpp) and existing
// pairs keep their friction springs.
void contact_breaks(EngineData& d) {
  ContactData& c = d.contact;
  if (c.topology_dirty) return;  // the candidates are rebuilt at the next detection
  BreakScratch& s = c.breaks;
  collect_breaks(d);
  std::sort(s.tris.begin(), s.tris.end());
  s.tris.erase(std::unique(s.tris.begin(), s.tris.end()), s.tris.end());
  std::sort(s.vertices.begin(), s.vertices.end());
  s.vertices.erase(std::unique(s.vertices.begin(), s.vertices.end()), s.vertices.end());
  // The candidates are kept up to date in any case (a merge, where
  // rebuilding them visits every triangle's edges). Each new candidate is
  // tested against all candidates: beyond a few, or when a detection is due
  // anyway, the detection's grid finds the pairs.
  const bool many = s.tris.size() > c.candidates.size() / 16 + 16;
  insert_candidates(d);
  if (c.dirty || many) {
    c.dirty = true;
    return;
  }
  trial_pairs(d);
  s.found.clear();
  const auto sorted_end = c.pairs.begin() + static_cast<long>(c.sorted_pairs);
  auto o = c.pairs.begin();
  auto a = c.appended_order.begin();
  for (const auto& p : s.trial) {
    // A few trial pairs among many pairs: searched, not walked.
    o = std::lower_bound(o, sorted_end, p);
    if (o != sorted_end && *o == p) continue;
    a = std::lower_bound(a, c.appended_order.end(), p, CanonicalOrder{c});
    if (a != c.appended_order.end() && c.pairs[*a] == p) continue;
    const int i = candidate_index(c, p[0]), j = candidate_index(c, p[1]);
    if (i < 0 || j < 0 || !boxes_overlap(&c.boxes[4 * i], &c.boxes[4 * j])) continue;
    if (may_touch(&d, i, j)) s.found.push_back(p);
  }
  ++c.updates;
  if (s.found.empty()) return;
  const double handover = append_pairs(d);
  if (d.energy.started) d.energy.fracture += handover;
  // Sorted again once the appended pairs are a sixteenth of the sorted ones:
  // a pass over all pairs every so many updates instead of at each.
  if (c.pairs.size() - c.sorted_pairs > c.sorted_pairs / 16 + 64) sort_pairs(d);
  grow_to(c.pair_force, 12 * c.pairs.size());
  c.energy_partial.resize(2 * ((c.pairs.size() + kPairBlock - 1) / kPairBlock));
}

}  // namespace rockfdem::fdem::detail
