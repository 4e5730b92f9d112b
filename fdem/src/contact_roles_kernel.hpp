// The narrow phase's kernel (contact_roles.cpp), written once for any
// vector width. No include guard on purpose: isa_regions.hpp includes it
// once per instruction set, each time inside its own namespace and target
// region.
//
// Every lane evaluates every step of the scalar algorithm and keeps or
// drops each result by a select:
//  - clipping: the part [lo, hi] of the edge where all three barycentric
//    coordinates lambda_i of the target are >= 0 (empty: no hit);
//  - breakpoints: where two coordinates cross strictly inside (lo, hi); a
//    crossing that does not count is replaced by lo, which after sorting
//    only adds segments of zero width (+0 to both integrals, exactly, as
//    long as phi is finite: 0 * inf would be NaN);
//  - phi = 3 max(0, min lambda) at the five points, and the exact integrals
//    i0 = int phi, i1 = int phi xi segment by segment;
//  - the force at A, B and at the centre xi = i1 / i0, friction and damping.
// The selects are written as the standard library's min, max and clamp
// define them ((b < a) ? b : a, ...), so a lane gives exactly the bits of
// the scalar formulas.
//
// Expects: PairBatch, TriLanes, RoleParams (contact_roles.hpp), the vector
// types V2, V4, V8 (isa_regions.hpp).

#include "vector_lanes.hpp"

/// The target's three barycentric coordinates at one point of each lane.
template <class V>
struct Coords {
  V l0, l1, l2;
};

/// lambda = la + (lb - la) xi, component by component.
template <class V>
LANE_INLINE Coords<V> along(Coords<V> la, Coords<V> lb, V xi) {
  return {la.l0 + (lb.l0 - la.l0) * xi, la.l1 + (lb.l1 - la.l1) * xi, la.l2 + (lb.l2 - la.l2) * xi};
}

/// phi = 3 max(0, min_i lambda_i) at xi.
template <class V>
LANE_INLINE V phi_at(Coords<V> la, Coords<V> lb, V xi) {
  const Coords<V> l = along(la, lb, xi);
  return 3.0 * max_of(V{}, min_of(min_of(l.l0, l.l1), l.l2));
}

/// Breakpoint of two coordinates (ai, aj at xi = 0, bi, bj at 1): where
/// they cross strictly inside (lo, hi), else lo. (A crossing needs exactly
/// one negative difference, so the differences differ and x is defined.)
template <class V>
LANE_INLINE V crossing(V ai, V aj, V bi, V bj, V lo, V hi) {
  const V zero{};
  const V d0 = ai - aj, d1 = bi - bj;
  const V x = d0 / (d0 - d1);
  const auto crosses = (d0 < zero) ^ (d1 < zero);
  const auto inner = (x > lo) & (x < hi);
  return (crosses & inner) ? x : lo;
}

/// Clips [lo, hi] by one coordinate going from la (xi = 0) to lb (1);
/// negative at both ends empties it for good (hi = -1 < lo).
template <class V>
LANE_INLINE void clip(V la, V lb, V& lo, V& hi) {
  const V zero{};
  const V x = la / (la - lb);
  const auto out_a = la < zero, out_b = lb < zero;
  lo = out_a ? max_of(lo, x) : lo;
  hi = (out_a & out_b) ? all<V>(-1.0) : ((~out_a & out_b) ? min_of(hi, x) : hi);
}

/// Sorts a <= b.
template <class V>
LANE_INLINE void order(V& a, V& b) {
  const V lo = min_of(a, b);
  b = max_of(a, b);
  a = lo;
}

/// Adds segment [x0, x1] (phi pa, pb at its ends) to the integrals.
template <class V>
LANE_INLINE void segment(V x0, V x1, V pa, V pb, V& i0, V& i1) {
  const V w = x1 - x0;
  i0 += 0.5 * w * (pa + pb);
  i1 += w / 6.0 * (pa * (2.0 * x0 + x1) + pb * (x0 + 2.0 * x1));
}

