// Contact between triangles (reference sec. 3), private to fdem/.
//
//   contact_setup    once per set_contact: edge neighbours, penalty, buffer
//   contact_detect   broad phase: free-surface triangles, exclusions, grid
//   contact_breaks   after crack elements broke: the same broad phase,
//                    updated locally (new candidates, their pairs)
//   contact_forces   per step: re-detect if needed, narrow phase per pair,
//                    friction, gather into the triangles' force slots
//
// Determinism: every pair writes its twelve corner forces into its own
// buffer; each contact triangle then sums its pairs' entries in ascending
// pair order (contact_gather.cpp) and adds the sum to its own force
// slots, which the node loop gathers as usual. While no candidate pair
// exists the step does nothing but a displacement check over the
// free-surface nodes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "contact_grid.hpp"
#include "energy.hpp"
#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem::detail {

/// v.resize(n), with the capacity grown to n + n / 8 where it must grow:
/// libstdc++'s resize at least doubles it, and the pair and candidate
/// arrays grow a little at each local update, so doubling left up to half
/// of them unused at the end of a run.
template <class T>
void grow_to(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) v.reserve(n + n / 8);
  v.resize(n);
}

struct EngineData;

/// Scratch of contact_breaks and build_gather, reused so that a warmed-up
/// run allocates nothing.
struct BreakScratch {
  std::vector<int> cracks, tris, vertices, ints, merged;
  std::vector<std::array<int, 2>> trial, found;
  std::vector<int> gather_index;  ///< per triangle: its gather row, -1 between uses
};

/// A contact triangle as the narrow phase reads it, packed once per step
/// (contact_force.cpp): its corners and the target-side constants of the
/// clipping, so that no pair gathers nodes or recomputes them. 32 doubles,
/// aligned: a row is four whole cache lines.
struct alignas(64) ContactTriangle {
  double x[3], y[3], vx[3], vy[3], m[3];
  double two_a;                 ///< twice the area (corners counter-clockwise: > 0)
  double gx[3], gy[3];          ///< gradients of the barycentric coordinates
  double h;                     ///< smallest altitude (meaningful when two_a > 0)
  double len[3], tx[3], ty[3];  ///< edge k (corners k -> k+1): length, unit tangent
};

/// Fills c's twice-area, barycentric gradients, edge lengths and tangents
/// and smallest altitude from its corners (c.x, c.y).
inline void pack_geometry(ContactTriangle& c) {
  c.two_a = (c.x[1] - c.x[0]) * (c.y[2] - c.y[0]) - (c.x[2] - c.x[0]) * (c.y[1] - c.y[0]);
  const double inv2a = 1.0 / c.two_a;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    c.gx[i] = (c.y[j] - c.y[k]) * inv2a;
    c.gy[i] = (c.x[k] - c.x[j]) * inv2a;
  }
  double longest2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double ex = c.x[(k + 1) % 3] - c.x[k], ey = c.y[(k + 1) % 3] - c.y[k];
    const double len2 = ex * ex + ey * ey;
    longest2 = std::max(longest2, len2);
    c.len[k] = std::sqrt(len2);
    c.tx[k] = ex / c.len[k];
    c.ty[k] = ey / c.len[k];
  }
  // The smallest altitude from the longest edge (no hypot: the lengths are
  // those of a mesh, far from overflow).
  c.h = c.two_a / std::sqrt(longest2);
}

/// Whether an edge of s has all of o's corners outside it by more than a
/// millionth of s's smallest altitude.
inline bool edge_separates(const ContactTriangle& s, const ContactTriangle& o) {
  constexpr double kApartGap = 1e-6;
  const double gap = kApartGap * s.h;
  for (int k = 0; k < 3; ++k) {
    const double nx = s.ty[k], ny = -s.tx[k];  // outward (counter-clockwise corners)
    double nearest = (o.x[0] - s.x[k]) * nx + (o.y[0] - s.y[k]) * ny;
    nearest = std::min(nearest, (o.x[1] - s.x[k]) * nx + (o.y[1] - s.y[k]) * ny);
    nearest = std::min(nearest, (o.x[2] - s.x[k]) * nx + (o.y[2] - s.y[k]) * ny);
    if (nearest > gap) return true;
  }
  return false;
}

