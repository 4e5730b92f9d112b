// Strain-softening Mohr-Coulomb: c and phi fall linearly from the peak to
// the residual values as the equivalent plastic shear strain gamma_p grows
// from 0 to gamma_res, and stay residual beyond; the dilation psi is fixed.
// gamma_res = 0 is elastic-brittle-plastic: the first plastic step drops to
// the residual strength. No deal.II here (unit-tested on its own).
//
// gamma_p: with the plastic strain increment of a return in the ordered
// principal frame, d_eps_p = D^-1 (s* - s), d_gamma_p = d_eps_p1 - d_eps_p3
// (the definition of Brown et al. 1983 and Alonso et al. 2003); on the yield
// plane it is (1 + m) times the plastic multiplier, never negative.
//
// The update is implicit in gamma_p (backward Euler): gamma solves
//
//     h(q) = q - gamma_n - G(s*, q) = 0,   G(s*, q) = w . D^-1 (s* - S(s*, q)),
//
// with S the perfectly plastic return (mohr_coulomb.hpp) of the law at
// strength q and w = (1, 0, -1). If the residual law's own return already
// reaches gamma_res (h(gamma_res) <= 0) that is the answer, perfectly
// plastic at the residual strength; else the root lies in (gamma_n,
// gamma_res) where Newton on h, kept in its bracket, finds it. The tangent
// then adds the softening to the return's P = dS/ds*:
//
//     ds/ds* = P + dS/dq (x) dq/ds*,   dq/ds* = w D^-1 (I - P) / (1 - dG/dq),
//     dG/dq = -w . D^-1 dS/dq,
//
// dS/dq from each region's closed form differentiated in (k, sigma_c):
//   plane: dS/dq = (sigma_c' - k' s1) / (a.D b) D b   (f(S) = 0 kept)
//   edge:  S = A 1 + t r_f, A = sigma_c/(k - 1):
//          dS/dq = A' 1 + t' r_f + t r_f',  t' = -(A' w.1 + t w.r_f') / w.r_f
//   apex:  dS/dq = A' 1.
#pragma once

#include <cmath>

#include "mohr_coulomb.hpp"

namespace rockfdem::insitu::mc {

/// Peak and residual strengths (the elastic constants and psi of `peak`
/// hold throughout) and the plastic shear strain of the residual.
struct Softening {
  Material peak, residual;
  double gamma_res = 0;  ///< gamma_p at which the residual is reached [-]
};

class SofteningLaw {
 public:
  explicit SofteningLaw(const Softening& s)
      : s_(s),
        peak_(s.peak),
        residual_(at_strength(s.residual.cohesion, s.residual.friction_deg)),
        softens_(s.residual.cohesion != s.peak.cohesion ||
                 s.residual.friction_deg != s.peak.friction_deg) {}

  const Law& peak() const { return peak_; }
  const Law& residual() const { return residual_; }
  bool softens() const { return softens_; }
  double gamma_res() const { return s_.gamma_res; }

  /// The law at gamma_p = q (peak for q <= 0, else residual for q >= gamma_res).
  Law at(double q) const {
    if (!softens_ || q <= 0) return peak_;
    if (q >= s_.gamma_res) return residual_;
    const double x = q / s_.gamma_res;
    return at_strength(
        s_.peak.cohesion + x * (s_.residual.cohesion - s_.peak.cohesion),
        s_.peak.friction_deg + x * (s_.residual.friction_deg - s_.peak.friction_deg));
  }

  /// d k / dq and d sigma_c / dq of the law at q, 0 < q < gamma_res.
  void slopes(const Law& law, double q, double& dk, double& dsc) const {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    const double phi =
        kDeg * (s_.peak.friction_deg +
                q / s_.gamma_res * (s_.residual.friction_deg - s_.peak.friction_deg));
    const double dphi = kDeg * (s_.residual.friction_deg - s_.peak.friction_deg) / s_.gamma_res;
    const double dc = (s_.residual.cohesion - s_.peak.cohesion) / s_.gamma_res;
    const double sp = std::sin(phi);
    dk = 2 * std::cos(phi) / ((1 - sp) * (1 - sp)) * dphi;
    // sigma_c = 2 c sqrt(k): c = sigma_c / (2 sqrt(k)).
    const double sqk = std::sqrt(law.k), c = law.sigma_c / (2 * sqk);
    dsc = 2 * dc * sqk + c * dk / sqk;
  }

 private:
  Law at_strength(double c, double phi_deg) const {
    Material m = s_.peak;
    m.cohesion = c;
    m.friction_deg = phi_deg;
    return Law(m);
  }

