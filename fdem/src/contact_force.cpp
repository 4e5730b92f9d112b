// Narrow phase: Munjiza and Andrews' potential-based penalty contact
// (reference sec. 3) with Coulomb friction.
//
// The target's potential phi = 3 min(lambda_i) (barycentric coordinates) is
// 1 at its centroid and 0 on its edges. Each contactor edge A->B (length L,
// outward normal n) is clipped to the part inside the target, where phi is
// piecewise linear in the edge parameter xi; exactly integrated,
//   F_AB = p L int phi dxi,  F_B = p L int phi xi dxi,  F_A = F_AB - F_B
// push the contactor's nodes by -F n, and the target's nodes receive
// p L int phi lambda_i dxi n, the same force distributed by the barycentric
// coordinates of the points where it acts (so forces and moments balance
// exactly); lambda_i being linear along the edge, that is lambda_i(xi_c)
// F_AB n at the force centre xi_c = F_B / F_AB. Then the roles are swapped.
// This is the boundary form of the overlap integral of the two potentials'
// gradients.
//
// Cost: every contact triangle is packed once per step (pack). The pair
// loop tests the two packed triangles' boxes and copies the pairs that
// pass into a batch; the batch kernel (contact_roles.hpp) computes both
// roles of a vector register's worth of pairs at once without a branch,
// summing each pair's forces in the order of a scalar loop, and the pair
// loop copies them to the pairs' buffers.
//
// Friction: per contactor edge and pair, an incremental tangential spring at
// the edge's force centre xi_c = F_B / F_AB, F_t -= k_t v_t dt with
// k_t = 3 p L_in / H (the normal stiffness of the same overlap) and
// |F_t| <= mu F_n (mu from the residual friction angle). Optional normal
// damping c v_n, c = ratio 2 sqrt(k_n m), never making F_n adhesive.
#include <algorithm>
#include <cmath>

#include "contact_roles.hpp"
#include "engine_data.hpp"
#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

using Tri = ContactTriangle;

/// Packs triangle t (its gather row): corners, 2A, the gradients of its
/// barycentric coordinates, the smallest altitude, the edges' lengths and
/// unit tangents, and its bounding box, once per step instead of once per
/// pair and role.
inline void pack(const EngineData& d, int t, Tri& c, ContactBox& box) {
  const int* nd = &d.tris.nodes[3 * t];
  for (int k = 0; k < 3; ++k) {
    c.x[k] = d.nodes.pos[2 * nd[k]];
    c.y[k] = d.nodes.pos[2 * nd[k] + 1];
    c.vx[k] = d.nodes.vel[2 * nd[k]];
    c.vy[k] = d.nodes.vel[2 * nd[k] + 1];
    c.m[k] = d.nodes.mass[nd[k]];
  }
  pack_geometry(c);
  box.x_lo = std::min({c.x[0], c.x[1], c.x[2]});
  box.x_hi = std::max({c.x[0], c.x[1], c.x[2]});
  box.y_lo = std::min({c.y[0], c.y[1], c.y[2]});
  box.y_hi = std::max({c.y[0], c.y[1], c.y[2]});
}

/// Contact triangles are a thin sample of a large mesh: their nodes lie on
/// cache lines of their own, which the hardware does not fetch ahead.
/// Fetches the corners of triangle gather_tri[g + kAhead] and the corner
/// list of the one twice as far.
inline void prefetch_ahead(const EngineData& d, const int* gather_tri, long g, long ng) {
  constexpr long kAhead = 8;
  if (g + 2 * kAhead < ng) __builtin_prefetch(&d.tris.nodes[3 * gather_tri[g + 2 * kAhead]]);
  if (g + kAhead >= ng) return;
  const int* nd = &d.tris.nodes[3 * gather_tri[g + kAhead]];
  for (int k = 0; k < 3; ++k) {
    __builtin_prefetch(&d.nodes.pos[2 * nd[k]]);
    __builtin_prefetch(&d.nodes.vel[2 * nd[k]]);
    __builtin_prefetch(&d.nodes.mass[nd[k]]);
  }
}

/// Energy dissipated by the pairs of one block in one step (energy.hpp).
struct PairDissipation {
  double friction = 0, damping = 0;
};

/// One block's pairs on their way through a PairBatch: lane r holds pair
/// pair[r].
struct BlockPairs {
  PairBatch batch;
  int pair[kPairBatch];
  int n = 0;
};

