// The rock crack law (reference sec. 2): Mohr-Coulomb strength,
// Evans-Marathe softening, penalty in compression. Grout and the lining
// interface bond are materials of this law with their own parameters.
//   op = 2 h ft / pn, sp = 2 h fs / pt, or - op = GfI / (I ft),
//   sr - sp = GfII / (I fs), I = integral of z = 0.3863,
//   fs = c - sigma tan(phi) in compression (sigma < 0), c in tension.
// The only law with strength heterogeneity (its strength terms come from
// StrengthTerms).
#pragma once

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/crack_law_parts.hpp"

namespace rockfdem::fdem {

/// Evans-Marathe softening curve z(D), z(0) = 1, z(1) = 0 (a = 0.63,
/// b = 1.8, c = 6).
inline double evans_marathe_z(double d) {
  constexpr double a = 0.63, b = 1.8;
  constexpr double k1 = (a + b - 1.0) / (a + b);
  constexpr double k2 = (a + 6.0 * b) / ((a + b) * (1.0 - a - b));
  const double r = 1.0 - d;
  const double r2 = r * r;
  return (1.0 - k1 * std::exp(d * k2)) * (a * r + b * r2 * r2 * r2);
}

/// z(D) from a 4096-interval table with linear interpolation: the crack loop
/// evaluates it at every damaged point, and exp() there cost more than the
/// rest of the law. Exact at D = 0 and 1; relative error below 1e-6 elsewhere
/// (tested), far below anything the damage history resolves.
constexpr int kSofteningIntervals = 4096;

/// The table of softening_z: z at D = i / kSofteningIntervals, i = 0 .. n,
/// and a guard entry 0 for D = 1 (built once).
inline const double* softening_table() {
  constexpr int n = kSofteningIntervals;
  static const auto table = [] {
    std::array<double, n + 2> t{};
    for (int i = 0; i <= n; ++i) t[i] = evans_marathe_z(double(i) / n);
    t[n + 1] = 0.0;  // guard for d == 1
    return t;
  }();
  return table.data();
}

/// softening_z with the table at hand (loops that call it often).
inline double softening_z(const double* table, double d) {
  const double x = d * kSofteningIntervals;
  const int i = static_cast<int>(x);
  const double f = x - i;
  return table[i] + f * (table[i + 1] - table[i]);
}

inline double softening_z(double d) { return softening_z(softening_table(), d); }

/// Integral of z(D) over [0, 1] (about 0.3863), by composite Simpson with
/// 2048 intervals, computed once. The softening ranges are chosen from it so
/// that a crack dissipates exactly its fracture energy:
///   or - op = GfI / (I ft) = 2.589 GfI / ft  (not the common 3 GfI / ft,
///   which dissipates 1.16 GfI).
inline double rock_softening_integral() {
  static const double value = [] {
    constexpr int n = 2048;
    double sum = evans_marathe_z(0.0) + evans_marathe_z(1.0);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * evans_marathe_z(double(i) / n);
    return sum / (3.0 * n);
  }();
  return value;
}

struct RockLaw {
  static constexpr CrackLaw kId = CrackLaw::kRock;
  static constexpr const char* kName = "rock";
  static constexpr bool kHeterogeneous = true;  ///< reads StrengthTerms
  static constexpr bool kBatched = true;        ///< most elements: the crack loop's batch pass

  /// The law's entries of k from m (the penalties are set already).
  static void set_constants(const Material& m, CrackConstants& k) {
    const double integral = rock_softening_integral();
    k.ft = m.tensile_strength;
    k.c = m.cohesion;
    k.tan_phi = std::tan(m.friction_deg * kPi / 180.0);
    k.open_range = m.gf_I / (integral * m.tensile_strength);
    k.slip_energy = m.gf_II / integral;
  }

  /// What is wrong with m's parameters for this law ("": nothing).
  static std::string input_problem(const Material& m) {
    if (!(m.tensile_strength > 0 && m.cohesion > 0))
      return "tensile strength and cohesion must be > 0 for the rock crack law";
    if (!(m.friction_deg >= 0 && m.friction_deg < 90)) {
      std::ostringstream s;
      s << "friction angle " << m.friction_deg << " must lie in [0, 90) degrees";
      return s.str();
    }
    return "";
  }

  /// z(D), 1 at D = 0; a register looks up its softened lanes only (lanes
  /// at 0, or not a number, look up 0, not a stray index).
  template <class T>
  static ROCKFDEM_LAW_INLINE T softening(T damage) {
    if constexpr (lanes::kScalar<T>) {
      return damage > 0.0 ? softening_z(damage) : 1.0;
    } else {
      T z = lanes::splat<T>(1.0);
      if (lanes::any_positive(damage)) {
        const double* table = softening_table();
        T table_z;
        for (int i = 0; i < lanes::kWidth<T>; ++i)
          table_z[i] = softening_z(table, damage[i] > 0.0 ? damage[i] : 0.0);
        z = (damage > 0.0) ? table_z : z;
      }
      return z;
    }
  }

  /// One integration point: raises `damage` (the point's history) and
  /// returns the stresses at the raised history. h is the element length,
  /// inv_h = 1 / h; st the element's strength terms.
  template <class T>
  static ROCKFDEM_LAW_INLINE CrackPointOf<T> point(const CrackConstants& k,
                                                   const StrengthTerms<T>& st, const T& o,
                                                   const T& s, const T& h, const T& inv_h,
                                                   T& damage) {
    const T zero{};
    const T sigma_c = (o < zero) ? k.pn * o * inv_h : zero;  // penalty, unaffected by damage
    const T fs = st.c - sigma_c * k.tan_phi;                 // Mohr-Coulomb, tension positive
    const T inv_fs = (o < zero) ? 1.0 / fs : st.inv_c;
    const T op = h * st.op_per_h;
    const T sp = h * fs * k.two_over_pt;
    const T abs_s = lanes::abs(s);
    CrackPointOf<T> p;
    p.a = (o > op) ? (o - op) * st.inv_open_range : zero;
    p.b = (abs_s > sp) ? (abs_s - sp) * fs * k.inv_slip_energy : zero;
    raise_damage(p.a, p.b, damage);
    const T z = softening(damage);
    p.sigma = (o < zero) ? sigma_c : pre_peak(o * inv_h * st.h_per_op) * z * st.ft;
    p.tau = lanes::copysign(pre_peak(abs_s * inv_h * k.half_pt * inv_fs) * z * fs, s);
    return p;
  }

  /// Shear strength at the total normal stress sigma (Mohr-Coulomb in
  /// compression).
  static double shear_strength(const CrackConstants& k, double sigma) {
    return sigma < 0.0 ? k.c - sigma * k.tan_phi : k.c;
  }

  /// Factors of the normal and shear pre-peak curves at a fixed damage D
  /// (crack_point_potential): z(D) for both.
  static void damage_factors(const CrackConstants&, double damage, double& g_n, double& g_s) {
    g_n = g_s = softening(damage);
  }
};

}  // namespace rockfdem::fdem