  Softening s_;
  Law peak_, residual_;
  bool softens_;
};

namespace detail {

/// D^-1 w, w = (1, 0, -1): d_gamma_p = gw . (s* - s).
inline Vec3 gamma_weights(const Law& law) { return law.D_inv(Vec3{1, 0, -1}); }

/// dS/dq of the return `kind` that gave s from trial (see the header).
inline Vec3 return_slope(const Law& law, Return kind, bool upper, const Vec3& trial, const Vec3& s,
                         double dk, double dsc) {
  if (kind == Return::kElastic) return Vec3{};
  const double dA = dsc / (law.k - 1) - law.sigma_c * dk / ((law.k - 1) * (law.k - 1));
  if (kind == Return::kApex) return Vec3{dA, dA, dA};
  if (kind == Return::kPlane) {
    const Vec3 Db = law.D(Vec3{law.m, 0, -1});
    const double scale = (dsc - dk * s[0]) / dot(Vec3{law.k, 0, -1}, Db);
    return Vec3{scale * Db[0], scale * Db[1], scale * Db[2]};
  }
  const Vec3 r_f = upper ? Vec3{1, 1, law.k} : Vec3{1, law.k, law.k};
  const Vec3 dr_f = upper ? Vec3{0, 0, dk} : Vec3{0, dk, dk};
  const Vec3 w = law.D_inv(upper ? Vec3{1, 1, law.m} : Vec3{1, law.m, law.m});
  const double wr = dot(w, r_f),
               t = dot(w, Vec3{trial[0] - law.apex, trial[1] - law.apex, trial[2] - law.apex}) / wr;
  const double dt = -(dA * (w[0] + w[1] + w[2]) + t * dot(w, dr_f)) / wr;
  Vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = dA + dt * r_f[i] + t * dr_f[i];
  return out;
}

/// One evaluation of the return at gamma_p = q: s, P, kind, G and dG/dq
/// (and dS/dq in dS).
struct AtStrength {
  Vec3 s{}, dS{};
  Mat3 P{};
  Return kind = Return::kElastic;
  double G = 0, dG = 0;
};

inline AtStrength return_at(const SofteningLaw& sl, const Law& law, double q, const Vec3& trial) {
  AtStrength a;
  bool upper = false;
  a.kind = principal_return(law, trial, a.s, a.P, &upper);
  const Vec3 gw = gamma_weights(law);
  a.G = dot(gw, Vec3{trial[0] - a.s[0], trial[1] - a.s[1], trial[2] - a.s[2]});
  if (sl.softens() && q > 0 && q < sl.gamma_res()) {
    double dk = 0, dsc = 0;
    sl.slopes(law, q, dk, dsc);
    a.dS = return_slope(law, a.kind, upper, trial, a.s, dk, dsc);
    a.dG = -dot(gw, a.dS);
  }
  return a;
}

/// The softening return in ordered principal stresses: s, P = ds/ds*
/// (softening included) and gamma_p after the step.
inline Return softening_return(const SofteningLaw& sl, double gamma_n, const Vec3& trial, Vec3& s,
                               Mat3& P, double& gamma) {
  gamma = gamma_n;
  if (!sl.softens() || (gamma_n >= sl.gamma_res() && gamma_n > 0)) {
    const Law& law = sl.softens() ? sl.residual() : sl.peak();
    const Return kind = principal_return(law, trial, s, P);
    gamma += dot(gamma_weights(law), Vec3{trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]});
    return kind;
  }
  AtStrength a = return_at(sl, sl.at(gamma_n), gamma_n, trial);
  if (a.kind == Return::kElastic) {
    s = a.s;
    P = a.P;
    return a.kind;
  }
  const AtStrength r = return_at(sl, sl.residual(), sl.gamma_res(), trial);
  if (gamma_n + r.G >= sl.gamma_res()) {  // h(gamma_res) <= 0: residual
    s = r.s;
    P = r.P;
    gamma = gamma_n + r.G;
    return r.kind;
  }
  // h(gamma_n) < 0 < h(gamma_res): Newton in the bracket, bisection when it
  // would leave it.
  double lo = gamma_n, hi = sl.gamma_res(), q = gamma_n;
  for (int it = 0; it < 100; ++it) {
    const double h = q - gamma_n - a.G;
    if (h == 0) break;
    (h < 0 ? lo : hi) = q;
    const double slope = 1 - a.dG;
    double next = slope > 0 ? q - h / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - q) <= 1e-15 * sl.gamma_res() || hi - lo <= 1e-15 * hi;
    q = next;
    a = return_at(sl, sl.at(q), q, trial);
    if (done) break;
  }
  s = a.s;
  gamma = q;
  P = a.P;
  const double denom = 1 - a.dG;
  if (a.kind == Return::kElastic || !(denom > 1e-12)) return a.kind;
  // P += dS (x) w D^-1 (I - P) / denom.
  const Vec3 gw = gamma_weights(sl.at(q));
  Vec3 row{};
  for (int j = 0; j < 3; ++j)
    row[j] = gw[j] - (gw[0] * P[0][j] + gw[1] * P[1][j] + gw[2] * P[2][j]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) P[i][j] += a.dS[i] * row[j] / denom;
  return a.kind;
}

}  // namespace detail

/// The stress update of the softening law from the converged stress and
/// gamma_p; gamma (out) is gamma_p after the step. Without softening the
/// stress and tangent are those of update(peak, ...) bit for bit.
inline Result update(const SofteningLaw& sl, const Stress4& previous, double gamma_n,
                     const Vec3& d_eps, double& gamma) {
  return detail::update_with(sl.peak(), previous, d_eps, [&](const Vec3& t, Vec3& s, Mat3& P) {
    return detail::softening_return(sl, gamma_n, t, s, P, gamma);
  });
}

}  // namespace rockfdem::insitu::mc
