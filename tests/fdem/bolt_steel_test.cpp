// The bolt steel through the engine: a bolt bar (one row of cells, every
// triangle a bolt triangle, bolt-steel crack elements across and along it)
// pulled in tension must reproduce the seed's bilinear law (eqs. 4-7) with
// the calibrated material (bolt_steel.hpp); one crack element slid must fail
// brittly at tau_y; the row spacing must scale the force (eq. 20).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/bolt_output.hpp"
#include "rockfdem/fdem/bolt_sections.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kLength = 0.4, kDiameter = 0.025;

struct CurvePoint {
  double strain, stress;  ///< bar strain u / L; steel stress = F / (d f)
};

struct BarRun {
  std::vector<CurvePoint> curve;
  double yield_strain = -1, yield_stress = -1;  ///< first step with a yielding crack
  double break_strain = -1;                     ///< first step with a broken crack
  double scale = 1;                             ///< f = 1 / s_b
  double profile_stress = 0;                    ///< bolt_axial_profile mean at the yield step
  double final_stress = 0;                      ///< 2000 steps after the break
  /// bolt_sections and the grip's steel stress at half eps_y, at the yield
  /// step, just after the break and at the end.
  std::vector<BoltStation> half_yield, at_yield, at_break, final_sections;
  double half_yield_stress = 0, half_yield_strain = 0;
};

double eps_u_elastic(const BoltSteel& s) { return s.yield_strength / s.young; }

/// A 0.4 m bar of 4 cells 100 x 25 mm (8 triangles, 3 cracks across, 4
/// diagonals 14 deg off the axis), nu = 0 so it is uniaxial whatever the
/// ends do; left end held, right end pulled at 0.1 m/s (strain rate
/// 0.25/s) with local damping 0.7, both ends held laterally.
BarRun pull_bar(double row_spacing, const BoltSteel& steel) {
  RectangleSpec spec;
  spec.width = kLength;
  spec.height = kDiameter;
  spec.nx = 4;
  spec.ny = 1;
  spec.fracture = false;  // plan_bolts allows it in the bolt triangles
  Material base = test::rock();
  base.poisson = 0;
  ModelInput in = structured_rectangle(spec, base);
  BoundaryCondition left, right;
  left.tag = kTagLeft;
  left.x = left.y = Constraint::kFixed;
  right.tag = kTagRight;
  right.x = Constraint::kVelocity;
  right.y = Constraint::kFixed;
  right.vx = 0.1;  // 0.5 m/s already overshoots the hardening branch by 7% (dynamic)
  in.boundary_conditions = {left, right};
  in.damping.local = 0.7;
  BoltSpec bolt;
  bolt.bolt = {{0, kDiameter / 2}, {kLength, kDiameter / 2}, kDiameter};
  bolt.row_spacing = row_spacing;
  bolt.steel = steel;
  bolt.grout = base;
  BoltPlan plan = plan_bolts(in, {bolt});
  Engine e(in);
  e.set_threads(1);
  install_bolts(e, plan);
  BarRun r;
  r.scale = plan.steel[0].scale;
  const BoltCracks cracks = bolt_cracks(e, plan, 0);
  EXPECT_EQ(cracks.steel.size(), 7u);
  EXPECT_TRUE(cracks.grout.empty());
  const double eps_u = steel.yield_strength / steel.young +
                       (steel.ultimate_strength - steel.yield_strength) / steel.tangent_modulus;
  // The pull velocity ramps up over the first 40% of the elastic range, so
  // no stress wave rings on the elastic branch.
  const double v = right.vx, ramp_time = 0.4 * eps_u_elastic(steel) * kLength / v;
  double u = 0;
  long after_break = 0;
  while (after_break < 2000 && u / kLength < 1.2 * eps_u) {
    right.vx = v * std::min(1.0, (e.time() + 10 * e.dt()) / ramp_time);
    e.set_boundary_conditions({left, right});
    e.run(20);
    u += 20 * e.dt() * right.vx;
    if (r.break_strain >= 0) {
      after_break += 20;
      continue;
    }
    const double strain = u / kLength;
    const double stress = e.boundary_force(kTagRight)[0] / kDiameter / r.scale;
    r.curve.push_back({strain, stress});
    if (r.half_yield.empty() && strain >= 0.5 * eps_u_elastic(steel)) {
      r.half_yield = bolt_sections(e, plan, 0);
      r.half_yield_stress = stress;
      r.half_yield_strain = strain;
    }
    const BoltCounts counts = bolt_counts(e, plan, 0);
    if (r.yield_strain < 0 && counts.yielding > 0) {
      r.yield_strain = strain;
      r.yield_stress = stress;
      r.at_yield = bolt_sections(e, plan, 0);
      for (const auto& s : bolt_axial_profile(e, plan, 0)) r.profile_stress += s.steel_stress / 8;
    }
    if (counts.broken > 0) {
      r.break_strain = strain;
      r.at_break = bolt_sections(e, plan, 0);
    }
  }
  r.final_stress = e.boundary_force(kTagRight)[0] / kDiameter / r.scale;
  r.final_sections = bolt_sections(e, plan, 0);
  return r;
}

