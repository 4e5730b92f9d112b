// The bolt steel crack law (seed eqs. 11-19): below op the rock-law curve up
// to sigma_y, then axial hardening sigma_y + D (sigma_u - sigma_y)
// (f_axial = D) until D = 1; shear up to tau_y, then brittle decay
// f_lateral = (1 - D)^2, whose integral 1/3 makes eq. 16 with eta = 6
// dissipate exactly GfII. Penalty in compression; no strength
// heterogeneity (its strengths come from CrackConstants).
#pragma once

#include <string>

#include "rockfdem/fdem/crack_law_parts.hpp"

namespace rockfdem::fdem {

struct BoltSteelLaw {
  static constexpr CrackLaw kId = CrackLaw::kBoltSteel;
  static constexpr const char* kName = "bolt steel";
  static constexpr bool kHeterogeneous = false;
  /// Few elements (the bolts'): the scalar loop takes them. The batch
  /// kernel can (tested): set true to batch them.
  static constexpr bool kBatched = false;

  /// The law's entries of k from m (the penalties are set already): seed
  /// eqs. 14 and 16 with eta = 6 and tau_u = tau_y.
  static void set_constants(const Material& m, CrackConstants& k) {
    k.ft = m.yield_strength;
    k.fu = m.ultimate_strength;
    k.c = m.shear_yield_strength;
    k.open_range = 2.0 * m.gf_I / (m.yield_strength + m.ultimate_strength);
    k.slip_energy = 6.0 * m.gf_II / 2.0;
  }

  /// What is wrong with m's parameters for this law ("": nothing).
  static std::string input_problem(const Material& m) {
    if (!(m.yield_strength > 0 && m.ultimate_strength >= m.yield_strength &&
          m.shear_yield_strength > 0))
      return "bolt steel needs 0 < yield <= ultimate strength and shear yield > 0";
    return "";
  }

  /// One integration point: raises `damage` (the point's history) and
  /// returns the stresses at the raised history. h is the element length,
  /// inv_h = 1 / h; the strength terms are the material's (k).
  template <class T>
  static ROCKFDEM_LAW_INLINE CrackPointOf<T> point(const CrackConstants& k, const StrengthTerms<T>&,
                                                   const T& o, const T& s, const T& h,
                                                   const T& inv_h, T& damage) {
    const T zero{};
    const T op = h * k.op_per_h;
    const T sp = h * k.c * k.two_over_pt;
    const T abs_s = lanes::abs(s);
    CrackPointOf<T> p;
    p.a = (o > op) ? (o - op) * k.inv_open_range : zero;
    p.b = (abs_s > sp) ? (abs_s - sp) * k.c * k.inv_slip_energy : zero;
    raise_damage(p.a, p.b, damage);
    const T axial = (damage < 1.0) ? k.ft + damage * (k.fu - k.ft) : zero;
    const T lateral = (1.0 - damage) * (1.0 - damage);
    p.sigma = (o < zero) ? k.pn * o * inv_h : pre_peak(o * inv_h * k.h_per_op) * axial;
    p.tau = lanes::copysign(pre_peak(abs_s * inv_h * k.half_pt * k.inv_c) * lateral * k.c, s);
    return p;
  }

  /// Shear strength at any normal stress: tau_y.
  static double shear_strength(const CrackConstants& k, double) { return k.c; }

  /// Factors of the normal and shear pre-peak curves at a fixed damage D
  /// (crack_point_potential): g_n = (sigma_y + D (sigma_u - sigma_y)) /
  /// sigma_y (0 at D = 1), g_s = (1 - D)^2.
  static void damage_factors(const CrackConstants& k, double damage, double& g_n, double& g_s) {
    g_n = damage < 1.0 ? 1.0 + damage * (k.fu - k.ft) / k.ft : 0.0;
    g_s = (1.0 - damage) * (1.0 - damage);
  }
};

}  // namespace rockfdem::fdem
