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
// Cost: every contact triangle is packed once per step (pack); the pair
// loop reads two packed triangles, and a role computes the contactor's
// three corners' barycentric coordinates once, for its three edges.
//
// Friction: per contactor edge and pair, an incremental tangential spring at
// the edge's force centre xi_c = F_B / F_AB, F_t -= k_t v_t dt with
// k_t = 3 p L_in / H (the normal stiffness of the same overlap) and
// |F_t| <= mu F_n (mu from the residual friction angle). Optional normal
// damping c v_n, c = ratio 2 sqrt(k_n m), never making F_n adhesive.
#include <algorithm>
#include <cmath>

#include "engine_data.hpp"
#include "parallel.hpp"

namespace rockfdem::fdem::detail {
namespace {

using Tri = ContactTriangle;

/// Packs triangle t (its gather row): corners, 2A, the gradients of its
/// barycentric coordinates, the smallest altitude, the edges' lengths and
/// unit tangents and the bounding box, once per step instead of once per
/// pair and role.
inline void pack(const EngineData& d, int t, Tri& c) {
  const int* nd = &d.tris.nodes[3 * t];
  for (int k = 0; k < 3; ++k) {
    c.x[k] = d.nodes.pos[2 * nd[k]];
    c.y[k] = d.nodes.pos[2 * nd[k] + 1];
    c.vx[k] = d.nodes.vel[2 * nd[k]];
    c.vy[k] = d.nodes.vel[2 * nd[k] + 1];
    c.m[k] = d.nodes.mass[nd[k]];
  }
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
  c.x_lo = std::min({c.x[0], c.x[1], c.x[2]});
  c.x_hi = std::max({c.x[0], c.x[1], c.x[2]});
  c.y_lo = std::min({c.y[0], c.y[1], c.y[2]});
  c.y_hi = std::max({c.y[0], c.y[1], c.y[2]});
}

/// Barycentric coordinates of (px, py) in triangle t: lambda_i vanishes on
/// the edge opposite corner i, so at corner i + 1, and grows from there
/// with its packed gradient.
inline void barycentric(const Tri& t, double px, double py, double l[3]) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    l[i] = t.gx[i] * (px - t.x[j]) + t.gy[i] * (py - t.y[j]);
  }
}

/// Exact integrals of phi = 3 min(lambda) over the part of the edge inside
/// the target: i0 = int phi, i1 = int phi xi, and the inside length
/// fraction. lambda is linear from la (xi = 0) to lb (xi = 1), so
/// int phi lambda_i = la_i i0 + (lb_i - la_i) i1 = i0 lambda_i(xi_c) with
/// xi_c = i1 / i0: the target's share needs no integral of its own.
struct EdgeIntegral {
  double i0 = 0, i1 = 0, inside = 0;
};

inline bool integrate_edge(const double la[3], const double lb[3], EdgeIntegral& out) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (la[i] < 0.0 && lb[i] < 0.0) return false;
    if (la[i] < 0.0) lo = std::max(lo, la[i] / (la[i] - lb[i]));
    else if (lb[i] < 0.0) hi = std::min(hi, la[i] / (la[i] - lb[i]));
  }
  if (!(hi > lo)) return false;
  // Breakpoints of min(lambda): lo, where two coordinates cross strictly
  // inside (lo, hi) (at most three, sorted), hi.
  double xs[5];
  xs[0] = lo;
  int n = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double d0 = la[i] - la[j], d1 = lb[i] - lb[j];
      if ((d0 < 0.0) != (d1 < 0.0) && d0 != d1) {
        const double x = d0 / (d0 - d1);
        if (x > lo && x < hi) xs[n++] = x;
      }
    }
  for (int i = 2; i < n; ++i)  // insertion sort of the inner ones
    for (int j = i; j > 1 && xs[j] < xs[j - 1]; --j) std::swap(xs[j], xs[j - 1]);
  xs[n++] = hi;
  // phi at each breakpoint once (each inner one ends a segment and starts
  // the next).
  double ph[5];
  for (int s = 0; s < n; ++s) {
    double m = la[0] + (lb[0] - la[0]) * xs[s];
    for (int i = 1; i < 3; ++i) m = std::min(m, la[i] + (lb[i] - la[i]) * xs[s]);
    ph[s] = 3.0 * std::max(0.0, m);
  }
  // Sorted: a segment of two equal breakpoints adds zero.
  for (int s = 0; s + 1 < n; ++s) {
    const double a = xs[s], b = xs[s + 1], w = b - a;
    const double pa = ph[s], pb = ph[s + 1];
    out.i0 += 0.5 * w * (pa + pb);
    out.i1 += w / 6.0 * (pa * (2.0 * a + b) + pb * (a + 2.0 * b));
  }
  out.inside = hi - lo;
  return out.i0 > 0.0;
}

