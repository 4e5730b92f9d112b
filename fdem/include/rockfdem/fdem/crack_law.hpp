// Crack (cohesive) laws evaluated at one integration point of a four-node
// crack element. Header-only and inline because the crack loop calls them
// three times per element per step; a switch on CrackLaw picks the law.
//
// Conventions (reference sec. 2): opening o > 0 separates the faces, slip s
// is signed along the element; tension positive. Each law turns (o, s, h)
// plus the point's damage history D into a normal stress sigma and a shear
// stress tau, and reports the normalised softening excursions
//   a = (o - op)/(or - op) >= 0,  b = (|s| - sp)/(sr - sp) >= 0,
// from which the mixed-mode damage D = sqrt(a^2 + b^2) (seed eq. 10) and the
// failure mode at breakage follow.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/model_input.hpp"

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

/// Per-material constants of a crack law, derived once from a Material.
/// The reciprocals spare the crack loop its divisions.
struct CrackConstants {
  CrackLaw law = CrackLaw::kRock;
  double ft = 0;           ///< rock: tensile strength; bolt: yield strength sigma_y
  double fu = 0;           ///< bolt: ultimate strength sigma_u
  double c = 0;            ///< rock: cohesion; bolt: shear yield tau_y
  double tan_phi = 0;      ///< rock: tan(friction angle)
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
};

/// Derive the law constants of `m` (penalties default to 10 E).
inline CrackConstants make_crack_constants(const Material& m) {
  CrackConstants k;
  k.law = m.crack_law;
  k.pn = m.normal_penalty > 0 ? m.normal_penalty : 10.0 * m.young;
  k.pt = m.tangential_penalty > 0 ? m.tangential_penalty : k.pn;
  if (m.crack_law == CrackLaw::kBoltSteel) {
    // Seed eqs. 14 and 16 with eta = 6 and tau_u = tau_y.
    k.ft = m.yield_strength;
    k.fu = m.ultimate_strength;
    k.c = m.shear_yield_strength;
    k.open_range = 2.0 * m.gf_I / (m.yield_strength + m.ultimate_strength);
    k.slip_energy = 6.0 * m.gf_II / 2.0;
  } else {
    const double integral = rock_softening_integral();
    k.ft = m.tensile_strength;
    k.c = m.cohesion;
    k.tan_phi = std::tan(m.friction_deg * kPi / 180.0);
    k.open_range = m.gf_I / (integral * m.tensile_strength);
    k.slip_energy = m.gf_II / integral;
  }
  k.op_per_h = 2.0 * k.ft / k.pn;
  k.h_per_op = k.pn / (2.0 * k.ft);
  k.half_pt = 0.5 * k.pt;
  k.two_over_pt = 2.0 / k.pt;
  k.inv_c = 1.0 / k.c;
  k.inv_open_range = 1.0 / k.open_range;
  k.inv_slip_energy = 1.0 / k.slip_energy;
  return k;
}

/// Range of a crack element's strength factor (Material::weibull_modulus):
/// a Weibull draw outside it is clamped, so that no element is without
/// strength and none is far stronger than any laboratory scatter suggests.
constexpr double kMinStrengthFactor = 0.05;
constexpr double kMaxStrengthFactor = 5.0;

/// The rock-law terms a strength factor f scales: ft and c by f, and with
/// them (the penalties and fracture energies unchanged) op / h = 2 ft / pn,
/// h / op, 1 / c and 1 / (or - op) = I ft / GfI. (sr - sp = (GfII / I) / fs
/// follows from the scaled fs by itself.) The batch kernel performs the same
/// operations on a register of factors (crack_batch_kernel.hpp,
/// scaled_strength_lanes), so that both paths compute the same bits; f = 1
/// leaves every term's bits as they are.
template <class T>
struct StrengthTerms {
  T ft, c, inv_c, op_per_h, h_per_op, inv_open_range;
};

inline StrengthTerms<double> scaled_strength_terms(const CrackConstants& k, double f) {
  return {k.ft * f, k.c * f, k.inv_c / f, k.op_per_h * f, k.h_per_op / f, k.inv_open_range * f};
}

