// The narrow phase's kernel (contact_roles.cpp), written once for any
// vector width. No include guard on purpose: contact_roles.cpp includes it
// once per instruction set, each time inside its own namespace and
// `#pragma GCC target` region, so that every helper is compiled for the
// same instruction set as the loop that inlines it (GCC lowers vector
// operations per function, by that function's own target).
//
// Every lane evaluates every step of the scalar algorithm and keeps or
// drops each result by a select:
//  - clipping: the part [lo, hi] of the edge where all three barycentric
//    coordinates lambda_i of the target are >= 0 (empty: no hit);
//  - breakpoints: where two coordinates cross strictly inside (lo, hi); a
//    crossing that does not count is replaced by lo, which after sorting
//    only adds segments of zero width (+0 to both integrals, exactly);
//  - phi = 3 max(0, min lambda) at the five points, and the exact integrals
//    i0 = int phi, i1 = int phi xi segment by segment;
//  - the force at A, B and at the centre xi = i1 / i0, friction and damping.
// The selects are written as the standard library's min, max and clamp
// define them ((b < a) ? b : a, ...), so a lane gives exactly the bits of
// the scalar formulas.
//
// Expects: RoleBatch, RoleParams (contact_roles.hpp), ROLE_INLINE, the vector
// types V2, V4, V8.

template <class V>
constexpr int kWidth = sizeof(V) / sizeof(double);