/// Copies packed triangle c into lane r of `lanes`.
void load_triangle(const Tri& c, TriLanes& lanes, int r) {
  for (int k = 0; k < 3; ++k) {
    lanes.x[k][r] = c.x[k];
    lanes.y[k][r] = c.y[k];
    lanes.vx[k][r] = c.vx[k];
    lanes.vy[k][r] = c.vy[k];
    lanes.m[k][r] = c.m[k];
    lanes.len[k][r] = c.len[k];
    lanes.ex[k][r] = c.tx[k];
    lanes.ey[k][r] = c.ty[k];
    lanes.gx[k][r] = c.gx[k];
    lanes.gy[k][r] = c.gy[k];
  }
  lanes.h[r] = c.h;
  lanes.two_a[r] = c.two_a;
}

/// Copies pair q (triangles a, b, friction mu, springs) into the next lane.
void load_pair(const Tri& a, const Tri& b, double mu, const double* spring, long q,
               BlockPairs& bp) {
  PairBatch& pb = bp.batch;
  const int r = bp.n++;
  load_triangle(a, pb.tri[0], r);
  load_triangle(b, pb.tri[1], r);
  pb.mu[r] = mu;
  for (int j = 0; j < 6; ++j) pb.spring[j][r] = spring[j];
  bp.pair[r] = static_cast<int>(q);
}

/// Runs the batch, then copies each lane's forces and springs to its pair
/// and adds its edges' dissipation in pair and edge order (the scalar
/// loop's). Returns the number of touching pairs.
long flush_pairs(ContactData& c, const RoleParams& rp, BlockPairs& bp, PairDissipation& loss) {
  PairBatch& b = bp.batch;
  run_roles(b, bp.n, rp);
  long n_touching = 0;
  for (int r = 0; r < bp.n; ++r) {
    const long q = bp.pair[r];
    double* out = &c.pair_force[12 * q];
    double* spring = &c.friction[6 * q];
    for (int i = 0; i < 12; ++i) out[i] = b.force[i][r];
    for (int j = 0; j < 6; ++j) spring[j] = b.spring[j][r];
    // Most edges dissipate nothing: adding their zeros to a sum that is
    // never -0 would change no bit, so they are skipped.
    for (int j = 0; j < 6; ++j) {
      const double friction = b.loss_friction[j][r], damping = b.loss_damping[j][r];
      if (friction != 0.0) loss.friction += friction;
      if (damping != 0.0) loss.damping += damping;
    }
    n_touching += b.touching[r] != 0.0;
  }
  bp.n = 0;
  return n_touching;
}

/// Pair q apart: no force, springs reset (what the roles give it).
inline void clear_pair(ContactData& c, long q) {
  double* out = &c.pair_force[12 * q];
  double* spring = &c.friction[6 * q];
  for (int k = 0; k < 12; ++k) out[k] = 0.0;
  for (int k = 0; k < 6; ++k) spring[k] = 0.0;
}

/// Block `blk` of the pairs: each pair's 12 corner forces go to its own
/// buffer, its springs are updated; returns the number of touching pairs.
long block_forces(EngineData& d, long blk, const Tri* tris, const ContactBox* boxes, BlockPairs& bp,
                  PairDissipation& loss) {
  ContactData& c = d.contact;
  RoleParams rp;
  rp.p = c.penalty;
  rp.dt = d.dt;
  rp.damping = c.settings.damping_ratio;
  rp.friction = c.settings.friction;
  const long start = blk * kPairBlock;
  const long end = std::min(static_cast<long>(c.pairs.size()), start + kPairBlock);
  long n_touching = 0;
  const int* rows = c.entry_row.data();
  for (long q = start; q < end; ++q) {
    const int ra = rows[2 * q], rb = rows[2 * q + 1];
    const ContactBox &a = boxes[ra], &b = boxes[rb];
    // Most pairs lie within the buffer without touching: their boxes are
    // disjoint, and the roles are skipped (no force, springs reset).
    if (a.x_hi < b.x_lo || b.x_hi < a.x_lo || a.y_hi < b.y_lo || b.y_hi < a.y_lo ||
        pair_apart(tris[ra], tris[rb])) {
      clear_pair(c, q);
      continue;
    }
    const double mu =
        std::min(c.mu[d.tris.material[c.pairs[q][0]]], c.mu[d.tris.material[c.pairs[q][1]]]);
    load_pair(tris[ra], tris[rb], mu, &c.friction[6 * q], q, bp);
    if (bp.n == kPairBatch) n_touching += flush_pairs(c, rp, bp, loss);
  }
  if (bp.n > 0) n_touching += flush_pairs(c, rp, bp, loss);
  return n_touching;
}

