// Crack (cohesive) laws evaluated at one integration point of a four-node
// crack element: the list of laws and the one place that picks a law's
// traits by its id, for the scalar crack loop and the batch kernel alike.
//
// Each law is a traits struct in its own file (crack_law_rock.hpp,
// crack_law_bolt_steel.hpp) built from crack_law_parts.hpp:
//   kId, kName            its CrackLaw enumerator and its name in messages
//   kHeterogeneous        whether strength factors apply (StrengthTerms)
//   kBatched              whether the crack loop's batch pass takes its elements
//   set_constants(m, k)   its entries of CrackConstants from a Material
//   input_problem(m)      what is wrong with a Material for it ("" = nothing)
//   point<T>(k, st, o, s, h, inv_h, damage)
//                         stresses and raised damage at one point, for a
//                         double (scalar loop) or a register (batch kernel)
//   shear_strength(k, sigma), damage_factors(k, D, g_n, g_s)
//                         what pre_peak_displacement and crack_point_potential
//                         need of it.
// A new law: its file, an enumerator in CrackLaw (model_input.hpp) and one
// entry in CrackLaws below.
#pragma once

#include <algorithm>
#include <cmath>

#include "rockfdem/fdem/crack_law_bolt_steel.hpp"
#include "rockfdem/fdem/crack_law_joint.hpp"
#include "rockfdem/fdem/crack_law_parts.hpp"
#include "rockfdem/fdem/crack_law_rock.hpp"

namespace rockfdem::fdem {

template <class... Laws>
struct CrackLawList {};

/// Every crack law. An id that names none falls back to the first.
using CrackLaws = CrackLawList<RockLaw, BoltSteelLaw, JointLaw>;

namespace detail {

template <class Fallback, class F>
ROCKFDEM_LAW_INLINE decltype(auto) pick_law(CrackLaw, F& f, CrackLawList<>) {
  return f(Fallback{});
}

template <class Fallback, class F, class Law, class... Rest>
ROCKFDEM_LAW_INLINE decltype(auto) pick_law(CrackLaw id, F& f, CrackLawList<Law, Rest...>) {
  if (id == Law::kId) return f(Law{});
  return pick_law<Fallback>(id, f, CrackLawList<Rest...>{});
}

template <class F, class First, class... Rest>
ROCKFDEM_LAW_INLINE decltype(auto) pick_law(CrackLaw id, F& f, CrackLawList<First, Rest...> all) {
  return pick_law<First>(id, f, all);
}

}  // namespace detail

/// Calls f(Law{}) with the traits of law `id`: the one dispatch on the law
/// (no virtual call; the crack loop dispatches once per element, the batch
/// kernel once per batch).
template <class F>
ROCKFDEM_LAW_INLINE decltype(auto) with_crack_law(CrackLaw id, F&& f) {
  return detail::pick_law(id, f, CrackLaws{});
}

/// Derive the law constants of `m` (penalties default to 10 E).
inline CrackConstants make_crack_constants(const Material& m) {
  CrackConstants k;
  k.law = m.crack_law;
  k.pn = m.normal_penalty > 0 ? m.normal_penalty : 10.0 * m.young;
  k.pt = m.tangential_penalty > 0 ? m.tangential_penalty : k.pn;
  with_crack_law(m.crack_law, [&](auto law) { decltype(law)::set_constants(m, k); });
  // A joint may have ft = 0, c = 0 (no opening range): their reciprocals
  // are then 0, not infinite, so that no point computes 0 * inf.
  k.op_per_h = 2.0 * k.ft / k.pn;
  k.h_per_op = k.ft > 0 ? k.pn / (2.0 * k.ft) : 0.0;
  k.half_pt = 0.5 * k.pt;
  k.two_over_pt = 2.0 / k.pt;
  k.inv_c = k.c > 0 ? 1.0 / k.c : 0.0;
  k.inv_open_range = k.open_range > 0 ? 1.0 / k.open_range : 0.0;
  k.inv_slip_energy = 1.0 / k.slip_energy;
  return k;
}

/// Whether strength factors apply to law `id`.
inline bool crack_law_heterogeneous(CrackLaw id) {
  return with_crack_law(id, [](auto law) { return decltype(law)::kHeterogeneous; });
}

/// Whether the crack loop's batch pass takes the elements of law `id`.
inline bool crack_law_batched(CrackLaw id) {
  return with_crack_law(id, [](auto law) { return decltype(law)::kBatched; });
}

/// One point of k's law at its material strengths, h the element length.
inline CrackPoint crack_point(const CrackConstants& k, double o, double s, double h,
                              double& damage) {
  return with_crack_law(k.law, [&](auto law) {
    return decltype(law)::point(k, material_terms(k), o, s, h, 1.0 / h, damage);
  });
}

/// Relative displacement (opening o, slip s) at which an undamaged point of
/// law k carries the normal stress `sigma` and shear stress `tau` (the
/// inverse of the pre-peak branches): compression on the penalty branch
/// o = sigma h / pn; tension and shear invert (2x - x^2) times ft resp. the
/// law's shear strength at the total normal stress sigma.
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
  } else if (k.ft > 0.0) {
    o = invert(sigma / k.ft) * h * k.op_per_h;
  } else {  // a joint without tensile strength carries no tension
    o = 0.0;
    clipped = sigma > 0.0;
  }
  const double fs =
      with_crack_law(k.law, [&](auto law) { return decltype(law)::shear_strength(k, sigma); });
  if (!(fs > 0.0)) {  // a joint without cohesion in tension carries no shear
    s = 0.0;
    return clipped || tau != 0.0;
  }
  const double sp = h * fs * k.two_over_pt;
  s = std::copysign(invert(std::fabs(tau) / fs) * sp, tau);
  return clipped;
}

