// Perfectly plastic Mohr-Coulomb with non-associated flow: the closed-form
// return mapping in principal stresses, and its consistent tangent, for
// plane strain. No deal.II here: the law is unit-tested on its own.
//
// Conventions: TENSION POSITIVE stresses and strains; a plane-strain state
// is {xx, yy, zz, xy} (tensor components, eps_zz = 0 always). Principal
// stresses are ordered s1 >= s2 >= s3 (s3 the most compressive).
//
// Yield function and plastic potential (k, m >= 1):
//
//     f = k s1 - s3 - sigma_c,   k = (1 + sin phi) / (1 - sin phi),
//     g = m s1 - s3,             m = (1 + sin psi) / (1 - sin psi),
//     sigma_c = 2 c cos phi / (1 - sin phi)  (uniaxial compressive strength).
//
// (In compression-positive terms: s_major = k s_minor + sigma_c.) The return
// follows Clausen, Damkilde & Andersen (2006), "Efficient return algorithms
// for associated plasticity with multiple yield planes", IJNME 66:1036-1059,
// extended to non-associated flow as they do in their section 5: with the
// principal elastic matrix D = lambda 1 1^T + 2 mu I and a = grad f,
// b = grad g in principal space,
//
//   plane:  s = s* - [f(s*) / (a.D b)] D b
//   edge:   s = s_apex + t r_f,  t = r_g.D^-1 (s* - s_apex) / r_g.D^-1 r_f
//           (r_f, r_g: directions of the f- and g-edges: (1,1,k), (1,1,m)
//           where s1 = s2; (1,k,k), (1,m,m) where s2 = s3)
//   apex:   s = s_apex = sigma_c / (k - 1) (1,1,1)
//
// tried in this order: a plane return that keeps s1 >= s2 >= s3 is the
// answer; else the edge whose order was broken, accepted when both plastic
// multipliers are >= 0 and t <= 0 (below the apex); else the other edge;
// else the apex. Perfect plasticity makes each return linear in s*, so the
// principal tangent ds/ds* is a constant matrix P per region; the full
// tangent adds the rotation of the in-plane principal axes (the spin term
// (s_A - s_B) / (s*_A - s*_B) on the in-plane shear).
//
// The apex with psi < phi: the potential has no volumetric flow that could
// reach it (with psi = 0 none at all), so the stress is put at the apex as
// the associated law would (de Souza Neto, Peric & Owen 2008, sec. 8.2.2
// treat it the same way). It is reached only in all-round tension.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace rockfdem::insitu::mc {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;
using Stress4 = std::array<double, 4>;  ///< {xx, yy, zz, xy}, tension positive [Pa]

struct Material {
  double E = 0, nu = 0;      ///< elastic (plane strain) [Pa], [-]
  double cohesion = 0;       ///< c [Pa]
  double friction_deg = 30;  ///< phi, in (0, 90) [deg]
  double dilation_deg = 0;   ///< psi, in [0, phi] [deg]
};

enum class Return : std::uint8_t { kElastic = 0, kPlane = 1, kEdge = 2, kApex = 3 };

struct Result {
  Stress4 stress{};
  Return kind = Return::kElastic;
  /// d(s_xx, s_yy, s_xy) / d(e_xx, e_yy, e_xy) (e_xy the tensor component):
  /// the algorithmic tangent of the stress update, not symmetric when psi != phi.
  Mat3 tangent{};
};

/// The constants of the law, computed once per material.
struct Law {
  double lambda = 0, mu = 0;
  double k = 1, m = 1, sigma_c = 0, apex = 0;

  explicit Law(const Material& mat) {
    constexpr double kDeg = 3.14159265358979323846 / 180;
    lambda = mat.E * mat.nu / ((1 + mat.nu) * (1 - 2 * mat.nu));
    mu = mat.E / (2 * (1 + mat.nu));
    const double sp = std::sin(mat.friction_deg * kDeg), sd = std::sin(mat.dilation_deg * kDeg);
    k = (1 + sp) / (1 - sp);
    m = (1 + sd) / (1 - sd);
    sigma_c = 2 * mat.cohesion * std::cos(mat.friction_deg * kDeg) / (1 - sp);
    apex = sigma_c / (k - 1);
  }

  /// f in principal stresses s1 >= s2 >= s3 [Pa]: > 0 outside the surface.
  double yield(const Vec3& s) const { return k * s[0] - s[2] - sigma_c; }

  Vec3 D(const Vec3& v) const {  // principal elasticity
    const double tr = v[0] + v[1] + v[2];
    return {lambda * tr + 2 * mu * v[0], lambda * tr + 2 * mu * v[1], lambda * tr + 2 * mu * v[2]};
  }
  Vec3 D_inv(const Vec3& v) const {
    const double tr = v[0] + v[1] + v[2], c = lambda / (3 * lambda + 2 * mu);
    return {(v[0] - c * tr) / (2 * mu), (v[1] - c * tr) / (2 * mu), (v[2] - c * tr) / (2 * mu)};
  }
};