/// Rock-law constants of one crack element whose strengths are f times its
/// material's (heterogeneity); everything the law reads is consistent.
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
struct CrackPoint {
  double sigma;  ///< normal stress [Pa], tension positive
  double tau;    ///< shear stress [Pa], sign of the slip
  double a;      ///< normalised opening excursion (o - op)/(or - op), >= 0
  double b;      ///< normalised slip excursion (|s| - sp)/(sr - sp), >= 0
};

/// Hardening branch shared by both laws: (2x - x^2) below the peak, 1 beyond.
inline double pre_peak(double x) { return x >= 1.0 ? 1.0 : (2.0 - x) * x; }

/// Raises the point's damage history to the mixed-mode damage
/// sqrt(a^2 + b^2) (seed eq. 10), capped at 1; never lowers it.
inline void accumulate_damage(const CrackPoint& p, double& damage) {
  if (p.a > 0.0 || p.b > 0.0) {
    const double trial = std::sqrt(p.a * p.a + p.b * p.b);
    if (trial > damage) damage = std::min(trial, 1.0);
  }
}

/// Rock law (reference sec. 2): Mohr-Coulomb strength, Evans-Marathe
/// softening, penalty in compression; `damage` is the point's history.
/// h is the element length, inv_h = 1 / h.
///   op = 2 h ft / pn, sp = 2 h fs / pt, or - op = GfI / (I ft),
///   sr - sp = GfII / (I fs), I = integral of z = 0.3863.
inline CrackPoint rock_point(const CrackConstants& k, double o, double s, double h, double inv_h,
                             double& damage) {
  CrackPoint p;
  const bool closed = o < 0.0;
  const double sigma_c = closed ? k.pn * o * inv_h : 0.0;  // penalty, unaffected by damage
  const double fs = k.c - sigma_c * k.tan_phi;             // Mohr-Coulomb, tension positive
  const double inv_fs = closed ? 1.0 / fs : k.inv_c;
  const double op = h * k.op_per_h;
  const double sp = h * fs * k.two_over_pt;
  const double abs_s = std::fabs(s);
  p.a = o > op ? (o - op) * k.inv_open_range : 0.0;
  p.b = abs_s > sp ? (abs_s - sp) * fs * k.inv_slip_energy : 0.0;
  accumulate_damage(p, damage);
  const double z = damage > 0.0 ? softening_z(damage) : 1.0;
  p.sigma = closed ? sigma_c : pre_peak(o * inv_h * k.h_per_op) * z * k.ft;
  p.tau = std::copysign(pre_peak(abs_s * inv_h * k.half_pt * inv_fs) * z * fs, s);
  return p;
}

/// Bolt steel (seed eqs. 11-19): below op the rock-law curve up to sigma_y,
/// then axial hardening sigma_y + D (sigma_u - sigma_y) (f_axial = D) until
/// D = 1; shear up to tau_y, then brittle decay f_lateral = (1 - D)^2, whose
/// integral 1/3 makes eq. 16 with eta = 6 dissipate exactly GfII.
inline CrackPoint bolt_steel_point(const CrackConstants& k, double o, double s, double h,
                                   double inv_h, double& damage) {
  CrackPoint p;
  const double op = h * k.op_per_h;
  const double sp = h * k.c * k.two_over_pt;
  const double abs_s = std::fabs(s);
  p.a = o > op ? (o - op) * k.inv_open_range : 0.0;
  p.b = abs_s > sp ? (abs_s - sp) * k.c * k.inv_slip_energy : 0.0;
  accumulate_damage(p, damage);
  const double axial = damage < 1.0 ? k.ft + damage * (k.fu - k.ft) : 0.0;
  const double lateral = (1.0 - damage) * (1.0 - damage);
  p.sigma = o < 0.0 ? k.pn * o * inv_h : pre_peak(o * inv_h * k.h_per_op) * axial;
  p.tau = std::copysign(pre_peak(abs_s * inv_h * k.half_pt * k.inv_c) * lateral * k.c, s);
  return p;
}

