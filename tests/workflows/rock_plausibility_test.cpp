// The rock set's plausibility figures (outputs/rock_plausibility.hpp) on
// constructed rocks: the Mohr-Coulomb UCS in closed form, a soft rock an
// engineer accepts with no warning, and the field back-analysis rock of
// E 0.40 GPa and c 21.7 MPa (UCS/E 0.19) flagged with its figure and range.
#include "outputs/rock_plausibility.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockfdem::workflows;

namespace {

MaterialSpec rock(double young, double ft, double c, double phi_deg) {
  MaterialSpec m;
  m.young = young;
  m.tensile_strength = ft;
  m.cohesion = c;
  m.friction_angle = phi_deg;
  return m;
}

const PlausibilityFigure* find(const RockPlausibilityFigures& p, const std::string& name) {
  for (const PlausibilityFigure& f : p.figures)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace

// 2 c cos(phi) / (1 - sin(phi)): 2c at phi = 0; 2 c sqrt(3) at 30 deg;
// 2 c tan(45 + phi/2) in the other form, at 40 deg.
TEST(RockPlausibility, mohr_coulomb_ucs_is_the_closed_form) {
  EXPECT_DOUBLE_EQ(mohr_coulomb_ucs(3e6, 0), 6e6);
  EXPECT_NEAR(mohr_coulomb_ucs(3e6, 30), 6e6 * std::sqrt(3.0), 1e-6);
  EXPECT_NEAR(mohr_coulomb_ucs(1e6, 40), 2e6 * std::tan((45 + 20) * M_PI / 180), 1e-6);
}

// The generic soft rock (scenes/tunnel-seed-generic-rock.toml): UCS 10.4 MPa, UCS/E 0.0035,
// ft/UCS 0.096, h/l_ch 0.58.
TEST(RockPlausibility, a_soft_rock_within_every_range_gives_no_warning) {
  const RockPlausibilityFigures p = rock_plausibility(rock(3e9, 1e6, 3e6, 30), 0.58);
  ASSERT_TRUE(p.ucs_Pa);
  ASSERT_EQ(p.figures.size(), 3u);
  EXPECT_NEAR(find(p, "ucs_over_young")->value, 6e6 * std::sqrt(3.0) / 3e9, 1e-15);
  EXPECT_NEAR(find(p, "ft_over_ucs")->value, 1e6 / (6e6 * std::sqrt(3.0)), 1e-15);
  EXPECT_DOUBLE_EQ(find(p, "h_over_l_ch")->value, 0.58);
  for (const PlausibilityFigure& f : p.figures) EXPECT_TRUE(f.in_range) << f.name;
  EXPECT_TRUE(plausibility_warnings(p).empty());
}

// An elastic back-analysis's rock: UCS 75 MPa on E 0.40 GPa.
TEST(RockPlausibility, a_back_analysis_rock_is_flagged_with_its_figure_and_range) {
  const RockPlausibilityFigures p = rock_plausibility(rock(0.403e9, 2e6, 21.66e6, 30), 17);
  EXPECT_NEAR(*p.ucs_Pa / 1e6, 75.0, 0.1);
  EXPECT_FALSE(find(p, "ucs_over_young")->in_range);
  EXPECT_NEAR(find(p, "ucs_over_young")->value, 0.186, 0.001);
  EXPECT_FALSE(find(p, "ft_over_ucs")->in_range);  // 0.027, below Hoek-Brown's 1/33
  EXPECT_FALSE(find(p, "h_over_l_ch")->in_range);
  const std::vector<std::string> w = plausibility_warnings(p);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NE(w[0].find("ucs_over_young = 0.186 is outside [0.001, 0.01]"), std::string::npos)
      << w[0];
  EXPECT_NE(w[2].find("h_over_l_ch = 17"), std::string::npos) << w[2];
}

// Each bound is a bound: just inside passes, just outside fails.
TEST(RockPlausibility, each_range_edge_separates_in_from_out) {
  const double ucs = mohr_coulomb_ucs(1e6, 0);  // 2 MPa
  EXPECT_TRUE(
      find(rock_plausibility(rock(ucs / 0.0099, 0.1e6, 1e6, 0), 0), "ucs_over_young")->in_range);
  EXPECT_FALSE(
      find(rock_plausibility(rock(ucs / 0.0101, 0.1e6, 1e6, 0), 0), "ucs_over_young")->in_range);
  EXPECT_FALSE(
      find(rock_plausibility(rock(ucs / 0.00099, 0.1e6, 1e6, 0), 0), "ucs_over_young")->in_range);
  EXPECT_TRUE(find(rock_plausibility(rock(1e9, 0.49e6, 1e6, 0), 0), "ft_over_ucs")->in_range);
  EXPECT_FALSE(find(rock_plausibility(rock(1e9, 0.51e6, 1e6, 0), 0), "ft_over_ucs")->in_range);
  EXPECT_FALSE(find(rock_plausibility(rock(1e9, 0.05e6, 1e6, 0), 0), "ft_over_ucs")->in_range);
  EXPECT_TRUE(find(rock_plausibility(rock(1e9, 0.1e6, 1e6, 0), 1.0), "h_over_l_ch")->in_range);
  EXPECT_FALSE(find(rock_plausibility(rock(1e9, 0.1e6, 1e6, 0), 1.01), "h_over_l_ch")->in_range);
}

// Without cohesion there is no UCS to judge by: only h / l_ch, if any.
TEST(RockPlausibility, a_rock_without_cohesion_has_no_ucs_figures) {
  const RockPlausibilityFigures p = rock_plausibility(rock(1e9, 1e6, 0, 30), 0.5);
  EXPECT_FALSE(p.ucs_Pa);
  ASSERT_EQ(p.figures.size(), 1u);
  EXPECT_EQ(p.figures[0].name, "h_over_l_ch");
  EXPECT_TRUE(rock_plausibility(rock(1e9, 0, 0, 30), 0).figures.empty());
}
