// The convergence-confinement equilibrium (run/support_equilibrium.hpp):
// where a support line meets the ground's curve, against hand-solved
// straight lines.
#include "record/support_equilibrium.hpp"

#include <gtest/gtest.h>

using namespace rockfdem::workflows;

namespace {

// An implicit-stage point whose two key points average to (u, p).
GroundReactionPoint implicit_point(double u_mm, double p_Pa) {
  GroundReactionPoint g;
  g.key_points["vault"] = {u_mm - 1, p_Pa + 1e5, 1e7};
  g.key_points["invert"] = {u_mm + 1, p_Pa - 1e5, 1e7};
  return g;
}

// Installed at u0 [mm]; K [MPa/mm] and p_max [MPa].
ConvergenceConfinementFigures one_line(double u0, double k_mpa_per_mm, double p_max_mpa) {
  ConvergenceConfinementFigures c;
  c.install_radial_mm = u0;
  c.support.push_back(
      {"shotcrete", 1e6 * p_max_mpa, 1e9 * k_mpa_per_mm, p_max_mpa / k_mpa_per_mm, {}});
  return c;
}

// The elastic curve through (0 mm, 10 MPa) and (10 mm, 5 MPa), carried on
// to (20 mm, 0).
GroundCurve elastic_curve() {
  const std::optional<GroundCurve> g =
      ground_curve({implicit_point(0, 10e6), implicit_point(10, 5e6)}, std::nullopt);
  EXPECT_TRUE(g.has_value());
  return *g;
}

}  // namespace

// The curve is the key points' mean, and the elastic one is straight on to
// p = 0: (20 mm, 0) by hand.
TEST(SupportEquilibrium, elastic_curve_is_the_mean_carried_on_to_zero) {
  const GroundCurve g = elastic_curve();
  EXPECT_EQ(g.source, "elastic");
  EXPECT_TRUE(g.extended_to_zero);
  ASSERT_EQ(g.radial_mm.size(), 3u);
  EXPECT_NEAR(g.radial_mm[1], 10.0, 1e-12);
  EXPECT_NEAR(g.pressure_Pa[1], 5e6, 1e-6);
  EXPECT_NEAR(g.radial_mm[2], 20.0, 1e-12);
  EXPECT_EQ(g.pressure_Pa[2], 0.0);
}

// Installed at 10 mm, K = 0.5 MPa/mm: 5 - 0.5 du = 0.5 du, du = 5 mm,
// p = 2.5 MPa; p_max 4 MPa gives a factor of safety of 1.6.
TEST(SupportEquilibrium, elastic_line_meets_the_curve_where_hand_solved) {
  const auto eq = support_equilibria(one_line(10, 0.5, 4), elastic_curve());
  ASSERT_EQ(eq.size(), 1u);
  ASSERT_TRUE(eq[0].found) << eq[0].note;
  EXPECT_NEAR(eq[0].radial_mm, 15.0, 1e-9);
  EXPECT_NEAR(eq[0].pressure_Pa, 2.5e6, 1e-3);
  ASSERT_TRUE(eq[0].factor_of_safety.has_value());
  EXPECT_NEAR(*eq[0].factor_of_safety, 1.6, 1e-9);
}

// p_max 1 MPa is reached 2 mm after installation; the ground falls to 1 MPa
// at 18 mm: equilibrium on the plateau, the support yielding (factor 1).
TEST(SupportEquilibrium, a_weak_line_meets_the_curve_on_its_plateau) {
  const auto eq = support_equilibria(one_line(10, 0.5, 1), elastic_curve());
  ASSERT_TRUE(eq[0].found) << eq[0].note;
  EXPECT_NEAR(eq[0].radial_mm, 18.0, 1e-9);
  EXPECT_NEAR(eq[0].pressure_Pa, 1e6, 1e-3);
  EXPECT_EQ(eq[0].factor_of_safety, 1.0);
  EXPECT_NE(eq[0].note.find("yields"), std::string::npos) << eq[0].note;
}

// Installed after the ground came to rest (25 mm > 20 mm): not loaded.
TEST(SupportEquilibrium, support_installed_after_the_ground_stands_carries_nothing) {
  const auto eq = support_equilibria(one_line(25, 0.5, 4), elastic_curve());
  ASSERT_TRUE(eq[0].found);
  EXPECT_EQ(eq[0].pressure_Pa, 0.0);
  EXPECT_FALSE(eq[0].factor_of_safety.has_value());
  EXPECT_NE(eq[0].note.find("not loaded"), std::string::npos) << eq[0].note;
}

// A Mohr-Coulomb release that stops at 3 MPa (the continuum gave way) is
// preferred to the implicit points and not carried on: a stiff line meets
// it, a soft one does not.
TEST(SupportEquilibrium, a_collapsing_continuum_curve_is_met_or_said_to_end_above) {
  CounterpartComparison mc;
  mc.model = "mohr_coulomb";
  for (const auto& [u, p] : std::vector<std::pair<double, double>>{{0, 10e6}, {10, 3e6}}) {
    ContinuumGroundReactionPoint x;
    x.key_points["vault"] = {u, p};
    mc.ground_reaction.push_back(x);
  }
  const std::optional<GroundCurve> g =
      ground_curve({implicit_point(0, 10e6), implicit_point(10, 5e6)}, mc);
  ASSERT_TRUE(g.has_value());
  EXPECT_EQ(g->source, "mohr_coulomb");
  EXPECT_FALSE(g->extended_to_zero);
  // Installed at 5 mm (6.5 MPa on the curve, falling 0.7 MPa/mm), K = 1.3
  // MPa/mm: 6.5 - 0.7 du = 1.3 du, du = 3.25 mm, p = 4.225 MPa.
  auto eq = support_equilibria(one_line(5, 1.3, 10), *g);
  ASSERT_TRUE(eq[0].found) << eq[0].note;
  EXPECT_NEAR(eq[0].radial_mm, 8.25, 1e-9);
  EXPECT_NEAR(eq[0].pressure_Pa, 4.225e6, 1e-3);
  eq = support_equilibria(one_line(5, 0.1, 10), *g);
  EXPECT_FALSE(eq[0].found);
  EXPECT_NE(eq[0].note.find("ends at p = 3 MPa"), std::string::npos) << eq[0].note;
}