/// Edge k (corners a -> e) of contactor c against target t in the lanes
/// from r: la, lb are the target's coordinates of corners a and e; `valid`
/// marks lanes whose target has a positive area; row is the edge's row of
/// the per-edge arrays. Adds the edge's forces to fc (contactor) and ft
/// (target) where it touches, and returns where it does.
template <class V, bool Damping, bool Friction>
LANE_INLINE Mask<V> edge_lanes(PairBatch& b, int r, const TriLanes& c, const TriLanes& t, int k,
                               int a, int e, Coords<V> la, Coords<V> lb, Mask<V> valid, int row,
                               V* fc, V* ft, const RoleParams& rp) {
  const V zero{};
  // Clipping.
  V lo = zero, hi = all<V>(1.0);
  clip(la.l0, lb.l0, lo, hi);
  clip(la.l1, lb.l1, lo, hi);
  clip(la.l2, lb.l2, lo, hi);
  // Where no lane's edge enters its target (fragments near but apart),
  // the rest would only confirm it: springs reset (kept for a skipped
  // role), nothing dissipated, no force.
  const V spring_in = load<V>(&b.spring[row][r]);
  const Mask<V> open = valid & (hi > lo);
  if (!any_lane(open)) {
    store(&b.spring[row][r], valid ? zero : spring_in);
    store(&b.loss_friction[row][r], zero);
    store(&b.loss_damping[row][r], zero);
    return open;  // no lane
  }
  // Breakpoints, sorted (three compare-exchanges).
  V s0 = crossing(la.l0, la.l1, lb.l0, lb.l1, lo, hi);
  V s1 = crossing(la.l0, la.l2, lb.l0, lb.l2, lo, hi);
  V s2 = crossing(la.l1, la.l2, lb.l1, lb.l2, lo, hi);
  order(s0, s1);
  order(s1, s2);
  order(s0, s1);
  // Exact integrals over the four segments.
  const V p_lo = phi_at(la, lb, lo), p0 = phi_at(la, lb, s0), p1 = phi_at(la, lb, s1);
  const V p2 = phi_at(la, lb, s2), p_hi = phi_at(la, lb, hi);
  V i0 = zero, i1 = zero;
  segment(lo, s0, p_lo, p0, i0, i1);
  segment(s0, s1, p0, p1, i0, i1);
  segment(s1, s2, p1, p2, i0, i1);
  segment(s2, hi, p2, p_hi, i0, i1);
  const V inside = hi - lo;
  // A hit: a valid target, a non-empty inside part, a positive integral.
  const Mask<V> hit = open & (i0 > zero);
  // Forces: the potential's at A and B, friction and damping at the centre.
  const V len = load<V>(&c.len[k][r]), tx = load<V>(&c.ex[k][r]), ty = load<V>(&c.ey[k][r]);
  const V nx = ty, ny = -tx;  // outward normal
  const V s = rp.p * len;
  const V f_ab = s * i0, f_b = s * i1, f_a = f_ab - f_b;
  const V xi = i1 / i0;
  const Coords<V> lc = along(la, lb, xi);
  V vtx = zero, vty = zero;
  vtx += lc.l0 * load<V>(&t.vx[0][r]);
  vty += lc.l0 * load<V>(&t.vy[0][r]);
  vtx += lc.l1 * load<V>(&t.vx[1][r]);
  vty += lc.l1 * load<V>(&t.vy[1][r]);
  vtx += lc.l2 * load<V>(&t.vx[2][r]);
  vty += lc.l2 * load<V>(&t.vy[2][r]);
  const V vrx = (1 - xi) * load<V>(&c.vx[a][r]) + xi * load<V>(&c.vx[e][r]) - vtx;
  const V vry = (1 - xi) * load<V>(&c.vy[a][r]) + xi * load<V>(&c.vy[e][r]) - vty;
  const V k_n = 3.0 * s * inside / load<V>(&t.h[r]);
  V f_d = zero, loss_d = zero;  // normal damping, > 0 while approaching
  if constexpr (Damping) {
    const V m = min_of(load<V>(&c.m[a][r]), load<V>(&c.m[e][r]));
    const V v_n = vrx * nx + vry * ny;
    V root = k_n * m;
    for (int i = 0; i < kWidth<V>; ++i) root[i] = __builtin_sqrt(root[i]);
    f_d = max_of(rp.damping * 2.0 * root * v_n, -f_ab);
    loss_d = f_d * v_n * rp.dt;
  }
  V f_t = zero, loss_f = zero, spring = spring_in;
  if constexpr (Friction) {
    const V trial = spring - k_n * (vrx * tx + vry * ty) * rp.dt;
    const V cap = load<V>(&b.mu[r]) * (f_ab + f_d);
    f_t = clamp_to(trial, -cap, cap);
    spring = f_t;
    // Clipped: the slip beyond the spring's is plastic (return mapping).
    loss_f = (f_t != trial) ? f_t * (trial - f_t) / k_n : zero;
  }
  // Contactor: potential force at A, B plus the point force (F_t t - F_d n)
  // at xi. Target: the opposite of their sum at the same point, shared by
  // its barycentric coordinates there.
  const V px = f_t * tx - f_d * nx, py = f_t * ty - f_d * ny;
  fc[2 * a] = hit ? fc[2 * a] + (-f_a * nx + (1 - xi) * px) : fc[2 * a];
  fc[2 * a + 1] = hit ? fc[2 * a + 1] + (-f_a * ny + (1 - xi) * py) : fc[2 * a + 1];
  fc[2 * e] = hit ? fc[2 * e] + (-f_b * nx + xi * px) : fc[2 * e];
  fc[2 * e + 1] = hit ? fc[2 * e + 1] + (-f_b * ny + xi * py) : fc[2 * e + 1];
  const V gx = f_ab * nx - px, gy = f_ab * ny - py;
  ft[0] = hit ? ft[0] + lc.l0 * gx : ft[0];
  ft[1] = hit ? ft[1] + lc.l0 * gy : ft[1];
  ft[2] = hit ? ft[2] + lc.l1 * gx : ft[2];
  ft[3] = hit ? ft[3] + lc.l1 * gy : ft[3];
  ft[4] = hit ? ft[4] + lc.l2 * gx : ft[4];
  ft[5] = hit ? ft[5] + lc.l2 * gy : ft[5];
  // Springs: set where touching, reset where not, kept for a skipped role.
  store(&b.spring[row][r], hit ? spring : (valid ? zero : spring_in));
  store(&b.loss_friction[row][r], hit ? loss_f : zero);
  store(&b.loss_damping[row][r], hit ? loss_d : zero);
  return hit;
}