struct RoleParams {
  double p, mu, dt, damping;
  bool friction;
};

/// Energy dissipated by one pair in one step (energy.hpp).
struct PairDissipation {
  double friction = 0, damping = 0;
};

/// Contactor c's three edges against target t; adds the forces to fc, ft
/// (6 each: corner x, y), updates the three friction springs. Returns true
/// when some edge overlaps.
bool role(const Tri& c, const Tri& t, const RoleParams& rp, double* spring, double* fc,
          double* ft, PairDissipation& loss) {
  if (!(t.two_a > 0.0)) return false;
  // The contactor's corners in the target's barycentric coordinates, once
  // per corner (each starts one edge and ends another).
  double lam[3][3];
  for (int v = 0; v < 3; ++v) barycentric(t, c.x[v], c.y[v], lam[v]);
  // All three corners outside one edge of the target: no edge can enter
  // (integrate_edge would reject each one on that coordinate).
  for (int i = 0; i < 3; ++i)
    if (lam[0][i] < 0.0 && lam[1][i] < 0.0 && lam[2][i] < 0.0) {
      spring[0] = spring[1] = spring[2] = 0.0;
      return false;
    }
  bool touching = false;
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3;
    const double* la = lam[a];
    const double* lb = lam[b];
    EdgeIntegral e;
    if (!integrate_edge(la, lb, e)) {
      spring[k] = 0.0;
      continue;
    }
    touching = true;
    const double len = c.len[k], tx = c.tx[k], ty = c.ty[k], nx = ty, ny = -tx;  // n outward
    const double s = rp.p * len;
    const double f_ab = s * e.i0, f_b = s * e.i1, f_a = f_ab - f_b;
    // Point of action and the relative velocity there.
    const double xi = e.i1 / e.i0;
    double lc[3], vtx = 0, vty = 0;
    for (int i = 0; i < 3; ++i) {
      lc[i] = la[i] + (lb[i] - la[i]) * xi;
      vtx += lc[i] * t.vx[i];
      vty += lc[i] * t.vy[i];
    }
    const double vrx = (1 - xi) * c.vx[a] + xi * c.vx[b] - vtx;
    const double vry = (1 - xi) * c.vy[a] + xi * c.vy[b] - vty;
    const double k_n = 3.0 * s * e.inside / t.h;
    double f_d = 0.0;  // normal damping, > 0 while approaching (v_r . n > 0)
    if (rp.damping > 0.0) {
      const double m = std::min(c.m[a], c.m[b]);
      const double v_n = vrx * nx + vry * ny;
      f_d = std::max(rp.damping * 2.0 * std::sqrt(k_n * m) * v_n, -f_ab);
      loss.damping += f_d * v_n * rp.dt;
    }
    double f_t = 0.0;
    if (rp.friction) {
      const double trial = spring[k] - k_n * (vrx * tx + vry * ty) * rp.dt;
      const double cap = rp.mu * (f_ab + f_d);
      f_t = std::clamp(trial, -cap, cap);
      spring[k] = f_t;
      // Clipped: the slip beyond the spring's, (trial - f_t) / k_n, is
      // plastic and dissipates f_t times it (return mapping).
      if (f_t != trial) loss.friction += f_t * (trial - f_t) / k_n;
    }
    // Contactor: potential force at A, B plus the point force (F_t t - F_d n)
    // at xi. Target: the opposite of their sum, at the same point, shared by
    // its barycentric coordinates there (p L int phi lambda_i = lc_i F_AB).
    const double px = f_t * tx - f_d * nx, py = f_t * ty - f_d * ny;
    fc[2 * a] += -f_a * nx + (1 - xi) * px;
    fc[2 * a + 1] += -f_a * ny + (1 - xi) * py;
    fc[2 * b] += -f_b * nx + xi * px;
    fc[2 * b + 1] += -f_b * ny + xi * py;
    const double gx = f_ab * nx - px, gy = f_ab * ny - py;
    for (int i = 0; i < 3; ++i) {
      ft[2 * i] += lc[i] * gx;
      ft[2 * i + 1] += lc[i] * gy;
    }
  }
  return touching;
}