namespace detail {

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline Mat3 outer(const Vec3& a, const Vec3& b, double scale) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = scale * a[i] * b[j];
  return r;
}

inline bool ordered(const Vec3& s, double tol) { return s[0] >= s[1] - tol && s[1] >= s[2] - tol; }

/// Plastic multipliers of an edge return, D^-1 (s* - s) = l1 b1 + l2 b2
/// (least squares on the 2 unknowns): both must be >= 0.
inline bool multipliers_nonnegative(const Law& law, const Vec3& ds, const Vec3& b1, const Vec3& b2,
                                    double tol) {
  const Vec3 e = law.D_inv(ds);
  const double a11 = dot(b1, b1), a12 = dot(b1, b2), a22 = dot(b2, b2);
  const double r1 = dot(b1, e), r2 = dot(b2, e), det = a11 * a22 - a12 * a12;
  const double l1 = (a22 * r1 - a12 * r2) / det, l2 = (a11 * r2 - a12 * r1) / det;
  return l1 >= -tol && l2 >= -tol;
}

/// Return onto one edge: true when it is admissible; s and P set.
inline bool edge_return(const Law& law, const Vec3& trial, bool upper, double tol, Vec3& s,
                        Mat3& P) {
  const double k = law.k, m = law.m;
  const Vec3 r_f = upper ? Vec3{1, 1, k} : Vec3{1, k, k};
  const Vec3 r_g = upper ? Vec3{1, 1, m} : Vec3{1, m, m};
  const Vec3 apex{law.apex, law.apex, law.apex};
  const Vec3 w = law.D_inv(r_g);  // D^-1 symmetric: r_g.D^-1 x = w.x
  const double denom = dot(w, r_f);
  const Vec3 rel{trial[0] - apex[0], trial[1] - apex[1], trial[2] - apex[2]};
  const double t = dot(w, rel) / denom;
  if (t > 0) return false;  // beyond the apex
  for (int i = 0; i < 3; ++i) s[i] = apex[i] + t * r_f[i];
  const Vec3 b1{m, 0, -1}, b2 = upper ? Vec3{0, m, -1} : Vec3{m, -1, 0};
  const Vec3 ds{trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]};
  if (!multipliers_nonnegative(law, ds, b1, b2, tol / (2 * law.mu))) return false;
  P = outer(r_f, w, 1 / denom);
  return true;
}

}  // namespace detail

/// The return in ordered principal stresses: s and P = ds/ds* (3x3);
/// *upper_edge (when given) tells which edge an kEdge return went to.
inline Return principal_return(const Law& law, const Vec3& trial, Vec3& s, Mat3& P,
                               bool* upper_edge = nullptr) {
  using namespace detail;
  const double tol =
      1e-12 * (std::abs(trial[0]) + std::abs(trial[1]) + std::abs(trial[2]) + law.sigma_c);
  P = Mat3{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  s = trial;
  const double f = law.yield(trial);
  if (f <= 0) return Return::kElastic;

  const Vec3 a{law.k, 0, -1}, b{law.m, 0, -1};
  const Vec3 Db = law.D(b);
  const double adb = dot(a, Db);
  for (int i = 0; i < 3; ++i) s[i] = trial[i] - f / adb * Db[i];
  if (ordered(s, tol)) {
    const Mat3 corr = outer(Db, a, 1 / adb);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) P[i][j] -= corr[i][j];
    return Return::kPlane;
  }
  const bool upper_first = s[0] < s[1];  // s1 = s2 broken first, else s2 = s3
  for (const bool upper : {upper_first, !upper_first})
    if (edge_return(law, trial, upper, tol, s, P)) {
      if (upper_edge) *upper_edge = upper;
      return Return::kEdge;
    }
  s = Vec3{law.apex, law.apex, law.apex};
  P = Mat3{};
  return Return::kApex;
}

namespace detail {

/// In-plane principal axes: s_A = c + R along (cos t, sin t), s_B = c - R.
struct Axes {
  double sA = 0, sB = 0, cos_t = 1, sin_t = 0;
};

inline Axes in_plane_axes(double xx, double yy, double xy) {
  Axes ax;
  const double c = 0.5 * (xx + yy), h = 0.5 * (xx - yy);
  const double R = std::hypot(h, xy);
  ax.sA = c + R;
  ax.sB = c - R;
  const double t = 0.5 * std::atan2(xy, h);
  ax.cos_t = std::cos(t);
  ax.sin_t = std::sin(t);
  return ax;
}

/// Components {A, B, z} sorted descending: order[i] = which of them is s_(i+1).
inline std::array<int, 3> sort_order(const Vec3& abz) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return abz[i] > abz[j]; });
  return order;
}

}  // namespace detail