/// Sum of contact triangle g's pair entries, in ascending pair order, added
/// to its three force slots.
inline void gather_triangle(const ContactData& c, long g, double* slots) {
  double sum[6] = {0, 0, 0, 0, 0, 0};
  each_gather_entry(c, g, [&](int entry) {
    // entry = 2 q + side: its six values start at 12 q + 6 side = 6 entry.
    const double* f = &c.pair_force[6 * static_cast<std::size_t>(entry)];
    for (int i = 0; i < 6; ++i) sum[i] += f[i];
  });
  double* s = slots + 6 * c.gather_tri[g];
  for (int i = 0; i < 6; ++i) s[i] += sum[i];
}

}  // namespace

double largest_drift2(const EngineData& d, const int* nodes, long n) {
  double worst = 0.0;
  // Serial below a few thousand nodes (an intact body's outline): a
  // parallel region would cost more than the loop.
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(max                                                              \
              : worst) if (n > 16384)
  for (long i = 0; i < n; ++i) {
    const int node = nodes[i];
    const double dx = d.nodes.pos[2 * node] - d.detected_position(node, 0);
    const double dy = d.nodes.pos[2 * node + 1] - d.detected_position(node, 1);
    worst = std::max(worst, dx * dx + dy * dy);
  }
  return worst;
}

void contact_forces(EngineData& d) {
  ContactData& c = d.contact;
  // Two pieces approach by at most twice the largest drift: detect again
  // once that could close the buffer. The nodes are measured only once the
  // bound on their drift could be beyond that; below it the measure could
  // not find it, so the detections come at the same steps.
  if (!c.dirty && !c.watch_nodes.empty() && !(2.0 * c.drift_bound < c.buffer)) {
    const double worst2 = largest_drift2(d, c.watch_nodes.data(), long(c.watch_nodes.size()));
    if (4.0 * worst2 > c.buffer * c.buffer) {
      c.dirty = true;
    } else {
      c.drift_bound = bound_drift(std::sqrt(worst2), c.buffer);
    }
  }
  if (c.dirty) contact_detect(d);
  const long np = static_cast<long>(c.pairs.size());
  if (np == 0) {
    ++c.steps_skipped;
    c.touching = 0;
    return;
  }
  ++c.steps_with_pairs;
  long touching = 0;
  const long ng = static_cast<long>(c.gather_tri.size());
  const long n_blocks = (np + kPairBlock - 1) / kPairBlock;
  double* slots = d.slots.data();
  double* partial = c.energy_partial.data();
  // Sized with the pairs (a no-op unless a detection or update changed
  // them, or a checkpoint was loaded); the capacity stays.
  grow_to(c.narrow.tris, ng);
  grow_to(c.narrow.boxes, ng);
  Tri* tris = c.narrow.tris.data();
  ContactBox* boxes = c.narrow.boxes.data();
  // One parallel region for the three loops (the barriers between them are
  // the fors'), none at all for a handful of pairs.
#pragma omp parallel num_threads(thread_count(d.threads)) if (np > 64)
  {
    // Each contact triangle packed once (the pairs find it by entry_row).
#pragma omp for schedule(static)
    for (long g = 0; g < ng; ++g) {
      prefetch_ahead(d, c.gather_tri.data(), g, ng);
      pack(d, c.gather_tri[g], tris[g], boxes[g]);
    }
    BlockPairs batch{};  // per thread, on its stack (zeroed: padding lanes are read)
#pragma omp for schedule(dynamic, 1) reduction(+ : touching)
    for (long b = 0; b < n_blocks; ++b) {
      PairDissipation loss;
      touching += block_forces(d, b, tris, boxes, batch, loss);
      partial[2 * b] = loss.friction;
      partial[2 * b + 1] = loss.damping;
    }
    // Gather: each contact triangle sums its pairs in ascending pair order
    // into its own force slots (rewritten by the triangle loop every step).
#pragma omp for schedule(static)
    for (long g = 0; g < ng; ++g) gather_triangle(c, g, slots);
  }
  c.touching = touching;
  for (long b = 0; b < n_blocks; ++b) {
    d.energy.friction += partial[2 * b];
    d.energy.contact_damping += partial[2 * b + 1];
  }
}

}  // namespace rockfdem::fdem::detail
