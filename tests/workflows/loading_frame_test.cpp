// The intact box's compression under the in-situ stress (loading_frame):
// its strain loaded back through Hooke's law gives the in-situ stress, in
// plane strain and plane stress; the base and the centre line stay put;
// the seed tunnel's figures match a hand calculation; a loading that is
// not a uniform stress on a box has none.
#include "outputs/loading_frame.hpp"

#include <gtest/gtest.h>

namespace rockfdem::workflows {
namespace {

Scene seed_box(bool plane_stress) {
  Scene s;
  s.plane_stress = plane_stress;
  s.materials[mesh::kRock].young = 3e9;
  s.materials[mesh::kRock].poisson = 0.25;
  s.insitu.sigma_h = 18.2e6, s.insitu.sigma_v = 11.4e6;
  s.mesh.domain = {80, 80, 0, 0};
  return s;
}

// Compression-positive stress of a strain (compression positive).
std::array<double, 2> stress(const LoadingStrain& e, double E, double nu, bool plane_stress) {
  if (plane_stress)
    return {E / (1 - nu * nu) * (e.xx + nu * e.yy), E / (1 - nu * nu) * (e.yy + nu * e.xx)};
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  return {lambda * (e.xx + e.yy) + 2 * mu * e.xx, lambda * (e.xx + e.yy) + 2 * mu * e.yy};
}

TEST(LoadingFrame, the_strain_carries_the_in_situ_stress) {
  for (bool plane_stress : {false, true}) {
    const std::optional<LoadingStrain> e = loading_strain(seed_box(plane_stress));
    ASSERT_TRUE(e);
    const std::array<double, 2> s = stress(*e, 3e9, 0.25, plane_stress);
    EXPECT_NEAR(s[0], 18.2e6, 1e-6) << plane_stress;
    EXPECT_NEAR(s[1], 11.4e6, 1e-6) << plane_stress;
  }
}

// Plane strain by hand: eps_yy = ((1 - nu^2) 11.4 - nu (1 + nu) 18.2) / 3000
// = (10.6875 - 5.6875) / 3000 = 1/600; eps_xx = (17.0625 - 3.5625) / 3000
// = 0.0045. The crown 4.4 m above the centre, 44.4 m above the base, moves
// down 74 mm; the floor 4.4 m below it, 59.3 mm.
TEST(LoadingFrame, the_seed_box_settles_on_its_base) {
  const std::optional<LoadingStrain> e = loading_strain(seed_box(false));
  ASSERT_TRUE(e);
  EXPECT_NEAR(e->yy, 1.0 / 600, 1e-15);
  EXPECT_NEAR(e->xx, 0.0045, 1e-15);
  EXPECT_EQ(loading_displacement(*e, 0, -40)[1], 0.0);
  EXPECT_EQ(loading_displacement(*e, 0, 17)[0], 0.0);
  EXPECT_NEAR(loading_displacement(*e, 0, 4.4)[1], -0.074, 1e-12);
  EXPECT_NEAR(loading_displacement(*e, 0, -4.4)[1], -35.6 / 600, 1e-12);
  // Walls move inward alike.
  EXPECT_NEAR(loading_displacement(*e, 5.65, 0)[0], -loading_displacement(*e, -5.65, 0)[0], 1e-15);
  EXPECT_LT(loading_displacement(*e, 5.65, 0)[0], 0);
  // A box off the opening's centre holds its own base and centre line.
  Scene off = seed_box(false);
  off.mesh.domain.center_x = 3, off.mesh.domain.center_y = -10;
  const LoadingStrain o = *loading_strain(off);
  EXPECT_EQ(loading_displacement(o, 3, -50)[0], 0.0);
  EXPECT_EQ(loading_displacement(o, 3, -50)[1], 0.0);
}

TEST(LoadingFrame, none_without_a_uniform_stress_on_a_box) {
  Scene s = seed_box(false);
  s.engine.gravity = 9.81;
  EXPECT_FALSE(loading_strain(s));
  s = seed_box(false), s.insitu.unit_weight = 25e3;
  EXPECT_FALSE(loading_strain(s));
  s = seed_box(false), s.insitu.angle_deg = 30;
  EXPECT_FALSE(loading_strain(s));
  s = seed_box(false), s.insitu.sigma_h = s.insitu.sigma_v = 0;
  EXPECT_FALSE(loading_strain(s));
}

}  // namespace
}  // namespace rockfdem::workflows
