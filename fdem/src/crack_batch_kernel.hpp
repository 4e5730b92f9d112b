// run_crack_batch's kernel (crack_batch.cpp), written once for any vector
// width and included once per instruction set (isa_regions.hpp explains
// why). It is crack_element() (crack_elements.cpp) for a rock element
// with rock_point() (crack_law.hpp) at its points' damage histories, every
// branch a select; `grows` marks lanes where accumulate_damage would raise
// a history (a or b > 0 and sqrt(a^2 + b^2) above it). The softening z(D)
// is the scalar table look-up, lane by lane. kScaled: each lane's strength
// terms are its factor's (scaled_strength_terms, as the scalar loop's
// scale_crack_strength); otherwise k's own, broadcast once.
//
// Expects: CrackBatch, CrackConstants (crack_batch.hpp), the vector types
// V2, V4, V8 (isa_regions.hpp).

#include "vector_lanes.hpp"

/// pre_peak: (2 - x) x below the peak, 1 from x = 1 on.
template <class V>
LANE_INLINE V pre_peak_of(V x) {
  return (x >= 1.0) ? all<V>(1.0) : (2.0 - x) * x;
}

/// rock_point at the history `damage` where it does not grow: sigma, tau,
/// and whether it would grow.
template <class V>
LANE_INLINE void rock_point_lanes(const CrackConstants& k, const StrengthTerms<V>& st, V o, V s,
                                  V h, V inv_h, V damage, V& sigma, V& tau, Mask<V>& grows) {
  const V zero{};
  const Mask<V> closed = o < zero;
  const V sigma_c = closed ? k.pn * o * inv_h : zero;
  const V fs = st.c - sigma_c * k.tan_phi;
  V inv_fs = 1.0 / fs;
  inv_fs = closed ? inv_fs : st.inv_c;
  const V op = h * st.op_per_h;
  const V sp = h * fs * k.two_over_pt;
  const V abs_s = abs_of(s);
  const V a = (o > op) ? (o - op) * st.inv_open_range : zero;
  const V b = (abs_s > sp) ? (abs_s - sp) * fs * k.inv_slip_energy : zero;
  // Only registers with an excursion need its size, only softened ones z.
  const Mask<V> excursion = (a > zero) | (b > zero);
  if (any_lane(excursion)) {
    V trial = a * a + b * b;
    for (int i = 0; i < kWidth<V>; ++i) trial[i] = __builtin_sqrt(trial[i]);
    // A history at 1 stays there (accumulate_damage caps at 1).
    grows = grows | (excursion & (trial > damage) & (damage < 1.0));
  }
  V z = all<V>(1.0);
  const Mask<V> softened = damage > zero;
  if (any_lane(softened)) {
    const double* table = softening_table();
    V table_z;
    // Lanes at 0 (or not a number) look up 0, not a stray index.
    for (int i = 0; i < kWidth<V>; ++i)
      table_z[i] = softening_z(table, damage[i] > 0.0 ? damage[i] : 0.0);
    z = softened ? table_z : z;
  }
  sigma = closed ? sigma_c : pre_peak_of(o * inv_h * st.h_per_op) * z * st.ft;
  tau = copysign_of(pre_peak_of(abs_s * inv_h * k.half_pt * inv_fs) * z * fs, s);
}

/// scaled_strength_terms (crack_law.hpp) for a register of factors f: the
/// same operations, compiled here inside the instruction set's region.
template <class V>
LANE_INLINE StrengthTerms<V> scaled_strength_lanes(const CrackConstants& k, V f) {
  return {k.ft * f, k.c * f, k.inv_c / f, k.op_per_h * f, k.h_per_op / f, k.inv_open_range * f};
}

template <class V, bool kScaled>
LANE_INLINE void crack_loop(CrackBatch& b, int n, const CrackConstants& k) {
  const StrengthTerms<V> material{all<V>(k.ft),       all<V>(k.c),        all<V>(k.inv_c),
                                  all<V>(k.op_per_h), all<V>(k.h_per_op), all<V>(k.inv_open_range)};
  for (int r = 0; r < n; r += kWidth<V>) {
    const StrengthTerms<V> st =
        kScaled ? scaled_strength_lanes(k, load<V>(&b.strength[r])) : material;
    const V x0 = load<V>(&b.x[0][r]), y0 = load<V>(&b.y[0][r]);
    const V x1 = load<V>(&b.x[1][r]), y1 = load<V>(&b.y[1][r]);
    const V x2 = load<V>(&b.x[2][r]), y2 = load<V>(&b.y[2][r]);
    const V x3 = load<V>(&b.x[3][r]), y3 = load<V>(&b.y[3][r]);
    const V tx = 0.5 * ((x1 + x2) - (x0 + x3)), ty = 0.5 * ((y1 + y2) - (y0 + y3));
    V h = tx * tx + ty * ty;
    for (int i = 0; i < kWidth<V>; ++i) h[i] = __builtin_sqrt(h[i]);
    const V inv_h = 1.0 / h;
    const V ex = tx * inv_h, ey = ty * inv_h;
    const V nx = -ey, ny = ex;
    const V d0x = x0 - x3, d0y = y0 - y3, d1x = x1 - x2, d1y = y1 - y2;
    const V o0 = d0x * nx + d0y * ny, s0 = d0x * ex + d0y * ey;
    const V o1 = d1x * nx + d1y * ny, s1 = d1x * ex + d1y * ey;
    V o[3] = {o0, 0.5 * (o0 + o1), o1}, s[3] = {s0, 0.5 * (s0 + s1), s1};
    for (int i = 0; i < 3; ++i) {
      o[i] -= load<V>(&b.off_o[i][r]);
      s[i] -= load<V>(&b.off_s[i][r]);
    }
    V sigma[3], tau[3];
    Mask<V> grows{};
    for (int i = 0; i < 3; ++i)
      rock_point_lanes(k, st, o[i], s[i], h, inv_h, load<V>(&b.damage[i][r]), sigma[i], tau[i],
                       grows);
    const V w_end = h / 6.0, w_mid = h / 3.0;
    const V sn0 = w_end * sigma[0] + w_mid * sigma[1], st0 = w_end * tau[0] + w_mid * tau[1];
    const V sn1 = w_end * sigma[2] + w_mid * sigma[1], st1 = w_end * tau[2] + w_mid * tau[1];
    const V f0x = -(st0 * ex + sn0 * nx), f0y = -(st0 * ey + sn0 * ny);
    const V f1x = -(st1 * ex + sn1 * nx), f1y = -(st1 * ey + sn1 * ny);
    store(&b.out[0][r], f0x);
    store(&b.out[1][r], f0y);
    store(&b.out[2][r], f1x);
    store(&b.out[3][r], f1y);
    store(&b.out[4][r], -f1x);
    store(&b.out[5][r], -f1y);
    store(&b.out[6][r], -f0x);
    store(&b.out[7][r], -f0y);
    store(&b.grows[r], grows ? all<V>(1.0) : V{});
  }
}
