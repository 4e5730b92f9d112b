// Section forces along a bolt (bolt_sections.hpp) against beam theory: a
// strip bent and stretched has triangles in tension on one side and in
// compression on the other, but the force through any section is E A eps.
#include "rockfdem/fdem/bolt_sections.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rockfdem/fdem/bolt_output.hpp"
#include "rockfdem/fdem/constants.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

// A bolt of d = 50 mm on a 0.4 m strip of 8 x 2 cells (50 x 25 mm), both
// rows its own (long sides on mesh lines), nu = 0 (uniaxial). Every node
// (x, y) is put where a stretched, bent beam takes it: the axis bent to a
// circle of curvature kappa and stretched by eps, the fibre at y' = y - yc
// on its normal,
//   p = c(x) + y' n(kappa x),  c(x) = (1 + eps) (sin kappa x, 1 - cos kappa x) / kappa,
// so the fibre strain is eps - kappa y' exactly (eps = 1e-4, kappa = 0.01 /m:
// from -1.5e-4 on the top edge to 3.5e-4 on the bottom). Beam theory: the
// bending moment carries no axial force, so every station's steel stress
// is E_tri eps (E_tri the strip's uniaxial modulus over f) and its bar force
// E_tri eps pi d^2 / 4, within 1%: the cuts are normal to the bolt's
// original axis, and the far cells, turned by kappa x = 4 mrad, meet them
// askew (0.1 mm at the strip's edges), which leaves a part of the bending
// stress in the section (0.23% measured at 0.375 m; 0.9% with kappa =
// 0.02). The triangles themselves read both signs.
TEST(BoltSections, bending_cancels_and_each_section_carries_EA_eps) {
  RectangleSpec spec;
  spec.width = 0.4;
  spec.height = 0.05;
  spec.nx = 8;
  spec.ny = 2;
  spec.fracture = false;
  Material base = test::rock();
  base.poisson = 0;
  ModelInput in = structured_rectangle(spec, base);
  BoltSpec bolt;
  bolt.bolt = {{0, 0.025}, {0.4, 0.025}, 0.05};
  bolt.grout = base;
  BoltPlan plan = plan_bolts(in, {bolt});
  ASSERT_EQ(plan.owned[0].size(), 32u);
  Engine e(in);
  install_bolts(e, plan);
  const double eps = 1e-4, kappa = 0.01, yc = 0.025;
  for (std::size_t node = 0; node < e.n_nodes(); ++node) {
    const double x = e.positions()[2 * node], y = e.positions()[2 * node + 1];
    const double th = kappa * x, c = (1 + eps) / kappa;
    e.set_node_state(node, c * std::sin(th) - (y - yc) * std::sin(th),
                     yc + c * (1 - std::cos(th)) + (y - yc) * std::cos(th), 0, 0);
  }
  const double e_tri = plan.steel[0].triangle_modulus / plan.steel[0].scale;
  const double stress = e_tri * eps, force = stress * kPi * 0.05 * 0.05 / 4;
  double lowest = 0, highest = 0;
  for (const BoltSample& s : bolt_axial_profile(e, plan, 0)) {
    lowest = std::min(lowest, s.steel_stress);
    highest = std::max(highest, s.steel_stress);
  }
  std::printf("triangles from %.1f to %.1f MPa; closed form %.2f MPa\n", lowest / 1e6,
              highest / 1e6, stress / 1e6);
  EXPECT_LT(lowest, -stress / 2);  // the strip bends: raw values flip sign
  EXPECT_GT(highest, 2 * stress);
  const std::vector<BoltStation> st = bolt_sections(e, plan, 0);
  ASSERT_EQ(st.size(), 8u);  // one station per cell: 0.4 m over 50 mm triangles
  for (std::size_t i = 0; i < st.size(); ++i) {
    std::printf("station %.3f m: %.3f MPa, %.3f kN per bar\n", st[i].station,
                st[i].steel_stress / 1e6, st[i].bar_force / 1e3);
    EXPECT_NEAR(st[i].station, 0.025 + 0.05 * double(i), 1e-12);
    EXPECT_NEAR(st[i].steel_stress, stress, 0.01 * stress) << "station " << i;
    EXPECT_NEAR(st[i].bar_force, force, 0.01 * force) << "station " << i;
    EXPECT_NEAR(st[i].force_per_metre, stress * 0.05 / bolt.row_spacing, 0.01 * stress * 0.05);
    EXPECT_EQ(st[i].state, 0);
    // The section centroid lies on the bent axis: a circle of radius 1 / kappa.
    EXPECT_NEAR(std::hypot(st[i].x, st[i].y - yc - 1 / kappa), 1 / kappa, 1e-5);
  }
}

}  // namespace
}  // namespace rockfdem::fdem
