// The Mohr-Coulomb return mapping (insitu/src/mohr_coulomb.hpp) on its own:
// every returned stress on the surface, the plastic corrector along the flow
// direction with non-negative multipliers (the Kuhn-Tucker conditions, checked
// independently of how the return chose its region), the plane, edge and apex
// cases, frame invariance, and the tangent against finite differences.
#include "mohr_coulomb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "mohr_coulomb_softening.hpp"

namespace rockfdem::insitu::mc {
namespace {

constexpr double kMPa = 1e6;

Material rock(double psi = 0) {
  return Material{3e9, 0.25, 3 * kMPa, 30, psi};  // the seed's rock, phi 30
}

/// Sorted principal values of a plane-strain state.
Vec3 principal(const Stress4& s) {
  const double c = 0.5 * (s[0] + s[1]), R = std::hypot(0.5 * (s[0] - s[1]), s[3]);
  Vec3 v{c + R, c - R, s[2]};
  std::sort(v.begin(), v.end(), [](double x, double y) { return x > y; });
  return v;
}

/// The plastic strain D^-1 (s* - s) in principal space is a non-negative
/// combination of the gradients of g at s (1, 2 or 3 active planes).
void expect_flow_rule(const Law& law, const Vec3& trial, const Vec3& s, Return kind) {
  const Vec3 ds{trial[0] - s[0], trial[1] - s[1], trial[2] - s[2]};
  const Vec3 e = law.D_inv(ds);
  const double scale = (std::abs(trial[0]) + std::abs(trial[2]) + law.sigma_c) / (2 * law.mu);
  const double m = law.m;
  if (kind == Return::kPlane) {  // e = l (m, 0, -1), l >= 0
    EXPECT_GE(e[0], -1e-12 * scale);
    EXPECT_NEAR(e[1], 0, 1e-10 * scale);
    EXPECT_NEAR(e[2], -e[0] / m, 1e-10 * scale);
  } else if (kind == Return::kEdge) {  // e = l1 (m,0,-1) + l2 (0,m,-1) or (m,-1,0)
    const bool upper = std::abs(s[0] - s[1]) < std::abs(s[1] - s[2]);
    const double l2 = upper ? e[1] / m : -e[1];
    const double l1 = upper ? e[0] / m : (e[0] - m * l2) / m;
    EXPECT_GE(l1, -1e-10 * scale);
    EXPECT_GE(l2, -1e-10 * scale);
    EXPECT_NEAR(e[2], upper ? -(l1 + l2) : -l1, 1e-9 * scale);
  }
}

TEST(MohrCoulombReturn, random_trials_return_onto_the_surface_along_the_flow_direction) {
  for (const double psi : {0.0, 10.0, 30.0}) {
    const Law law(rock(psi));
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-60 * kMPa, 20 * kMPa);
    int counts[4] = {0, 0, 0, 0};
    for (int n = 0; n < 20000; ++n) {
      const Stress4 trial{u(rng), u(rng), u(rng), 0.3 * u(rng)};
      const Result r = update(law, trial, {0, 0, 0});
      ++counts[static_cast<int>(r.kind)];
      const Vec3 ts = principal(trial), s = principal(r.stress);
      const double scale = std::abs(ts[0]) + std::abs(ts[1]) + std::abs(ts[2]) + law.sigma_c;
      if (r.kind == Return::kElastic) {
        EXPECT_LE(law.yield(ts), 0);
        for (int i = 0; i < 4; ++i) EXPECT_EQ(r.stress[i], trial[i]);
        continue;
      }
      EXPECT_GT(law.yield(ts), 0);
      EXPECT_NEAR(law.yield(s) / scale, 0, 1e-10) << "psi " << psi << " kind " << int(r.kind);
      if (r.kind == Return::kApex) {
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], law.apex, 1e-10 * scale);
      }
      expect_flow_rule(law, ts, s, r.kind);
    }
    // Every region is reached: this sample spans all four.
    for (int k = 0; k < 4; ++k) EXPECT_GT(counts[k], 20) << "psi " << psi << " region " << k;
  }
}