/// Corner v of contactor c in target t's barycentric coordinates (lanes
/// from r): lambda_i vanishes at target corner i + 1 and grows with its
/// gradient.
template <class V>
LANE_INLINE Coords<V> corner_coords(const TriLanes& c, const TriLanes& t, int r, int v) {
  const V px = load<V>(&c.x[v][r]), py = load<V>(&c.y[v][r]);
  auto l = [&](int i, int j) {
    return load<V>(&t.gx[i][r]) * (px - load<V>(&t.x[j][r])) +
           load<V>(&t.gy[i][r]) * (py - load<V>(&t.y[j][r]));
  };
  return {l(0, 1), l(1, 2), l(2, 0)};
}

/// Contactor c's three edges against target t (role `role`); returns where
/// some edge touches.
template <class V, bool Damping, bool Friction>
LANE_INLINE Mask<V> role_lanes(PairBatch& b, int r, const TriLanes& c, const TriLanes& t, int role,
                               V* fc, V* ft, const RoleParams& rp) {
  const Mask<V> valid = load<V>(&t.two_a[r]) > V{};
  const Coords<V> l0 = corner_coords<V>(c, t, r, 0), l1 = corner_coords<V>(c, t, r, 1),
                  l2 = corner_coords<V>(c, t, r, 2);
  const int row = 3 * role;
  const Mask<V> h0 =
      edge_lanes<V, Damping, Friction>(b, r, c, t, 0, 0, 1, l0, l1, valid, row, fc, ft, rp);
  const Mask<V> h1 =
      edge_lanes<V, Damping, Friction>(b, r, c, t, 1, 1, 2, l1, l2, valid, row + 1, fc, ft, rp);
  const Mask<V> h2 =
      edge_lanes<V, Damping, Friction>(b, r, c, t, 2, 2, 0, l2, l0, valid, row + 2, fc, ft, rp);
  return h0 | h1 | h2;
}

/// The batch, W lanes at a time (lanes past n compute on whatever the batch
/// holds there and are never read).
template <class V, bool Damping, bool Friction>
LANE_INLINE void roles_loop(PairBatch& b, int n, const RoleParams& rp) {
  for (int r = 0; r < n; r += kWidth<V>) {
    V f[12];
    for (int i = 0; i < 12; ++i) f[i] = V{};
    const Mask<V> t0 = role_lanes<V, Damping, Friction>(b, r, b.tri[0], b.tri[1], 0, f, f + 6, rp);
    const Mask<V> t1 = role_lanes<V, Damping, Friction>(b, r, b.tri[1], b.tri[0], 1, f + 6, f, rp);
    for (int i = 0; i < 12; ++i) store(&b.force[i][r], f[i]);
    store(&b.touching[r], (t0 | t1) ? all<V>(1.0) : V{});
  }
}

/// The loop for the step's settings (no branch on them inside it).
template <class V>
LANE_INLINE void roles_body(PairBatch& b, int n, const RoleParams& rp) {
  const bool damping = rp.damping > 0.0;
  if (damping && rp.friction)
    roles_loop<V, true, true>(b, n, rp);
  else if (damping)
    roles_loop<V, true, false>(b, n, rp);
  else if (rp.friction)
    roles_loop<V, false, true>(b, n, rp);
  else
    roles_loop<V, false, false>(b, n, rp);
}