/// Stress on the curve at a strain (linear interpolation).
double stress_at(const std::vector<CurvePoint>& c, double strain) {
  for (std::size_t i = 1; i < c.size(); ++i)
    if (c[i].strain >= strain) {
      const double w = (strain - c[i - 1].strain) / (c[i].strain - c[i - 1].strain);
      return c[i - 1].stress + w * (c[i].stress - c[i - 1].stress);
    }
  return NAN;
}

// Yield at (eps_y, sigma_y) = (0.002, 400 MPa) and hardening slope ET =
// 2 GPa between 30% and 70% of the hardening branch, within 0.5%; the bar
// breaks at eps_u = 0.052 (1%). The first yielding crack is seen at most 20
// steps late (5e-6 strain, 0.25% of eps_y): its strain is held to 1%, and the
// curve itself must pass through (eps_y, sigma_y) within 0.5%.
TEST(BoltSteel, bar_in_tension_reproduces_the_bilinear_law) {
  const BoltSteel steel;
  const BarRun r = pull_bar(1.0, steel);
  const double eps_y = steel.yield_strength / steel.young;
  const double eps_u =
      eps_y + (steel.ultimate_strength - steel.yield_strength) / steel.tangent_modulus;
  ASSERT_GT(r.yield_strain, 0);
  ASSERT_GT(r.break_strain, 0);
  std::printf("yield at strain %.6f stress %.2f MPa (profile %.2f), break at %.5f\n",
              r.yield_strain, r.yield_stress / 1e6, r.profile_stress / 1e6, r.break_strain);
  EXPECT_NEAR(r.yield_stress, steel.yield_strength, 0.005 * steel.yield_strength);
  EXPECT_NEAR(r.profile_stress, steel.yield_strength, 0.005 * steel.yield_strength);
  EXPECT_NEAR(r.yield_strain, eps_y, 0.01 * eps_y);
  EXPECT_NEAR(stress_at(r.curve, eps_y), steel.yield_strength, 0.005 * steel.yield_strength);
  const double e1 = eps_y + 0.3 * (eps_u - eps_y), e2 = eps_y + 0.7 * (eps_u - eps_y);
  const double slope = (stress_at(r.curve, e2) - stress_at(r.curve, e1)) / (e2 - e1);
  std::printf("hardening slope %.4f GPa for ET = %.4f GPa\n", slope / 1e9,
              steel.tangent_modulus / 1e9);
  EXPECT_NEAR(slope, steel.tangent_modulus, 0.005 * steel.tangent_modulus);
  EXPECT_NEAR(r.break_strain, eps_u, 0.01 * eps_u);
  // Brittle at the end: no load once broken.
  EXPECT_LT(std::fabs(r.final_stress), 0.05 * steel.ultimate_strength);
}