TEST(MohrCoulombReturn, constructed_plane_edge_and_apex_cases) {
  const Law law(rock());
  // Plane: a uniaxial compression beyond sigma_c, with distinct principals.
  Result r = update(law, {-1 * kMPa, -15 * kMPa, -30 * kMPa, 0}, {0, 0, 0});
  EXPECT_EQ(r.kind, Return::kPlane);
  // Edge s2 = s3 (triaxial compression): two equal compressive principals.
  r = update(law, {0, -40 * kMPa, -40 * kMPa, 0}, {0, 0, 0});
  EXPECT_EQ(r.kind, Return::kEdge);
  Vec3 s = principal(r.stress);
  EXPECT_NEAR(s[1], s[2], 1e-6);
  // Edge s1 = s2 (triaxial extension): two equal, least compressive.
  r = update(law, {0, 0, -40 * kMPa, 0}, {0, 0, 0});
  EXPECT_EQ(r.kind, Return::kEdge);
  s = principal(r.stress);
  EXPECT_NEAR(s[0], s[1], 1e-6);
  // Apex: all-round tension beyond sigma_c / (k - 1).
  r = update(law, {2 * law.apex, 2 * law.apex, 2 * law.apex, 0}, {0, 0, 0});
  EXPECT_EQ(r.kind, Return::kApex);
  EXPECT_NEAR(r.stress[0], law.apex, 1e-6);
}

TEST(MohrCoulombReturn, elastic_predictor_is_previous_plus_C_d_eps_below_the_surface) {
  const Law law(rock());
  const Stress4 previous{-10 * kMPa, -12 * kMPa, -5.5 * kMPa, 1 * kMPa};
  const Vec3 d{1e-5, -2e-5, 0.5e-5};
  const Result r = update(law, previous, d);
  ASSERT_EQ(r.kind, Return::kElastic);
  const double tr = d[0] + d[1];
  EXPECT_DOUBLE_EQ(r.stress[0], previous[0] + law.lambda * tr + 2 * law.mu * d[0]);
  EXPECT_DOUBLE_EQ(r.stress[1], previous[1] + law.lambda * tr + 2 * law.mu * d[1]);
  EXPECT_DOUBLE_EQ(r.stress[2], previous[2] + law.lambda * tr);
  EXPECT_DOUBLE_EQ(r.stress[3], previous[3] + 2 * law.mu * d[2]);
  EXPECT_NEAR(r.tangent[0][0], law.lambda + 2 * law.mu, 1e-6 * law.mu);
  EXPECT_NEAR(r.tangent[2][2], 2 * law.mu, 1e-6 * law.mu);
}

TEST(MohrCoulombReturn, result_rotates_with_the_frame) {
  const Law law(rock(10));
  const Stress4 a{-2 * kMPa, -35 * kMPa, -12 * kMPa, 0};
  const double t = 0.6, c = std::cos(t), s = std::sin(t);
  // The same state with the axes rotated by t.
  const Stress4 b{a[0] * c * c + a[1] * s * s, a[0] * s * s + a[1] * c * c, a[2],
                  (a[0] - a[1]) * c * s};
  const Result ra = update(law, a, {0, 0, 0}), rb = update(law, b, {0, 0, 0});
  const Stress4& x = ra.stress;
  EXPECT_NEAR(rb.stress[0], x[0] * c * c + x[1] * s * s - 2 * x[3] * c * s, 1e-6);
  EXPECT_NEAR(rb.stress[1], x[0] * s * s + x[1] * c * c + 2 * x[3] * c * s, 1e-6);
  EXPECT_NEAR(rb.stress[3], (x[0] - x[1]) * c * s + x[3] * (c * c - s * s), 1e-6);
  EXPECT_NEAR(rb.stress[2], x[2], 1e-6);
}

