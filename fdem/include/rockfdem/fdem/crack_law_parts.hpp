// What every crack (cohesive) law is built from: the per-material constants
// record, the strength terms heterogeneity scales, the result of one
// integration point, and the few operations a law needs written once for a
// plain double and for a register of doubles (a GCC vector: V2, V4, V8 of
// isa_regions.hpp), so that each law is one template that both the scalar
// crack loop and the batch kernel run (crack_law.hpp).
//
// Conventions (reference sec. 2): opening o > 0 separates the faces, slip s
// is signed along the element; tension positive. Each law turns (o, s, h)
// plus the point's damage history D into a normal stress sigma and a shear
// stress tau, and reports the normalised softening excursions
//   a = (o - op)/(or - op) >= 0,  b = (|s| - sp)/(sr - sp) >= 0,
// from which the mixed-mode damage D = sqrt(a^2 + b^2) (seed eq. 10) and the
// failure mode at breakage follow.
//
// Same bits on both paths: a lane performs the scalar formulas' IEEE
// operations in their order; a select takes the place of each branch.
// Everything here is always inlined into its caller, which is compiled for
// its own instruction set (GCC lowers arithmetic and selects after
// inlining; see the rule on comparisons below), so the ABI GCC warns about
// for vector arguments never applies (crack_batch.cpp: -Wno-psabi).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "rockfdem/fdem/model_input.hpp"

#define ROCKFDEM_LAW_INLINE inline __attribute__((always_inline))