template <class V>
ROLE_INLINE V load(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
ROLE_INLINE void store(double* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}
template <class V>
ROLE_INLINE V all(double x) {
  V v;
  for (int i = 0; i < kWidth<V>; ++i) v[i] = x;
  return v;
}

// The standard library's definitions, lane by lane.
template <class V>
ROLE_INLINE V min_of(V a, V b) {
  return (b < a) ? b : a;
}
template <class V>
ROLE_INLINE V max_of(V a, V b) {
  return (a < b) ? b : a;
}
template <class V>
ROLE_INLINE V clamp_to(V v, V lo, V hi) {
  return (v < lo) ? lo : ((hi < v) ? hi : v);
}

/// The target's three barycentric coordinates at one point of each lane.
template <class V>
struct Coords {
  V l0, l1, l2;
};

/// lambda = la + (lb - la) xi, component by component.
template <class V>
ROLE_INLINE Coords<V> along(Coords<V> la, Coords<V> lb, V xi) {
  return {la.l0 + (lb.l0 - la.l0) * xi, la.l1 + (lb.l1 - la.l1) * xi, la.l2 + (lb.l2 - la.l2) * xi};
}

/// phi = 3 max(0, min_i lambda_i) at xi.
template <class V>
ROLE_INLINE V phi_at(Coords<V> la, Coords<V> lb, V xi) {
  const Coords<V> l = along(la, lb, xi);
  return 3.0 * max_of(V{}, min_of(min_of(l.l0, l.l1), l.l2));
}

/// Breakpoint of two coordinates (ai, aj at xi = 0, bi, bj at 1): where
/// they cross strictly inside (lo, hi), else lo. (A crossing needs exactly
/// one negative difference, so the differences differ and x is defined.)
template <class V>
ROLE_INLINE V crossing(V ai, V aj, V bi, V bj, V lo, V hi) {
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
ROLE_INLINE void clip(V la, V lb, V& lo, V& hi) {
  const V zero{};
  const V x = la / (la - lb);
  const auto out_a = la < zero, out_b = lb < zero;
  lo = out_a ? max_of(lo, x) : lo;
  hi = (out_a & out_b) ? all<V>(-1.0) : ((~out_a & out_b) ? min_of(hi, x) : hi);
}

/// Sorts a <= b.
template <class V>
ROLE_INLINE void order(V& a, V& b) {
  const V lo = min_of(a, b);
  b = max_of(a, b);
  a = lo;
}

/// Adds segment [x0, x1] (phi pa, pb at its ends) to the integrals.
template <class V>
ROLE_INLINE void segment(V x0, V x1, V pa, V pb, V& i0, V& i1) {
  const V w = x1 - x0;
  i0 += 0.5 * w * (pa + pb);
  i1 += w / 6.0 * (pa * (2.0 * x0 + x1) + pb * (x0 + 2.0 * x1));
}

/// Edge k (corners a -> e) of the lanes from r: la, lb are the target's
/// coordinates of corners a and e.
template <class V, bool Damping, bool Friction>
ROLE_INLINE void edge_lanes(RoleBatch& b, int r, int k, int a, int e, Coords<V> la, Coords<V> lb,
                            const RoleParams& rp) {
  const V zero{};
  // Clipping.
  V lo = zero, hi = all<V>(1.0);
  clip(la.l0, lb.l0, lo, hi);
  clip(la.l1, lb.l1, lo, hi);
  clip(la.l2, lb.l2, lo, hi);
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
  // Forces: the potential's at A and B, friction and damping at the centre.
  const V len = load<V>(&b.len[k][r]), tx = load<V>(&b.ex[k][r]), ty = load<V>(&b.ey[k][r]);
  const V nx = ty, ny = -tx;  // outward normal
  const V s = rp.p * len;
  const V f_ab = s * i0, f_b = s * i1, f_a = f_ab - f_b;
  const V xi = i1 / i0;
  const Coords<V> lc = along(la, lb, xi);
  V vtx = zero, vty = zero;
  vtx += lc.l0 * load<V>(&b.tvx[0][r]);
  vty += lc.l0 * load<V>(&b.tvy[0][r]);
  vtx += lc.l1 * load<V>(&b.tvx[1][r]);
  vty += lc.l1 * load<V>(&b.tvy[1][r]);
  vtx += lc.l2 * load<V>(&b.tvx[2][r]);
  vty += lc.l2 * load<V>(&b.tvy[2][r]);
  const V vrx = (1 - xi) * load<V>(&b.cvx[a][r]) + xi * load<V>(&b.cvx[e][r]) - vtx;
  const V vry = (1 - xi) * load<V>(&b.cvy[a][r]) + xi * load<V>(&b.cvy[e][r]) - vty;
  const V k_n = 3.0 * s * inside / load<V>(&b.h[r]);
  V f_d = zero, loss_d = zero;  // normal damping, > 0 while approaching
  if constexpr (Damping) {
    const V m = min_of(load<V>(&b.cm[a][r]), load<V>(&b.cm[e][r]));
    const V v_n = vrx * nx + vry * ny;
    V root = k_n * m;
    for (int i = 0; i < kWidth<V>; ++i) root[i] = __builtin_sqrt(root[i]);
    f_d = max_of(rp.damping * 2.0 * root * v_n, -f_ab);
    loss_d = f_d * v_n * rp.dt;
  }
  V f_t = zero, loss_f = zero, spring = load<V>(&b.spring[k][r]);
  if constexpr (Friction) {
    const V trial = spring - k_n * (vrx * tx + vry * ty) * rp.dt;
    const V cap = load<V>(&b.mu[r]) * (f_ab + f_d);
    f_t = clamp_to(trial, -cap, cap);
    spring = f_t;
    // Clipped: the slip beyond the spring's is plastic (return mapping).
    loss_f = (f_t != trial) ? f_t * (trial - f_t) / k_n : zero;
  }
  const V px = f_t * tx - f_d * nx, py = f_t * ty - f_d * ny;
  store(&b.fc[k][0][r], -f_a * nx + (1 - xi) * px);
  store(&b.fc[k][1][r], -f_a * ny + (1 - xi) * py);
  store(&b.fc[k][2][r], -f_b * nx + xi * px);
  store(&b.fc[k][3][r], -f_b * ny + xi * py);
  const V gx = f_ab * nx - px, gy = f_ab * ny - py;
  store(&b.ft[k][0][r], lc.l0 * gx);
  store(&b.ft[k][1][r], lc.l0 * gy);
  store(&b.ft[k][2][r], lc.l1 * gx);
  store(&b.ft[k][3][r], lc.l1 * gy);
  store(&b.ft[k][4][r], lc.l2 * gx);
  store(&b.ft[k][5][r], lc.l2 * gy);
  // A hit: a non-empty inside part with a positive integral.
  const auto hit = (hi > lo) & (i0 > zero);
  store(&b.hit[k][r], hit ? all<V>(1.0) : zero);
  store(&b.spring[k][r], hit ? spring : zero);
  store(&b.loss_friction[k][r], loss_f);
  store(&b.loss_damping[k][r], loss_d);
}

/// Contactor corner v of the lanes from r in the target's barycentric
/// coordinates: lambda_i vanishes at target corner i + 1 and grows with its
/// gradient.
template <class V>
ROLE_INLINE Coords<V> corner_coords(const RoleBatch& b, int r, int v) {
  const V px = load<V>(&b.cx[v][r]), py = load<V>(&b.cy[v][r]);
  auto l = [&](int i, int j) {
    return load<V>(&b.gx[i][r]) * (px - load<V>(&b.tx[j][r])) +
           load<V>(&b.gy[i][r]) * (py - load<V>(&b.ty[j][r]));
  };
  return {l(0, 1), l(1, 2), l(2, 0)};
}

/// The batch, W lanes at a time (lanes past n compute on whatever the batch
/// holds there and are never read).
template <class V, bool Damping, bool Friction>
ROLE_INLINE void roles_loop(RoleBatch& b, int n, const RoleParams& rp) {
  for (int r = 0; r < n; r += kWidth<V>) {
    const Coords<V> l0 = corner_coords<V>(b, r, 0), l1 = corner_coords<V>(b, r, 1),
                    l2 = corner_coords<V>(b, r, 2);
    edge_lanes<V, Damping, Friction>(b, r, 0, 0, 1, l0, l1, rp);
    edge_lanes<V, Damping, Friction>(b, r, 1, 1, 2, l1, l2, rp);
    edge_lanes<V, Damping, Friction>(b, r, 2, 2, 0, l2, l0, rp);
  }
}

/// The loop for the step's settings (no branch on them inside it).
template <class V>
ROLE_INLINE void roles_body(RoleBatch& b, int n, const RoleParams& rp) {
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