// Eq. 20: at s_b = 2 the bar carries half the force at the same strain, in
// the elastic range and in hardening (0.5%); the steel stress (F / (d f))
// is the same.
TEST(BoltSteel, doubling_row_spacing_halves_the_force) {
  const BoltSteel steel;
  const BarRun one = pull_bar(1.0, steel), two = pull_bar(2.0, steel);
  EXPECT_DOUBLE_EQ(two.scale, 0.5);
  const double eps_y = steel.yield_strength / steel.young;
  for (double strain : {0.5 * eps_y, 10 * eps_y}) {
    const double f1 = stress_at(one.curve, strain) * one.scale;
    const double f2 = stress_at(two.curve, strain) * two.scale;
    std::printf("strain %.4f: force ratio %.5f\n", strain, f2 / f1);
    EXPECT_NEAR(f2 / f1, 0.5, 0.0025) << "strain " << strain;
  }
}

int worst_state(const std::vector<BoltStation>& st) {
  int worst = 0;
  for (const BoltStation& s : st) worst = std::max(worst, s.state);
  return worst;
}

// A bar between two grips opened by u (bolt_sections.hpp). Every
// station's section force, in N per bar F = sigma pi d^2 / 4, equals the
// grip's (sigma = F_grip / (d f); no bond, so constant along the bar)
// within 0.5%:
// - at u = eps_y L / 2, every station elastic (state 0), and F = k u with
//   k = E pi d^2 / 4 / L within 2.5% (the steel crack elements' pre-peak
//   curve stiffens the bar below yield, its secant reaching E at yield:
//   1.9% above k u measured);
// - at the first yielding step, F = fy pi d^2 / 4 = 196.35 kN (0.5%), a
//   station in state 1;
// then a station reads 2 after the break, and 2000 steps later every
// section carries less than 5% of fu pi d^2 / 4.
TEST(BoltSteel, sections_read_the_grip_force_yield_and_break) {
  const BoltSteel steel;
  const BarRun r = pull_bar(1.0, steel);
  const double area = M_PI * kDiameter * kDiameter / 4;
  ASSERT_EQ(r.half_yield.size(), 4u);  // 0.4 m over 100 mm cells
  ASSERT_FALSE(r.at_yield.empty());
  ASSERT_FALSE(r.at_break.empty());
  const double k_u = steel.young * r.half_yield_strain * area;  // k_steel x opening, k = E A / L
  for (const BoltStation& s : r.half_yield) {
    std::printf("half yield: station %.3f m %.3f kN, E A u / L = %.3f kN\n", s.station,
                s.bar_force / 1e3, k_u / 1e3);
    EXPECT_NEAR(s.bar_force, k_u, 0.025 * k_u);
    EXPECT_NEAR(s.bar_force, r.half_yield_stress * area, 0.005 * r.half_yield_stress * area);
    EXPECT_EQ(s.state, 0);
  }
  EXPECT_EQ(worst_state(r.at_yield), 1);
  const double fy = steel.yield_strength * area;
  for (const BoltStation& s : r.at_yield) {
    std::printf("yield step: station %.3f m %.2f kN (fy A = %.2f kN), state %d\n", s.station,
                s.bar_force / 1e3, fy / 1e3, s.state);
    EXPECT_NEAR(s.bar_force, r.yield_stress * area, 0.005 * fy);
    EXPECT_NEAR(s.bar_force, fy, 0.005 * fy);
  }
  EXPECT_EQ(worst_state(r.at_break), 2);
  for (const BoltStation& s : r.final_sections)
    EXPECT_LT(std::fabs(s.bar_force), 0.05 * steel.ultimate_strength * area);
}

