// The Mohr-Coulomb return mapping (insitu/src/mohr_coulomb.hpp) on its own:
// every returned stress on the surface, the plastic corrector along the flow
// direction with non-negative multipliers (the Kuhn-Tucker conditions, checked
// independently of how the return chose its region), the plane, edge and apex
// cases, frame invariance, and the tangent against finite differences.
#include "mohr_coulomb.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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
      const double h = 1e-9;
      bool same_region = true;
      Mat3 fd{};
      for (int j = 0; j < 3; ++j) {
        Vec3 dp = d, dm = d;
        dp[j] += h;
        dm[j] -= h;
        const Result rp = update(law, prev, dp), rm = update(law, prev, dm);
        same_region = same_region && rp.kind == r.kind && rm.kind == r.kind;
        const int idx[3] = {0, 1, 3};
        for (int i = 0; i < 3; ++i) fd[i][j] = (rp.stress[idx[i]] - rm.stress[idx[i]]) / (2 * h);
      }
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

}  // namespace
}  // namespace rockfdem::insitu::mc