/// Central differences of a stress update `at(d_eps)` around d: the 3x3
/// d(s_xx, s_yy, s_xy)/d(e_xx, e_yy, e_xy); `same` is false when a sample
/// left the region `kind` (or `admissible(result)` failed): a kink between.
template <class Update, class Admissible>
Mat3 central_differences(Update&& at, const Vec3& d, Return kind, Admissible&& admissible,
                         bool& same) {
  const double h = 1e-9;
  const int idx[3] = {0, 1, 3};
  Mat3 fd{};
  same = true;
  for (int j = 0; j < 3; ++j) {
    Vec3 dp = d, dm = d;
    dp[j] += h;
    dm[j] -= h;
    const Result rp = at(dp);
    const bool ok = admissible();
    const Result rm = at(dm);
    same = same && ok && admissible() && rp.kind == kind && rm.kind == kind;
    for (int i = 0; i < 3; ++i) fd[i][j] = (rp.stress[idx[i]] - rm.stress[idx[i]]) / (2 * h);
  }
  return fd;
}

TEST(MohrCoulombReturn, tangent_matches_central_differences_in_every_region) {
  for (const double psi : {0.0, 20.0}) {
    const Law law(rock(psi));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-60 * kMPa, 20 * kMPa);
    int checked[4] = {0, 0, 0, 0};
    for (int n = 0; n < 3000; ++n) {
      const Stress4 prev{u(rng), u(rng), u(rng), 0.3 * u(rng)};
      const Vec3 d{1e-4 * (u(rng) / kMPa) / 60, 1e-4 * (u(rng) / kMPa) / 60, 2e-5};
      const Result r = update(law, prev, d);
      bool same_region = true;
      const Mat3 fd = central_differences([&](const Vec3& e) { return update(law, prev, e); }, d,
                                          r.kind, [] { return true; }, same_region);
      if (!same_region) continue;  // a kink of the map between the samples
      ++checked[static_cast<int>(r.kind)];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(r.tangent[i][j], fd[i][j], 2e-5 * (law.lambda + 2 * law.mu))
              << "psi " << psi << " kind " << int(r.kind) << " (" << i << "," << j << ")";
    }
    for (int k = 0; k < 3; ++k) EXPECT_GT(checked[k], 20) << "region " << k;
  }
}

// ---------------------------------------------------------------------------
// The strain-softening law (mohr_coulomb_softening.hpp).
// ---------------------------------------------------------------------------

Softening softening(double psi, double gamma_res) {
  Softening s;
  s.peak = rock(psi);
  s.residual = s.peak;
  s.residual.cohesion = 0.5 * kMPa;
  s.residual.friction_deg = 22;
  s.gamma_res = gamma_res;
  return s;
}

TEST(SofteningReturn, residual_equal_to_the_peak_is_the_perfectly_plastic_update_bit_for_bit) {
  Softening s = softening(10, 0.01);
  s.residual = s.peak;
  const SofteningLaw sl(s);
  const Law law(rock(10));
  EXPECT_FALSE(sl.softens());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-60 * kMPa, 20 * kMPa);
  for (int n = 0; n < 5000; ++n) {
    const Stress4 prev{u(rng), u(rng), u(rng), 0.3 * u(rng)};
    const Vec3 d{1e-4 * u(rng) / kMPa / 60, 1e-4 * u(rng) / kMPa / 60, 2e-5};
    double gamma = 0;
    const Result a = update(sl, prev, 0.003, d, gamma), b = update(law, prev, d);
    ASSERT_EQ(a.kind, b.kind);
    for (int i = 0; i < 4; ++i) ASSERT_EQ(a.stress[i], b.stress[i]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ASSERT_EQ(a.tangent[i][j], b.tangent[i][j]);
    EXPECT_GE(gamma, 0.003);
    if (a.kind == Return::kElastic) {
      EXPECT_EQ(gamma, 0.003);
    }
  }
}

