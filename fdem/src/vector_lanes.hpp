// Lane helpers of the engine's vector kernels (contact_roles_kernel.hpp,
// crack_batch_kernel.hpp). No include guard on purpose: each kernel
// includes it inside every instruction-set region (isa_regions.hpp), so
// that the helpers are compiled for the same set as the loops that inline
// them. V is a GCC vector of doubles (V2, V4, V8); arithmetic and
// comparisons act lane by lane and `m ? a : b` selects by the mask m.

#define LANE_INLINE inline __attribute__((always_inline))

template <class V>
constexpr int kWidth = sizeof(V) / sizeof(double);

/// A comparison's lane mask (integer lanes of the width of V's).
template <class V>
using Mask = decltype(V{} < V{});

template <class V>
LANE_INLINE V load(const double* p) {
  V v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
LANE_INLINE void store(double* p, V v) {
  __builtin_memcpy(p, &v, sizeof v);
}
template <class V>
LANE_INLINE V all(double x) {
  V v;
  for (int i = 0; i < kWidth<V>; ++i) v[i] = x;
  return v;
}

/// Whether any lane of m is set.
template <class M>
LANE_INLINE bool any_lane(M m) {
  long set = 0;
  for (int i = 0; i < static_cast<int>(sizeof(M) / sizeof(m[0])); ++i) set |= m[i];
  return set != 0;
}

// The standard library's definitions, lane by lane (same bits as std::min,
// std::max, std::clamp, std::fabs, std::copysign).
template <class V>
LANE_INLINE V min_of(V a, V b) {
  return (b < a) ? b : a;
}
template <class V>
LANE_INLINE V max_of(V a, V b) {
  return (a < b) ? b : a;
}
template <class V>
LANE_INLINE V clamp_to(V v, V lo, V hi) {
  return (v < lo) ? lo : ((hi < v) ? hi : v);
}
template <class V>
LANE_INLINE V abs_of(V x) {
  const Mask<V> sign = (Mask<V>)all<V>(-0.0);
  return (V)((Mask<V>)x & ~sign);
}
template <class V>
LANE_INLINE V copysign_of(V m, V s) {
  const Mask<V> sign = (Mask<V>)all<V>(-0.0);
  return (V)(((Mask<V>)m & ~sign) | ((Mask<V>)s & sign));
}