/// The plane-strain elasticity C as d(s_xx, s_yy, s_xy) / d(e_xx, e_yy, e_xy).
inline Mat3 elastic_tangent(const Law& law) {
  return {Vec3{law.lambda + 2 * law.mu, law.lambda, 0},
          Vec3{law.lambda, law.lambda + 2 * law.mu, 0}, Vec3{0, 0, 2 * law.mu}};
}

namespace detail {

/// The stress update around a principal return `ret(trial, s, P)` (ordered
/// principal stresses; law gives the elasticity): trial, principal frame,
/// return, and back with the tangent.
template <class PrincipalReturn>
Result update_with(const Law& law, const Stress4& previous, const Vec3& d_eps,
                   PrincipalReturn&& ret) {
  const double tr = d_eps[0] + d_eps[1];
  const Stress4 trial{previous[0] + law.lambda * tr + 2 * law.mu * d_eps[0],
                      previous[1] + law.lambda * tr + 2 * law.mu * d_eps[1],
                      previous[2] + law.lambda * tr, previous[3] + 2 * law.mu * d_eps[2]};
  const Axes ax = in_plane_axes(trial[0], trial[1], trial[3]);
  const Vec3 abz{ax.sA, ax.sB, trial[2]};
  const std::array<int, 3> order = sort_order(abz);
  const Vec3 sorted{abz[order[0]], abz[order[1]], abz[order[2]]};
  Vec3 s;
  Mat3 P;
  Result out;
  out.kind = ret(sorted, s, P);
  if (out.kind == Return::kElastic) {
    out.stress = trial;
    out.tangent = elastic_tangent(law);
    return out;
  }
  Vec3 abz_new{};
  Mat3 P_abz{};  // P in the {A, B, z} numbering
  for (int i = 0; i < 3; ++i) {
    abz_new[order[i]] = s[i];
    for (int j = 0; j < 3; ++j) P_abz[order[i]][order[j]] = P[i][j];
  }
  const double c = ax.cos_t, sn = ax.sin_t;
  // s = s_A nA nA + s_B nB nB, nA = (c, sn), nB = (-sn, c).
  out.stress = {abz_new[0] * c * c + abz_new[1] * sn * sn,
                abz_new[0] * sn * sn + abz_new[1] * c * c, abz_new[2],
                (abz_new[0] - abz_new[1]) * c * sn};

  // Tangent, column by column: the response to a unit strain e_j.
  const double gap = ax.sA - ax.sB;
  const double spin = std::abs(gap) > 1e-9 * (std::abs(ax.sA) + std::abs(ax.sB) + law.mu)
                          ? (abz_new[0] - abz_new[1]) / gap
                          : 0.5 * (P_abz[0][0] - P_abz[0][1] - P_abz[1][0] + P_abz[1][1]);
  for (int j = 0; j < 3; ++j) {
    Vec3 e{};
    e[j] = 1;
    const double t = e[0] + e[1];
    const double dxx = law.lambda * t + 2 * law.mu * e[0], dyy = law.lambda * t + 2 * law.mu * e[1];
    const double dxy = 2 * law.mu * e[2], dzz = law.lambda * t;
    // Trial increment in the principal frame.
    const Vec3 d_abz{dxx * c * c + dyy * sn * sn + 2 * dxy * c * sn,
                     dxx * sn * sn + dyy * c * c - 2 * dxy * c * sn, dzz};
    const double d_ab = (dyy - dxx) * c * sn + dxy * (c * c - sn * sn);
    Vec3 r{};
    for (int i = 0; i < 3; ++i)
      r[i] = P_abz[i][0] * d_abz[0] + P_abz[i][1] * d_abz[1] + P_abz[i][2] * d_abz[2];
    const double r_ab = spin * d_ab;
    out.tangent[0][j] = r[0] * c * c + r[1] * sn * sn - 2 * r_ab * c * sn;
    out.tangent[1][j] = r[0] * sn * sn + r[1] * c * c + 2 * r_ab * c * sn;
    out.tangent[2][j] = (r[0] - r[1]) * c * sn + r_ab * (c * c - sn * sn);
  }
  return out;
}

}  // namespace detail

/// The stress update: from the converged stress `previous` and the strain
/// increment d_eps = {xx, yy, xy} (tensor), the elastic trial
/// previous + C d_eps returned onto the surface, with its tangent.
inline Result update(const Law& law, const Stress4& previous, const Vec3& d_eps) {
  return detail::update_with(law, previous, d_eps, [&](const Vec3& t, Vec3& s, Mat3& P) {
    return principal_return(law, t, s, P);
  });
}

/// f of a plane-strain stress [Pa]: > 0 outside the surface.
inline double yield_value(const Law& law, const Stress4& s) {
  const detail::Axes ax = detail::in_plane_axes(s[0], s[1], s[3]);
  Vec3 v{ax.sA, ax.sB, s[2]};
  std::sort(v.begin(), v.end(), [](double x, double y) { return x > y; });
  return law.yield(v);
}

}  // namespace rockfdem::insitu::mc