/// The returned stress lies on the surface of the law at the new gamma_p,
/// gamma_p grew by the plastic shear strain of the return, and the plastic
/// strain follows the flow rule (Kuhn-Tucker) of that law.
TEST(SofteningReturn, stress_on_the_surface_of_the_law_at_the_updated_gamma) {
  for (const double gamma_res : {0.0, 1e-4, 0.02}) {
    const SofteningLaw sl(softening(15, gamma_res));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-60 * kMPa, 20 * kMPa), g(0, 0.03);
    int softening_interval = 0, residual = 0;
    for (int n = 0; n < 20000; ++n) {
      const Stress4 trial{u(rng), u(rng), u(rng), 0.3 * u(rng)};
      const double gamma_n = n % 3 == 0 ? 0.0 : g(rng);
      double gamma = -1;
      const Result r = update(sl, trial, gamma_n, {0, 0, 0}, gamma);
      const Law at_n = sl.at(gamma_n), at = sl.at(gamma);
      const Vec3 ts = principal(trial), s = principal(r.stress);
      const double scale = std::abs(ts[0]) + std::abs(ts[1]) + std::abs(ts[2]) + at_n.sigma_c;
      if (r.kind == Return::kElastic) {
        EXPECT_LE(at_n.yield(ts), 0);
        EXPECT_EQ(gamma, gamma_n);
        continue;
      }
      EXPECT_GT(at_n.yield(ts), 0);
      EXPECT_NEAR(at.yield(s) / scale, 0, 1e-10) << "gamma_res " << gamma_res;
      const Vec3 e = at.D_inv(Vec3{ts[0] - s[0], ts[1] - s[1], ts[2] - s[2]});
      EXPECT_NEAR(gamma - gamma_n, e[0] - e[2], 1e-12 + 1e-9 * (gamma - gamma_n));
      expect_flow_rule(at, ts, s, r.kind);
      if (gamma_res > 0 && gamma > 0 && gamma < gamma_res) ++softening_interval;
      if (gamma >= gamma_res) ++residual;
    }
    // Both branches are exercised (the interval only where gamma_res exceeds
    // most returns' plastic strain).
    if (gamma_res >= 0.02) {
      EXPECT_GT(softening_interval, 100);
    }
    EXPECT_GT(residual, 100) << gamma_res;
  }
}

TEST(SofteningReturn, brittle_law_drops_to_the_residual_at_first_yield) {
  const SofteningLaw sl(softening(0, 0.0));
  // Just beyond the peak in uniaxial-like compression: the residual surface.
  const Law& peak = sl.peak();
  const double s3 = -(peak.sigma_c + 0.01 * kMPa);
  double gamma = 0;
  const Result r = update(sl, {0, -5 * kMPa, s3, 0}, 0.0, {0, 0, 0}, gamma);
  ASSERT_EQ(r.kind, Return::kPlane);
  EXPECT_GT(gamma, 0);
  EXPECT_NEAR(sl.residual().yield(principal(r.stress)) / kMPa, 0, 1e-9);
  EXPECT_GT(peak.yield(principal({0, -5 * kMPa, s3, 0})), 0);
}

TEST(SofteningReturn, tangent_matches_central_differences_while_softening) {
  for (const double psi : {0.0, 15.0}) {
    const SofteningLaw sl(softening(psi, 0.01));
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(-60 * kMPa, 20 * kMPa), g(0, 0.01);
    int checked[4] = {0, 0, 0, 0};
    for (int n = 0; n < 6000; ++n) {
      const Stress4 prev{u(rng), u(rng), u(rng), 0.3 * u(rng)};
      const double gamma_n = n % 2 ? 0.0 : g(rng);
      const Vec3 d{1e-4 * (u(rng) / kMPa) / 60, 1e-4 * (u(rng) / kMPa) / 60, 2e-5};
      double gamma = 0;
      const Result r = update(sl, prev, gamma_n, d, gamma);
      if (!(gamma > 0 && gamma < 0.01)) continue;  // the interval where it softens
      bool same = true;
      double g_sample = 0;  // each sample must stay in the softening interval
      const Mat3 fd =
          central_differences([&](const Vec3& e) { return update(sl, prev, gamma_n, e, g_sample); },
                              d, r.kind, [&] { return g_sample < 0.01; }, same);
      if (!same) continue;
      ++checked[static_cast<int>(r.kind)];
      const double E = sl.peak().lambda + 2 * sl.peak().mu;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(r.tangent[i][j], fd[i][j], 2e-5 * E)
              << "psi " << psi << " kind " << int(r.kind) << " (" << i << "," << j << ")";
    }
    std::printf("  psi %.0f: tangent checked at %d plane, %d edge, %d apex points\n", psi,
                checked[1], checked[2], checked[3]);
    EXPECT_GT(checked[1], 20);
    EXPECT_GT(checked[2], 20);
  }
}

}  // namespace
}  // namespace rockfdem::insitu::mc