/// Both roles of pair q (its triangles packed in rows ra, rb); its 12
/// corner forces go to its own buffer.
bool pair_forces(const EngineData& d, std::size_t q, const Tri& a, const Tri& b, double* spring,
                 double* out, PairDissipation& loss) {
  const ContactData& c = d.contact;
  for (int k = 0; k < 12; ++k) out[k] = 0.0;
  // Most pairs lie within the buffer without touching: their boxes are
  // disjoint, and the edge clipping is skipped (springs reset, as apart).
  if (a.x_hi < b.x_lo || b.x_hi < a.x_lo || a.y_hi < b.y_lo || b.y_hi < a.y_lo) {
    for (int k = 0; k < 6; ++k) spring[k] = 0.0;
    return false;
  }
  RoleParams rp;
  rp.p = c.penalty;
  rp.mu = std::min(c.mu[d.tris.material[c.pairs[q][0]]], c.mu[d.tris.material[c.pairs[q][1]]]);
  rp.dt = d.dt;
  rp.damping = c.settings.damping_ratio;
  rp.friction = c.settings.friction;
  const bool t0 = role(a, b, rp, spring, out, out + 6, loss);
  const bool t1 = role(b, a, rp, spring + 3, out + 6, out, loss);
  return t0 || t1;
}

/// Largest squared displacement of a watched node since the detection.
double watched_drift2(const EngineData& d) {
  const ContactData& c = d.contact;
  const long n = static_cast<long>(c.watch_nodes.size());
  double worst = 0.0;
  // Serial below a few thousand nodes (an intact body's outline): a
  // parallel region would cost more than the loop.
#pragma omp parallel for schedule(static) num_threads(thread_count(d.threads)) \
    reduction(max : worst) if (n > 16384)
  for (long i = 0; i < n; ++i) {
    const int node = c.watch_nodes[i];
    const double dx = d.nodes.pos[2 * node] - c.detect_pos[2 * node];
    const double dy = d.nodes.pos[2 * node + 1] - c.detect_pos[2 * node + 1];
    worst = std::max(worst, dx * dx + dy * dy);
  }
  return worst;
}

/// Sum of contact triangle g's pair entries, in ascending pair order, added
/// to its three force slots.
inline void gather_triangle(const ContactData& c, long g, double* slots) {
  double sum[6] = {0, 0, 0, 0, 0, 0};
  for (int k = c.gather_start[g]; k < c.gather_start[g + 1]; ++k) {
    // entry = 2 q + side: its six values start at 12 q + 6 side = 6 entry.
    const double* f = &c.pair_force[6 * static_cast<std::size_t>(c.gather_entry[k])];
    for (int i = 0; i < 6; ++i) sum[i] += f[i];
  }
  double* s = slots + 6 * c.gather_tri[g];
  for (int i = 0; i < 6; ++i) s[i] += sum[i];
}

}  // namespace

void contact_forces(EngineData& d) {
  ContactData& c = d.contact;
  // Two pieces approach by at most twice the largest drift: detect again
  // once that could close the buffer.
  if (!c.dirty && !c.watch_nodes.empty() && 4.0 * watched_drift2(d) > c.buffer * c.buffer)
    c.dirty = true;
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
  c.narrow.tris.resize(ng);
  c.narrow.rows.resize(2 * np);
  Tri* tris = c.narrow.tris.data();
  int* rows = c.narrow.rows.data();
  // One parallel region for the three loops (the barriers between them are
  // the fors'), none at all for a handful of pairs.
#pragma omp parallel num_threads(thread_count(d.threads)) if (np > 64)
  {
    // Each contact triangle packed once, and its row written to the entries
    // of its pairs.
#pragma omp for schedule(static)
    for (long g = 0; g < ng; ++g) {
      pack(d, c.gather_tri[g], tris[g]);
      for (int k = c.gather_start[g]; k < c.gather_start[g + 1]; ++k)
        rows[c.gather_entry[k]] = static_cast<int>(g);
    }
#pragma omp for schedule(dynamic, 1) reduction(+ : touching)
    for (long b = 0; b < n_blocks; ++b) {
      PairDissipation loss;
      const long end = std::min(np, (b + 1) * kPairBlock);
      for (long q = b * kPairBlock; q < end; ++q)
        touching += pair_forces(d, q, tris[rows[2 * q]], tris[rows[2 * q + 1]],
                                &c.friction[6 * q], &c.pair_force[12 * q], loss);
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
