// Closed forms for a lining ring bonded (no slip) in an infinite elastic
// medium, installed stress-free before the in-situ stress (P vertical,
// K P horizontal, compression positive) is released on it, plane strain.
// Forces per metre, as lining.csv gives them (docs/support.md): thrust
// N(theta) = n0 + n2 cos 2theta (compression positive) and moment
// M(theta) = m0 + m2 cos 2theta about the mid-line (> 0: the rock side more
// compressed), theta counter-clockwise from the horizontal (springline).
//
// - einstein_schwartz: the thin ring of Einstein & Schwartz (1979),
//   "Simplified analysis for tunnel supports", J. Geotech. Eng. Div. ASCE
//   105(GT4), no-slip case (derived again here for a thin extensible ring:
//   the same coefficients, to the ring's t^2 / (12 R^2) coupling).
// - thick_ring: the exact plane-strain elasticity solution of the ring
//   b < r < a (Lame for the mean stress, Michell's cos 2theta functions
//   for the deviator: four constants in the ring, two in the medium, fixed
//   by a traction-free inner face and continuity of traction and
//   displacement at r = a), its hoop stress integrated through the
//   thickness. ES is its limit for t / R -> 0.
#pragma once

#include <Eigen/Dense>
#include <cmath>

namespace rockfdem::test {

struct LinedRing {
  double P = 0, K = 1;     ///< vertical stress [Pa] and horizontal / vertical ratio
  double Em = 0, num = 0;  ///< medium's Young's modulus [Pa] and Poisson's ratio
  double Es = 0, nus = 0;  ///< lining's
  double a = 0, t = 0;     ///< outer radius and thickness [m]
};

struct RingForces {
  double n0 = 0, n2 = 0;  ///< thrust [N/m]
  double m0 = 0, m2 = 0;  ///< moment [N m/m]
};

/// ES no slip with ring radius R: compressibility and flexibility ratios
/// C* = Em R (1 - nus^2) / (Es A (1 - num^2)), F* = Em R^3 (1 - nus^2) /
/// (Es I (1 - num^2)), A = t, I = t^3 / 12;
/// a0* = C* F* (1 - num) / (C* + F* + C* F* (1 - num)),
/// beta = ((6 + F*) C* (1 - num) + 2 F* num) / (3 F* + 3 C* + 2 C* F* (1 - num)),
/// b2* = C* (1 - num) / (2 (C* (1 - num) + 4 num - 6 beta - 3 beta C* (1 - num))),
/// a2* = beta b2*;
/// T / (P R) = (1 + K)(1 - a0*) / 2 + (1 - K)(1 + 2 a2*) cos 2theta / 2,
/// M / (P R^2) = -(1 - K)(1 - 2 a2* + 2 b2*) cos 2theta / 4 (ES's moment
/// with the sign of this document: the springline's extrados in tension
/// when K < 1).
inline RingForces einstein_schwartz(const LinedRing& c, double R) {
  const double nu = c.num, A = c.t, I = c.t * c.t * c.t / 12;
  const double Cs = c.Em * R * (1 - c.nus * c.nus) / (c.Es * A * (1 - nu * nu));
  const double Fs = c.Em * R * R * R * (1 - c.nus * c.nus) / (c.Es * I * (1 - nu * nu));
  const double a0 = Cs * Fs * (1 - nu) / (Cs + Fs + Cs * Fs * (1 - nu));
  const double beta =
      ((6 + Fs) * Cs * (1 - nu) + 2 * Fs * nu) / (3 * Fs + 3 * Cs + 2 * Cs * Fs * (1 - nu));
  const double b2 =
      Cs * (1 - nu) / (2 * (Cs * (1 - nu) + 4 * nu - 6 * beta - 3 * beta * Cs * (1 - nu)));
  const double a2 = beta * b2;
  return {c.P * R * (1 + c.K) * (1 - a0) / 2, c.P * R * (1 - c.K) * (1 + 2 * a2) / 2, 0,
          -c.P * R * R * (1 - c.K) * (1 - 2 * a2 + 2 * b2) / 4};
}

/// The exact thick ring (see the file's comment); tension-positive stresses
/// inside, forces returned compression positive.
inline RingForces thick_ring(const LinedRing& c) {
  const double a = c.a, b = c.a - c.t, rm = (a + b) / 2;
  const double Gs = c.Es / (2 * (1 + c.nus)), Gm = c.Em / (2 * (1 + c.num));
  // Mean stress: ring s_r = A0 + B0 / r^2, s_t = A0 - B0 / r^2, u = ((1 - 2 nus) A0 r
  // - B0 / r) / (2 Gs); medium (perturbation) u = Bm / r, s_r = -pm - 2 Gm Bm / r^2.
  const double pm = c.P * (1 + c.K) / 2;
  Eigen::Matrix3d L;
  L << 1, 1 / (b * b), 0, 1, 1 / (a * a), 2 * Gm / (a * a), (1 - 2 * c.nus) * a / (2 * Gs),
      -1 / (2 * Gs * a), -1 / a;
  const Eigen::Vector3d l = L.partialPivLu().solve(Eigen::Vector3d(0, -pm, 0));
  const double A0 = l[0], B0 = l[1];
  RingForces f;
  f.n0 = -(A0 * c.t - B0 * (1 / b - 1 / a));
  f.m0 = B0 * (std::log(a / b) - rm * (1 / b - 1 / a));
  // Deviator, phi = (A r^2 + B r^4 + C / r^2 + D) cos 2theta in the ring,
  // (Cm / r^2 + Dm) cos 2theta in the medium; far field s_rr = S cos 2theta,
  // s_rt = -S sin 2theta with S = P (1 - K) / 2.
  const auto srr = [](double r) {
    return Eigen::Vector4d(-2, 0, -6 / std::pow(r, 4), -4 / (r * r));
  };
  const auto srt = [](double r) {
    return Eigen::Vector4d(2, 6 * r * r, -6 / std::pow(r, 4), -2 / (r * r));
  };
  const auto ur = [](double r, double G, double nu) {
    return Eigen::Vector4d(-r / G, -2 * nu * r * r * r / G, 1 / (G * r * r * r),
                           2 * (1 - nu) / (G * r));
  };
  const auto ut = [](double r, double G, double nu) {
    return Eigen::Vector4d(r / G, (3 - 2 * nu) * r * r * r / G, 1 / (G * r * r * r),
                           (2 * nu - 1) / (G * r));
  };
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  const auto put = [&](int row, const Eigen::Vector4d& ring, const Eigen::Vector4d& medium) {
    M.block<1, 4>(row, 0) = ring.transpose();
    M.block<1, 2>(row, 4) = -medium.tail<2>().transpose();
  };
  const Eigen::Vector4d none = Eigen::Vector4d::Zero();
  put(0, srr(b), none);
  put(1, srt(b), none);
  put(2, srr(a), srr(a));
  put(3, srt(a), srt(a));
  put(4, ur(a, Gs, c.nus), ur(a, Gm, c.num));
  put(5, ut(a, Gs, c.nus), ut(a, Gm, c.num));
  const double S = c.P * (1 - c.K) / 2;
  Eigen::Matrix<double, 6, 1> rhs;
  rhs << 0, 0, S, -S, 0, 0;
  const Eigen::Matrix<double, 6, 1> k = M.partialPivLu().solve(rhs);
  // s_tt = 2A + 12 B r^2 + 6 C / r^4, integrated and its first moment about r_m.
  const double a3 = a * a * a, b3 = b * b * b;
  f.n2 = -(2 * k[0] * c.t + 4 * k[1] * (a3 - b3) + 2 * k[2] * (1 / b3 - 1 / a3));
  f.m2 = -(12 * k[1] * ((a3 * a - b3 * b) / 4 - rm * (a3 - b3) / 3) +
           6 * k[2] * ((1 / (b * b) - 1 / (a * a)) / 2 - rm * (1 / b3 - 1 / a3) / 3));
  return f;
}

}  // namespace rockfdem::test