/// Whether two packed triangles of positive area are apart: an edge of
/// either separates them. Most contact pairs whose boxes overlap are such
/// neighbours (triangles around a vertex, apart across broken faces). The
/// roles would find no edge inside the other triangle and give no force,
/// reset springs and no dissipation; the gap (a millionth of the altitude,
/// far above the rounding of the roles' barycentric coordinates) leaves
/// every pair they could find touching to them, so the pair loop skips
/// these without a change of any bit
/// (`ContactRoles.pairs_called_apart_get_nothing_from_the_roles`).
inline bool pair_apart(const ContactTriangle& a, const ContactTriangle& b) {
  if (!(a.two_a > 0.0) || !(b.two_a > 0.0)) return false;  // a role keeps its springs there
  return edge_separates(a, b) || edge_separates(b, a);
}

/// A contact triangle's bounding box, packed with it.
struct ContactBox {
  double x_lo, x_hi, y_lo, y_hi;
};

/// Per-step scratch of the narrow phase: rewritten at the start of every
/// contact pass before it is read. The pair loop tests the compact boxes
/// first and reads the rows of the pairs whose boxes overlap only.
struct NarrowScratch {
  std::vector<ContactTriangle> tris;  ///< per gather row (gather_tri)
  std::vector<ContactBox> boxes;      ///< per gather row
};

struct ContactData {
  ContactSettings settings;
  double penalty = 0, buffer = 0;
  std::vector<double> mu;  ///< per material: tan(residual friction angle)
  // Detection results.
  std::vector<int> candidates;            ///< free-surface triangles, ascending
  std::vector<double> boxes;              ///< 4 per candidate, grown by buffer / 2
  std::vector<int> watch_nodes;           ///< nodes of the candidates (displacement check)
  std::vector<float> detect_shift;        ///< per node, interleaved: its position at the last
                                          ///< detection less its mesh vertex's (a displacement:
                                          ///< single precision rounds it by ~1e-7 of itself, where
                                          ///< an absolute coordinate would lose ~1e-7 of the
                                          ///< model's extent); EngineData::detected_position()
  std::vector<std::array<int, 2>> pairs;  ///< triangle ids: [0, sorted_pairs) in canonical
                                          ///< order (the last detection's), then those local
                                          ///< updates appended since (contact_gather.cpp)
  std::size_t sorted_pairs = 0;
  std::vector<int> appended_order;     ///< the appended pairs' indices, canonical order
  std::vector<double> friction;        ///< 6 per pair: role x contactor edge
  std::vector<double> pair_force;      ///< 12 per pair: A's corners, B's corners; between
                                       ///< contact passes a detection's scratch
  std::vector<double> energy_partial;  ///< 2 per block of kPairBlock pairs: friction, damping
  // Gather (contact_gather.cpp): row g sums the entries 2 pair + side of
  // triangle gather_tri[g] in canonical pair order, merging the sorted
  // pairs' from a CSR over rows [0, gather_start.size() - 1) with the
  // appended pairs' from the row's list: entry 2 sorted_pairs + x for each
  // x from extra_head[g] along extra_next, kept in canonical order.
  std::vector<int> gather_tri, gather_start, gather_entry;
  std::vector<int> extra_head;                    ///< per row: first appended x or -1
  std::vector<int> extra_next;                    ///< per appended entry x: next x or -1
  std::vector<std::array<int, 2>> appended_rows;  ///< (triangle, row) past the CSR's rows
  std::vector<int> entry_row;  ///< per pair entry 2 pair + side: its gather row (the
                               ///< inverse of the gather, built with it)
  GridScratch grid;
  BreakScratch breaks;
  NarrowScratch narrow;
  /// At least the largest drift of a watched node since the detection
  /// (bound_drift); infinity: unknown.
  double drift_bound = std::numeric_limits<double>::infinity();
  bool dirty = true;           ///< re-detect before the next contact pass
  bool topology_dirty = true;  ///< candidates must be rebuilt
  long detections = 0, steps_with_pairs = 0, steps_skipped = 0, touching = 0;
  long updates = 0;  ///< local updates after breakage (contact_breaks)
};

