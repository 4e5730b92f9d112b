// run_crack_batch's kernel (crack_batch.cpp), written once for any vector
// width and included once per instruction set (see contact_roles_kernel.hpp
// for why). It is crack_element() (crack_elements.cpp) for a rock element
// with rock_point() (crack_law.hpp) at its points' damage histories, every
// branch a select; `grows` marks lanes where accumulate_damage would raise
// a history (a or b > 0 and sqrt(a^2 + b^2) above it). The softening z(D)
// is the scalar table look-up, lane by lane.
//
// Expects: CrackBatch, CrackConstants, ROLE_INLINE, the vector types.

template <class V>
constexpr int kCrackWidth = sizeof(V) / sizeof(double);

template <class V>
ROLE_INLINE V cload(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
ROLE_INLINE void cstore(double* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}
template <class V>
ROLE_INLINE V splat(double x) {
  V v;
  for (int i = 0; i < kCrackWidth<V>; ++i) v[i] = x;
  return v;
}

/// The integer lanes of a double vector, for sign-bit operations.
template <class V>
using Bits = decltype(V{} < V{});

/// |x| and copysign(m, s) by the sign bit, as the library defines them.
template <class V>
ROLE_INLINE V abs_of(V x) {
  const Bits<V> sign = (Bits<V>)splat<V>(-0.0);
  return (V)((Bits<V>)x & ~sign);
}
template <class V>
ROLE_INLINE V copysign_of(V m, V s) {
  const Bits<V> sign = (Bits<V>)splat<V>(-0.0);
  return (V)(((Bits<V>)m & ~sign) | ((Bits<V>)s & sign));
}

/// Whether any lane of m is set.
template <class M>
ROLE_INLINE bool any_set(M m) {
  long set = 0;
  for (int i = 0; i < static_cast<int>(sizeof(M) / sizeof(m[0])); ++i) set |= m[i];
  return set != 0;
}

/// pre_peak: (2 - x) x below the peak, 1 from x = 1 on.
template <class V>
ROLE_INLINE V pre_peak_of(V x) {
  return (x >= 1.0) ? splat<V>(1.0) : (2.0 - x) * x;
}

/// rock_point at the history `damage` where it does not grow: sigma, tau,
/// and whether it would grow.
template <class V>
ROLE_INLINE void rock_point_lanes(const CrackConstants& k, V o, V s, V h, V inv_h, V damage,
                                  V& sigma, V& tau, Bits<V>& grows) {
  const V zero{};
  const Bits<V> closed = o < zero;
  const V sigma_c = closed ? k.pn * o * inv_h : zero;
  const V fs = k.c - sigma_c * k.tan_phi;
  V inv_fs = 1.0 / fs;
  inv_fs = closed ? inv_fs : splat<V>(k.inv_c);
  const V op = h * k.op_per_h;
  const V sp = h * fs * k.two_over_pt;
  const V abs_s = abs_of(s);
  const V a = (o > op) ? (o - op) * k.inv_open_range : zero;
  const V b = (abs_s > sp) ? (abs_s - sp) * fs * k.inv_slip_energy : zero;
  // Only registers with an excursion need its size, only softened ones z.
  const Bits<V> excursion = (a > zero) | (b > zero);
  if (any_set(excursion)) {
    V trial = a * a + b * b;
    for (int i = 0; i < kCrackWidth<V>; ++i) trial[i] = __builtin_sqrt(trial[i]);
    // A history at 1 stays there (accumulate_damage caps at 1).
    grows = grows | (excursion & (trial > damage) & (damage < 1.0));
  }
  V z = splat<V>(1.0);
  const Bits<V> softened = damage > zero;
  if (any_set(softened)) {
    const double* table = softening_table();
    V table_z;
    // Lanes at 0 (or not a number) look up 0, not a stray index.
    for (int i = 0; i < kCrackWidth<V>; ++i)
      table_z[i] = softening_z(table, damage[i] > 0.0 ? damage[i] : 0.0);
    z = softened ? table_z : z;
  }
  sigma = closed ? sigma_c : pre_peak_of(o * inv_h * k.h_per_op) * z * k.ft;
  tau = copysign_of(pre_peak_of(abs_s * inv_h * k.half_pt * inv_fs) * z * fs, s);
}

template <class V>
ROLE_INLINE void crack_loop(CrackBatch& b, int n, const CrackConstants& k) {
  for (int r = 0; r < n; r += kCrackWidth<V>) {
    const V x0 = cload<V>(&b.x[0][r]), y0 = cload<V>(&b.y[0][r]);
    const V x1 = cload<V>(&b.x[1][r]), y1 = cload<V>(&b.y[1][r]);
    const V x2 = cload<V>(&b.x[2][r]), y2 = cload<V>(&b.y[2][r]);
    const V x3 = cload<V>(&b.x[3][r]), y3 = cload<V>(&b.y[3][r]);
    const V tx = 0.5 * ((x1 + x2) - (x0 + x3)), ty = 0.5 * ((y1 + y2) - (y0 + y3));
    V h = tx * tx + ty * ty;
    for (int i = 0; i < kCrackWidth<V>; ++i) h[i] = __builtin_sqrt(h[i]);
    const V inv_h = 1.0 / h;
    const V ex = tx * inv_h, ey = ty * inv_h;
    const V nx = -ey, ny = ex;
    const V d0x = x0 - x3, d0y = y0 - y3, d1x = x1 - x2, d1y = y1 - y2;
    const V o0 = d0x * nx + d0y * ny, s0 = d0x * ex + d0y * ey;
    const V o1 = d1x * nx + d1y * ny, s1 = d1x * ex + d1y * ey;
    V o[3] = {o0, 0.5 * (o0 + o1), o1}, s[3] = {s0, 0.5 * (s0 + s1), s1};
    for (int i = 0; i < 3; ++i) {
      o[i] -= cload<V>(&b.off_o[i][r]);
      s[i] -= cload<V>(&b.off_s[i][r]);
    }
    V sigma[3], tau[3];
    Bits<V> grows{};
    for (int i = 0; i < 3; ++i)
      rock_point_lanes(k, o[i], s[i], h, inv_h, cload<V>(&b.damage[i][r]), sigma[i], tau[i], grows);
    const V w_end = h / 6.0, w_mid = h / 3.0;
    const V sn0 = w_end * sigma[0] + w_mid * sigma[1], st0 = w_end * tau[0] + w_mid * tau[1];
    const V sn1 = w_end * sigma[2] + w_mid * sigma[1], st1 = w_end * tau[2] + w_mid * tau[1];
    const V f0x = -(st0 * ex + sn0 * nx), f0y = -(st0 * ey + sn0 * ny);
    const V f1x = -(st1 * ex + sn1 * nx), f1y = -(st1 * ey + sn1 * ny);
    cstore(&b.out[0][r], f0x);
    cstore(&b.out[1][r], f0y);
    cstore(&b.out[2][r], f1x);
    cstore(&b.out[3][r], f1y);
    cstore(&b.out[4][r], -f1x);
    cstore(&b.out[5][r], -f1y);
    cstore(&b.out[6][r], -f0x);
    cstore(&b.out[7][r], -f0y);
    cstore(&b.grows[r], grows ? splat<V>(1.0) : V{});
  }
}
