// The joint crack law: a rock discontinuity with Mohr-Coulomb peak and
// residual strength. Like the rock law below the peak (penalty in
// compression, (2x - x^2) pre-peak curves, Evans-Marathe softening z(D)),
// but
//   - the tensile strength may be 0: the joint then opens freely, carries
//     no tension and takes no damage from opening;
//   - the shear strength softens from the peak to a residual friction
//     instead of to zero:
//       fs(D) = fr + z(D) (fp - fr),  fp = c - sigma tan(phi),
//       fr = -sigma tan(phi_r)        (compression, sigma < 0; fr = 0 in tension),
//     with the slip range from the peak, sp = 2 h fp / pt, and the damage
//     b = (|s| - sp) fp / (GfII / I) as in the rock law;
//   - the element never breaks (CrackConstants::breaks = false): at D = 1 it
//     goes on sliding on its residual friction, so a joint keeps its
//     frictional contact without handing over to the contact search.
// The slip is the total one of the element (no plastic slip history): the
// law is Mohr-Coulomb for monotonic sliding; on a reversal the shear stress
// returns along the pre-peak curve.
//
// Barton-Bandis peak (optional, Material::jcs > 0): with sigma_n = -sigma
// the compression,
//   fp = c + sigma_n tan(phi_r + JRC log10(JCS / sigma_n)),
// the total angle at most kBartonBandisMaxAngleDeg (70 deg: as sigma_n -> 0
// the logarithm grows without bound, the cap keeps fp -> c) and at least
// phi_r (sigma_n above JCS: the asperities are sheared off); no tension
// (fp = c for sigma_n <= 0). The peak friction angle phi is then unused;
// the residual is phi_r's, as in Barton's model once the roughness is
// worn down. The slip range follows from fp as before.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/crack_law_parts.hpp"
#include "rockfdem/fdem/crack_law_rock.hpp"

namespace rockfdem::fdem {

/// Cap of the Barton-Bandis total friction angle phi_r + JRC log10(JCS/sigma_n).
constexpr double kBartonBandisMaxAngleDeg = 70.0;

struct JointLaw {
  static constexpr CrackLaw kId = CrackLaw::kJoint;
  static constexpr const char* kName = "joint";
  static constexpr bool kHeterogeneous = false;
  static constexpr bool kBatched = false;  ///< few elements: the scalar loop takes them

  /// The law's entries of k from m (the penalties are set already). With
  /// ft = 0 the opening range stays 0 (make_crack_constants then leaves its
  /// reciprocal 0: opening does no damage).
  static void set_constants(const Material& m, CrackConstants& k) {
    const double integral = rock_softening_integral();
    k.ft = m.tensile_strength;
    k.c = m.cohesion;
    k.tan_phi = std::tan(m.friction_deg * kPi / 180.0);
    k.tan_phi_r = std::tan(m.residual_friction_deg * kPi / 180.0);
    k.open_range = m.tensile_strength > 0 ? m.gf_I / (integral * m.tensile_strength) : 0.0;
    k.slip_energy = m.gf_II / integral;
    k.breaks = false;
    k.barton_bandis = m.jcs > 0;
    k.phi_r = m.residual_friction_deg * kPi / 180.0;
    k.jrc_rad = m.jrc * kPi / 180.0;
    k.jcs = m.jcs;
    k.max_angle_rad = kBartonBandisMaxAngleDeg * kPi / 180.0;
  }

  /// What is wrong with m's parameters for this law ("": nothing).
  static std::string input_problem(const Material& m) {
    if (!(m.tensile_strength >= 0 && m.cohesion >= 0))
      return "tensile strength and cohesion must be >= 0 for the joint crack law";
    if (m.jcs != 0 || m.jrc != 0) {  // Barton-Bandis: phi_r, JRC and JCS; phi unused
      std::ostringstream s;
      if (!(m.jcs > 0))
        s << "joint wall compressive strength JCS " << m.jcs << " Pa must be > 0";
      else if (!(m.jrc >= 0 && m.jrc <= 20))
        s << "joint roughness coefficient JRC " << m.jrc << " must lie in [0, 20]";
      else if (!(m.residual_friction_deg >= 0 &&
                 m.residual_friction_deg < kBartonBandisMaxAngleDeg))
        s << "residual friction angle " << m.residual_friction_deg << " must lie in [0, "
          << kBartonBandisMaxAngleDeg << ") degrees with Barton-Bandis";
      return s.str();
    }
    if (!(m.friction_deg >= 0 && m.friction_deg < 90) ||
        !(m.residual_friction_deg >= 0 && m.residual_friction_deg <= m.friction_deg)) {
      std::ostringstream s;
      s << "friction angles " << m.friction_deg << " (peak) and " << m.residual_friction_deg
        << " (residual) must satisfy 0 <= residual <= peak < 90 degrees";
      return s.str();
    }
    return "";
  }