namespace rockfdem::fdem {

/// Per-material constants of a crack law, derived once from a Material
/// (make_crack_constants). The reciprocals spare the crack loop its
/// divisions. What ft, fu, c and tan_phi hold is the law's to say.
struct CrackConstants {
  CrackLaw law = CrackLaw::kRock;
  double ft = 0;           ///< rock: tensile strength; bolt: yield strength sigma_y
  double fu = 0;           ///< bolt: ultimate strength sigma_u
  double c = 0;            ///< rock: cohesion; bolt: shear yield tau_y
  double tan_phi = 0;      ///< rock, joint: tan(friction angle)
  double tan_phi_r = 0;    ///< joint: tan(residual friction angle)
  double pn = 0, pt = 0;   ///< normal and tangential penalties [Pa]
  double open_range = 0;   ///< or - op [m]
  double slip_energy = 0;  ///< sr - sp = slip_energy / fs [Pa m]
  // Derived.
  double op_per_h = 0;         ///< op / h = 2 ft / pn
  double h_per_op = 0;         ///< pn / (2 ft)
  double half_pt = 0;          ///< pt / 2 (h / sp = half_pt / fs)
  double two_over_pt = 0;      ///< 2 / pt (sp = 2 h fs / pt)
  double inv_c = 0;            ///< 1 / c
  double inv_open_range = 0;   ///< 1 / (or - op)
  double inv_slip_energy = 0;  ///< 1 / slip_energy
  bool breaks = true;          ///< whether the element breaks when two points reach D = 1
  // Joint with a Barton-Bandis peak (crack_law_joint.hpp).
  bool barton_bandis = false;
  double phi_r = 0;          ///< residual (basic) friction angle [rad]
  double jrc_rad = 0;        ///< JRC pi / 180: the roughness angle per decade of JCS / sigma_n
  double jcs = 0;            ///< joint wall compressive strength [Pa]
  double max_angle_rad = 0;  ///< cap of the total friction angle [rad]
};

/// Range of a crack element's strength factor (Material::weibull_modulus):
/// a Weibull draw outside it is clamped, so that no element is without
/// strength and none is far stronger than any laboratory scatter suggests.
constexpr double kMinStrengthFactor = 0.05;
constexpr double kMaxStrengthFactor = 5.0;

/// The terms a strength factor f scales: ft and c by f, and with them (the
/// penalties and fracture energies unchanged) op / h = 2 ft / pn, h / op,
/// 1 / c and 1 / (or - op) = I ft / GfI. (sr - sp = (GfII / I) / fs follows
/// from the scaled fs by itself.) T is double or a register of doubles: the
/// batch kernel performs the same operations on a register of factors, so
/// that both paths compute the same bits; f = 1 leaves every term's bits as
/// they are. A law that admits heterogeneity reads these terms from here,
/// never from CrackConstants.
template <class T>
struct StrengthTerms {
  T ft, c, inv_c, op_per_h, h_per_op, inv_open_range;
};

/// The material's own terms (factor 1).
inline StrengthTerms<double> material_terms(const CrackConstants& k) {
  return {k.ft, k.c, k.inv_c, k.op_per_h, k.h_per_op, k.inv_open_range};
}

/// The terms of an element whose strengths are f times its material's;
/// F is double or a register of factors.
template <class F>
ROCKFDEM_LAW_INLINE StrengthTerms<F> scaled_strength_terms(const CrackConstants& k, const F& f) {
  return {k.ft * f, k.c * f, k.inv_c / f, k.op_per_h * f, k.h_per_op / f, k.inv_open_range * f};
}

/// Constants of one crack element whose strengths are f times its
/// material's (heterogeneity); everything a law reads is consistent.
inline CrackConstants scale_crack_strength(const CrackConstants& k, double f) {
  CrackConstants s = k;
  const StrengthTerms<double> t = scaled_strength_terms(k, f);
  s.ft = t.ft;
  s.c = t.c;
  s.inv_c = t.inv_c;
  s.op_per_h = t.op_per_h;
  s.h_per_op = t.h_per_op;
  s.inv_open_range = t.inv_open_range;
  s.open_range = k.open_range / f;
  return s;
}

/// Result of one integration point. No default initialisers: the laws set
/// every field, and zeroing three of these per element cost 4% of the loop.
template <class T>
struct CrackPointOf {
  T sigma;  ///< normal stress [Pa], tension positive
  T tau;    ///< shear stress [Pa], sign of the slip
  T a;      ///< normalised opening excursion (o - op)/(or - op), >= 0
  T b;      ///< normalised slip excursion (|s| - sp)/(sr - sp), >= 0
};
using CrackPoint = CrackPointOf<double>;

/// The operations a law needs on a double or a register of doubles: the
/// standard library's for a double, lane by lane (same bits) for a
/// register. Arithmetic and `cond ? a : b` need nothing: for a register
/// they act lane by lane and the comparison selects.
///
/// One rule for law code that runs on registers: a comparison appears only
/// as the condition of `?:`, never stored or combined as a mask value. The
/// laws are compiled outside the kernels' instruction-set regions
/// (isa_regions.hpp) and inlined into them; GCC lowers arithmetic and
/// selects in the function they end up in, but a comparison kept as a mask
/// value is lowered for the instruction set of the place it is written
/// (SSE2: lane by lane, several times slower in the AVX-512 kernel). Reductions over lanes
/// go through any_positive.
namespace lanes {

template <class T>
inline constexpr bool kScalar = std::is_same_v<T, double>;

template <class T>
inline constexpr int kWidth = sizeof(T) / sizeof(double);

template <class T>
ROCKFDEM_LAW_INLINE T splat(double x) {
  if constexpr (kScalar<T>) {
    return x;
  } else {
    T v;
    for (int i = 0; i < kWidth<T>; ++i) v[i] = x;
    return v;
  }
}

/// The integer lanes of a register's bit patterns.
template <class T>
using Bits = decltype(T{} < T{});

/// Whether some lane of x is > 0 (not a number: no).
template <class T>
ROCKFDEM_LAW_INLINE bool any_positive(T x) {
  if constexpr (kScalar<T>) {
    return x > 0.0;
  } else {
    const T one = splat<T>(1.0), zero{};
    const auto set = (Bits<T>)((x > zero) ? one : zero);  // a select, then its bits
    long any = 0;
    for (int i = 0; i < kWidth<T>; ++i) any |= set[i];
    return any != 0;
  }
}

template <class T>
ROCKFDEM_LAW_INLINE T sqrt(T x) {
  if constexpr (kScalar<T>) {
    return std::sqrt(x);
  } else {
    for (int i = 0; i < kWidth<T>; ++i) x[i] = __builtin_sqrt(x[i]);
    return x;
  }
}

template <class T>
ROCKFDEM_LAW_INLINE T abs(T x) {
  if constexpr (kScalar<T>) {
    return std::fabs(x);
  } else {
    const Bits<T> sign = (Bits<T>)splat<T>(-0.0);
    return (T)((Bits<T>)x & ~sign);
  }
}

/// f(x) of a double, or f of each lane of a register (library functions
/// without a vector form: the same bits as the scalar call).
template <class T, class F>
ROCKFDEM_LAW_INLINE T each_lane(const T& x, F f) {
  if constexpr (kScalar<T>) {
    return f(x);
  } else {
    T y;
    for (int i = 0; i < kWidth<T>; ++i) y[i] = f(x[i]);
    return y;
  }
}

template <class T>
ROCKFDEM_LAW_INLINE T log10(const T& x) {
  return each_lane(x, [](double v) { return std::log10(v); });
}

template <class T>
ROCKFDEM_LAW_INLINE T tan(const T& x) {
  return each_lane(x, [](double v) { return std::tan(v); });
}

/// |m| with the sign of s.
template <class T>
ROCKFDEM_LAW_INLINE T copysign(T m, T s) {
  if constexpr (kScalar<T>) {
    return std::copysign(m, s);
  } else {
    const Bits<T> sign = (Bits<T>)splat<T>(-0.0);
    return (T)(((Bits<T>)m & ~sign) | ((Bits<T>)s & sign));
  }
}

}  // namespace lanes

/// Hardening branch shared by the laws: (2x - x^2) below the peak, 1 beyond.
template <class T>
ROCKFDEM_LAW_INLINE T pre_peak(T x) {
  return (x >= 1.0) ? lanes::splat<T>(1.0) : (2.0 - x) * x;
}

/// Raises the point's damage history to the mixed-mode damage
/// sqrt(a^2 + b^2) (seed eq. 10), capped at 1; never lowers it. Only a
/// point (a register) with an excursion pays for the root. (In a register,
/// a lane without excursion has a = b = 0, so its root 0 raises nothing.)
template <class T>
ROCKFDEM_LAW_INLINE void raise_damage(T a, T b, T& damage) {
  if constexpr (lanes::kScalar<T>) {
    if (a > 0.0 || b > 0.0) {
      const double trial = std::sqrt(a * a + b * b);
      if (trial > damage) damage = std::min(trial, 1.0);
    }
  } else {
    const T zero{};
    if (lanes::any_positive((a > zero) ? a : b)) {
      const T trial = lanes::sqrt(a * a + b * b);
      const T one = lanes::splat<T>(1.0);
      const T capped = (one < trial) ? one : trial;  // std::min(trial, 1.0)
      damage = (trial > damage) ? capped : damage;
    }
  }
}

}  // namespace rockfdem::fdem