/// Relative displacement (opening o, slip s) at which an undamaged point of
/// law k carries the normal stress `sigma` and shear stress `tau` (the
/// inverse of the pre-peak branches): compression on the penalty branch
/// o = sigma h / pn; tension and shear invert (2x - x^2) times ft resp. the
/// shear strength (rock: Mohr-Coulomb with the total normal stress sigma).
/// A demand at or above the strength starts just below the peak, so the
/// point carries the strength, not the demand (and stays undamaged).
/// Returns true when the demand was clipped that way.
inline bool pre_peak_displacement(const CrackConstants& k, double sigma, double tau, double h,
                                  double& o, double& s) {
  constexpr double kBelowPeak = 1.0 - 1e-12;  // keeps a = b = 0 at the start
  bool clipped = false;
  auto invert = [&](double ratio) {  // x with (2x - x^2) = ratio, x <= 1
    if (ratio >= 1.0) {
      clipped = clipped || ratio > 1.0;
      return kBelowPeak;
    }
    return ratio / (1.0 + std::sqrt(1.0 - ratio));  // 1 - sqrt(1 - r), without cancellation
  };
  if (sigma < 0.0) {
    o = sigma * h / k.pn;
  } else {
    o = invert(sigma / k.ft) * h * k.op_per_h;
  }
  const double fs = (k.law == CrackLaw::kRock && sigma < 0.0) ? k.c - sigma * k.tan_phi : k.c;
  const double sp = h * fs * k.two_over_pt;
  s = std::copysign(invert(std::fabs(tau) / fs) * sp, tau);
  return clipped;
}

/// Potential of one point per unit length at a fixed damage D: the work the
/// law's tractions do from (0, 0) to (o, s) with D held, i.e. the elastic
/// energy the point would return on unloading. At fixed D both laws are
/// elastic: the pre-peak curve (2x - x^2) scaled by a factor of D, then its
/// plateau, and the compressive penalty (which damage does not touch):
///   normal   o < 0: pn o^2 / (2h);  o >= 0: g_n(D) ft [op (x^2 - x^3/3) + (o - op)+]
///   shear    g_s(D) fs [sp (y^2 - y^3/3) + (|s| - sp)+],   x = min(o/op, 1), y = min(|s|/sp, 1)
/// with g_n = g_s = z(D) for rock (fs the Mohr-Coulomb strength) and, for
/// bolt steel, g_n = (sigma_y + D (sigma_u - sigma_y))/sigma_y (0 at D = 1),
/// g_s = (1 - D)^2. Damage growth at fixed (o, s) releases
/// phi(D_old) - phi(D_new): the fracture energy of the energy balance.
/// (Rock: the closed-shear strength grows with compression while sigma does
/// not carry the matching term, so under changing compression the law is
/// not exactly conservative below the peak; see docs/engine.md.)
inline double crack_point_potential(const CrackConstants& k, double o, double s, double h,
                                    double damage) {
  const bool bolt = k.law == CrackLaw::kBoltSteel;
  double g_n, g_s;
  if (bolt) {
    g_n = damage < 1.0 ? 1.0 + damage * (k.fu - k.ft) / k.ft : 0.0;
    g_s = (1.0 - damage) * (1.0 - damage);
  } else {
    g_n = g_s = damage > 0.0 ? softening_z(damage) : 1.0;
  }
  double e;
  if (o < 0.0) {
    e = 0.5 * k.pn * o * o / h;
  } else {
    const double op = h * k.op_per_h, x = std::min(o / op, 1.0);
    e = g_n * k.ft * (op * (x * x - x * x * x / 3.0) + std::max(o - op, 0.0));
  }
  const double fs = (!bolt && o < 0.0) ? k.c - k.pn * o / h * k.tan_phi : k.c;
  const double sp = h * fs * k.two_over_pt, abs_s = std::fabs(s);
  const double y = std::min(abs_s / sp, 1.0);
  return e + g_s * fs * (sp * (y * y - y * y * y / 3.0) + std::max(abs_s - sp, 0.0));
}

/// One point of any law: a switch on the law id, no virtual call. The crack
/// loop dispatches once per element instead (crack_elements.cpp).
inline CrackPoint crack_point(const CrackConstants& k, double o, double s, double h,
                              double& damage) {
  switch (k.law) {
    case CrackLaw::kBoltSteel:
      return bolt_steel_point(k, o, s, h, 1.0 / h, damage);
    case CrackLaw::kRock:
    default:
      return rock_point(k, o, s, h, 1.0 / h, damage);
  }
}

}  // namespace rockfdem::fdem