  /// Peak shear strength at the penalty stress sigma_c (tension positive, 0
  /// when open): Mohr-Coulomb c - sigma_c tan(phi), or Barton-Bandis.
  template <class T>
  static ROCKFDEM_LAW_INLINE T peak_strength(const CrackConstants& k, const T& sigma_c) {
    if (!k.barton_bandis) return k.c - sigma_c * k.tan_phi;
    const T zero{};
    const T one = lanes::splat<T>(1.0);
    const T sigma_n = zero - sigma_c;                 // compression, >= 0
    const T safe = (sigma_n > zero) ? sigma_n : one;  // open: any angle, times 0
    const T raw = k.phi_r + k.jrc_rad * lanes::log10(k.jcs / safe);
    const T capped = (raw > k.max_angle_rad) ? lanes::splat<T>(k.max_angle_rad) : raw;
    const T angle = (capped < k.phi_r) ? lanes::splat<T>(k.phi_r) : capped;
    return k.c + sigma_n * lanes::tan(angle);
  }

  template <class T>
  static ROCKFDEM_LAW_INLINE T softening(T damage) {
    return RockLaw::softening(damage);
  }

  /// One integration point: raises `damage` and returns the stresses at the
  /// raised history. A zero peak strength (tension without cohesion) gives
  /// no shear stress and no damage; the divisions take 1 there so that no
  /// lane computes 0/0.
  template <class T>
  static ROCKFDEM_LAW_INLINE CrackPointOf<T> point(const CrackConstants& k, const StrengthTerms<T>&,
                                                   const T& o, const T& s, const T& h,
                                                   const T& inv_h, T& damage) {
    const T zero{};
    const T one = lanes::splat<T>(1.0);
    const T sigma_c = (o < zero) ? k.pn * o * inv_h : zero;  // penalty, unaffected by damage
    const T fp = peak_strength(k, sigma_c);                  // peak, tension positive
    const T fr = -sigma_c * k.tan_phi_r;                     // residual
    const T op = h * k.op_per_h;
    const T sp = h * fp * k.two_over_pt;
    const T abs_s = lanes::abs(s);
    CrackPointOf<T> p;
    p.a = (o > op) ? (o - op) * k.inv_open_range : zero;
    p.b = (abs_s > sp) ? (abs_s - sp) * fp * k.inv_slip_energy : zero;
    raise_damage(p.a, p.b, damage);
    const T z = softening(damage);
    const T fs = fr + z * (fp - fr);
    const T inv_fp = one / ((fp > zero) ? fp : one);
    const T shear = pre_peak(abs_s * inv_h * k.half_pt * inv_fp) * fs;
    p.sigma = (o < zero) ? sigma_c : pre_peak(o * inv_h * k.h_per_op) * z * k.ft;
    p.tau = lanes::copysign((fp > zero) ? shear : zero, s);
    return p;
  }

  /// Peak shear strength at the total normal stress sigma (the point's,
  /// c in tension).
  static double shear_strength(const CrackConstants& k, double sigma) {
    return sigma < 0.0 ? peak_strength(k, sigma) : k.c;
  }

  /// z(D) for both curves, as the rock's: the potential is the softened peak
  /// curve's (the residual part of the strength is left out of the energy).
  static void damage_factors(const CrackConstants& k, double damage, double& g_n, double& g_s) {
    RockLaw::damage_factors(k, damage, g_n, g_s);
  }
};

}  // namespace rockfdem::fdem