/// Pair indices in the canonical order of their pairs (triangle ids), and
/// a pair index against a pair: the order the sorted and appended pairs
/// are merged and searched in.
struct CanonicalOrder {
  const ContactData& c;
  bool operator()(int a, int b) const { return c.pairs[a] < c.pairs[b]; }
  bool operator()(int a, const std::array<int, 2>& p) const { return c.pairs[a] < p; }
};

/// Edge neighbours and crack elements per triangle edge, penalty, buffer,
/// friction coefficients.
void contact_setup(EngineData& d);

/// Broad phase: candidates (active triangles with a free edge), exclusions
/// (shared nodes, an intact crack element between them, or one shared vertex
/// whose nodes an intact chain of crack elements joins), grid pairs.
void contact_detect(EngineData& d);

/// After crack elements broke in this step (broken_step == step): their
/// triangles become candidates, and the pairs that the breakage allows
/// (the components at their end vertices may split) are inserted, tested at
/// the positions of the last detection. The result equals a full detection
/// at those positions (contact_detect.cpp explains why that is safe). Falls
/// back to a full detection (of pairs; the candidates are updated here)
/// when many triangles change at once or one is due anyway.
void contact_breaks(EngineData& d);

/// The gather and entry_row from the pairs and sorted_pairs: after a
/// detection, and after a checkpoint is loaded (the gather is not saved).
void build_gather(EngineData& d);

/// Appends the entries of pair q, the last pair, to its triangles' rows.
void append_pair_entries(ContactData& c, std::size_t q);

/// Calls f(entry) for each entry of gather row g in canonical pair order:
/// the order a full detection gives, so that the sums have its bits.
template <class F>
inline void each_gather_entry(const ContactData& c, long g, F f) {
  int k = 0, end = 0;
  if (g + 1 < static_cast<long>(c.gather_start.size())) {
    k = c.gather_start[g];
    end = c.gather_start[g + 1];
  }
  const int base = static_cast<int>(2 * c.sorted_pairs);
  for (int x = c.extra_head[g]; x >= 0; x = c.extra_next[x]) {
    const std::array<int, 2>& appended = c.pairs[(base + x) / 2];
    for (; k < end && c.pairs[c.gather_entry[k] / 2] < appended; ++k) f(c.gather_entry[k]);
    f(base + x);
  }
  for (; k < end; ++k) f(c.gather_entry[k]);
}

/// One step of contact; see the header comment.
void contact_forces(EngineData& d);

/// Largest squared displacement of nodes[0, n) since the last detection.
double largest_drift2(const EngineData& d, const int* nodes, long n);

/// A drift bound from a drift `moved` plus margins for rounding: a billionth
/// of `buffer` (above a step's rounding of positions in a model up to 10^6
/// buffers wide) and of `moved` itself.
inline double bound_drift(double moved, double buffer) {
  constexpr double kMargin = 1e-9;
  return moved * (1.0 + kMargin) + kMargin * buffer;
}

/// Every node moved at most `distance` in a step: the drift check's bound
/// grows by it (no node moved farther than the fastest one did).
inline void contact_nodes_moved(ContactData& c, double distance) {
  c.drift_bound += bound_drift(distance, c.buffer);
}

/// Nodes moved by other than a step (kinetic damping's settle), or a state
/// was loaded: the bound is unknown and the next drift check measures.
inline void contact_drift_unknown(ContactData& c) {
  c.drift_bound = std::numeric_limits<double>::infinity();
}

/// Pairs per block of the pair loop (dynamic scheduling; the energy sums
/// are partials per block, added in block order).
constexpr long kPairBlock = 64;

/// Stored energy of pair q at `at`: the penalty potential
/// p int (phi_A + phi_B) dA over the overlap plus the friction springs'
/// F^2 / (2 k_t) (contact_energy.cpp).
double contact_pair_energy(const EngineData& d, std::size_t q, const Placement& at);
/// The same for triangles ta, tb with friction springs `springs` (6, or nullptr).
double contact_pair_energy(const EngineData& d, int ta, int tb, const double* springs,
                           const Placement& at);

/// Sum over all pairs (0 with contact off).
double contact_energy(const EngineData& d, const Placement& at);

}  // namespace rockfdem::fdem::detail
