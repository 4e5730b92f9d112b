// run_crack_batch's kernel (crack_batch.cpp), written once for any vector
// width and any crack law, and included once per instruction set
// (isa_regions.hpp explains why). It is crack_element() (crack_elements.cpp)
// with the law's point() (crack_law.hpp) run on a register of elements: the
// law is the same template the scalar loop runs, so the law is written once.
// `grows` marks lanes where some point's damage history would rise (their
// outputs are discarded and the scalar path redoes them). kScaled: each
// lane's strength terms are its factor's (scaled_strength_terms, as the
// scalar loop's); otherwise k's own, broadcast once.
//
// Expects: CrackBatch, CrackConstants (crack_batch.hpp), the vector types
// V2, V4, V8 (isa_regions.hpp).

#include "vector_lanes.hpp"

template <class V, class Law, bool kScaled>
LANE_INLINE void crack_loop(CrackBatch& b, int n, const CrackConstants& k) {
  const StrengthTerms<V> material{all<V>(k.ft),       all<V>(k.c),        all<V>(k.inv_c),
                                  all<V>(k.op_per_h), all<V>(k.h_per_op), all<V>(k.inv_open_range)};
  for (int r = 0; r < n; r += kWidth<V>) {
    const StrengthTerms<V> st =
        kScaled ? scaled_strength_terms(k, load<V>(&b.strength[r])) : material;
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
    CrackPointOf<V> p[3];
    Mask<V> grows{};
    for (int i = 0; i < 3; ++i) {
      const V before = load<V>(&b.damage[i][r]);
      V damage = before;
      p[i] = Law::point(k, st, o[i], s[i], h, inv_h, damage);
      grows = grows | (damage > before);
    }
    const V w_end = h / 6.0, w_mid = h / 3.0;
    const V sn0 = w_end * p[0].sigma + w_mid * p[1].sigma;
    const V st0 = w_end * p[0].tau + w_mid * p[1].tau;
    const V sn1 = w_end * p[2].sigma + w_mid * p[1].sigma;
    const V st1 = w_end * p[2].tau + w_mid * p[1].tau;
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