/// Slides the upper triangle of a two-triangle pair along the crack by u,
/// one step per increment; returns the shear traction tau(u) [Pa].
std::vector<std::array<double, 2>> slide(Engine& e, double h, double u_max, int n) {
  const auto top = e.triangle_nodes(1), bottom = e.triangle_nodes(0);
  std::array<double, 12> ref{};
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 2; ++d) {
      ref[2 * k + d] = e.positions()[2 * top[k] + d];
      ref[6 + 2 * k + d] = e.positions()[2 * bottom[k] + d];
    }
  std::vector<std::array<double, 2>> out;
  for (int i = 1; i <= n && e.crack_state(0) != CrackState::kBroken; ++i) {
    const double u = u_max * i / n;
    for (int k = 0; k < 3; ++k) {
      e.set_node_state(top[k], ref[2 * k] + u, ref[2 * k + 1], 0, 0);
      e.set_node_state(bottom[k], ref[6 + 2 * k], ref[6 + 2 * k + 1], 0, 0);
    }
    e.step();
    double fx = 0;
    for (int node : top) fx += e.node_force(node)[0];
    out.push_back({u, -fx / h});
  }
  return out;
}

// Shear: the steel crack carries tau_y at sp = 2 h tau_y / pt (0.5%), then
// drops brittly, (1 - D)^2 tau_y, to zero at sr = sp + 3 GfII / tau_y (1%):
// at the middle of the decay a quarter of tau_y is left.
TEST(BoltSteel, shear_fails_brittly_at_tau_y) {
  const double h = 0.025;
  BoltSteel steel;
  steel.gf_II = 2e3;
  const Material m = row_spacing_scaled_steel(steel, 1.0, 0.1);
  Engine e(test::two_triangles(h, m));
  const CrackConstants k = make_crack_constants(m);
  const double tau_y = steel.shear_yield_strength;
  const double sp = 2 * h * tau_y / k.pt, range = 3 * steel.gf_II / tau_y;
  const auto curve = slide(e, h, 1.5 * (sp + range), 4000);
  ASSERT_EQ(e.crack_state(0), CrackState::kBroken);
  double peak = 0, u_peak = 0;
  for (const auto& p : curve)
    if (std::fabs(p[1]) > peak) {
      peak = std::fabs(p[1]);
      u_peak = p[0];
    }
  std::printf("shear peak %.2f MPa at %.3e m (sp %.3e), break at %.4e m (sr %.4e)\n", peak / 1e6,
              u_peak, sp, curve.back()[0], sp + range);
  EXPECT_NEAR(peak, tau_y, 0.005 * tau_y);
  EXPECT_NEAR(u_peak, sp, 0.01 * sp + 1.5 * (sp + range) / 4000);
  EXPECT_NEAR(curve.back()[0], sp + range, 0.01 * range);
  for (const auto& p : curve) {
    if (std::fabs(p[0] - (sp + 0.5 * range)) < 1.5 * (sp + range) / 4000) {
      EXPECT_NEAR(std::fabs(p[1]), 0.25 * tau_y, 0.01 * tau_y);
    }
  }
  EXPECT_EQ(e.crack_mode(0), FailureMode::kModeII);
}

// A strip whose inner crack elements lie at 45 deg to the axis would fail
// in shear (tau = sigma / 2 > tau_y = 0.4 sigma_y) before yielding: refused.
TEST(BoltSteel, strip_that_would_fail_in_shear_is_refused) {
  RectangleSpec spec;
  spec.width = 0.1;
  spec.height = 0.025;
  spec.nx = 4;
  spec.ny = 1;
  ModelInput in = structured_rectangle(spec, test::rock());
  BoltSpec bolt;
  bolt.bolt = {{0, 0.0125}, {0.1, 0.0125}, 0.025};
  bolt.steel.shear_yield_strength = 0.4 * bolt.steel.yield_strength;
  EXPECT_THROW(plan_bolts(in, {bolt}), InputError);
}

}  // namespace
}  // namespace rockfdem::fdem