/// Potential of one point per unit length at a fixed damage D: the work the
/// law's tractions do from (0, 0) to (o, s) with D held, i.e. the elastic
/// energy the point would return on unloading. At fixed D every law is
/// elastic: the pre-peak curve (2x - x^2) scaled by a factor of D, then its
/// plateau, and the compressive penalty (which damage does not touch):
///   normal   o < 0: pn o^2 / (2h);  o >= 0: g_n(D) ft [op (x^2 - x^3/3) + (o - op)+]
///   shear    g_s(D) fs [sp (y^2 - y^3/3) + (|s| - sp)+],   x = min(o/op, 1), y = min(|s|/sp, 1)
/// with the law's damage_factors g_n, g_s and shear strength fs at the
/// penalty stress pn o / h. Damage growth at fixed (o, s) releases
/// phi(D_old) - phi(D_new): the fracture energy of the energy balance.
/// (Rock: the closed-shear strength grows with compression while sigma does
/// not carry the matching term, so under changing compression the law is
/// not exactly conservative below the peak; see docs/engine.md.)
inline double crack_point_potential(const CrackConstants& k, double o, double s, double h,
                                    double damage) {
  return with_crack_law(k.law, [&](auto law) {
    using Law = decltype(law);
    double g_n, g_s;
    Law::damage_factors(k, damage, g_n, g_s);
    double e = 0.0;
    if (o < 0.0) {
      e = 0.5 * k.pn * o * o / h;
    } else if (k.ft > 0.0) {  // a joint without tensile strength stores nothing open
      const double op = h * k.op_per_h, x = std::min(o / op, 1.0);
      e = g_n * k.ft * (op * (x * x - x * x * x / 3.0) + std::max(o - op, 0.0));
    }
    const double fs = Law::shear_strength(k, o < 0.0 ? k.pn * o / h : 0.0);
    if (!(fs > 0.0)) return e;  // a joint without cohesion in tension
    const double sp = h * fs * k.two_over_pt, abs_s = std::fabs(s);
    const double y = std::min(abs_s / sp, 1.0);
    return e + g_s * fs * (sp * (y * y - y * y * y / 3.0) + std::max(abs_s - sp, 0.0));
  });
}

}  // namespace rockfdem::fdem
