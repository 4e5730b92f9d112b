// One crack element between two triangles, driven quasi-statically through
// the engine: the upper triangle is translated rigidly (positions set, zero
// velocity) by u along a direction, one step evaluates the forces, and the
// crack's force on the upper triangle (the triangles carry no strain) gives
// the work by the trapezoid rule. Closed forms: total work per unit length
// = (2/3) ft op (pre-peak branch) + Gf (softening branch).
#include <gtest/gtest.h>

#include "rockfdem/fdem/crack_law.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

struct PathResult {
  double work_per_length = 0;  ///< [J/m^2]
  double u_at_break = -1;      ///< displacement at breakage; -1 if unbroken
};

/// Translates triangle 1 by u (dx, dy) in n increments up to u_max.
PathResult drive(Engine& e, double h, double dx, double dy, double u_max, int n) {
  PathResult r;
  const auto top = e.triangle_nodes(1), bottom = e.triangle_nodes(0);
  std::array<double, 6> ref_top{}, ref_bottom{};
  for (int k = 0; k < 3; ++k) {
    ref_top[2 * k] = e.positions()[2 * top[k]];
    ref_top[2 * k + 1] = e.positions()[2 * top[k] + 1];
    ref_bottom[2 * k] = e.positions()[2 * bottom[k]];
    ref_bottom[2 * k + 1] = e.positions()[2 * bottom[k] + 1];
  }
  double prev = 0;
  for (int i = 1; i <= n; ++i) {
    const double u = u_max * i / n;
    for (int k = 0; k < 3; ++k) {
      e.set_node_state(top[k], ref_top[2 * k] + u * dx, ref_top[2 * k + 1] + u * dy, 0, 0);
      e.set_node_state(bottom[k], ref_bottom[2 * k], ref_bottom[2 * k + 1], 0, 0);
    }
    e.step();
    double fx = 0, fy = 0;
    for (int node : top) {
      fx += e.node_force(node)[0];
      fy += e.node_force(node)[1];
    }
    const double resisting = -(fx * dx + fy * dy);  // the crack pulls back
    r.work_per_length += 0.5 * (resisting + prev) * (u_max / n) / h;
    prev = resisting;
    if (e.crack_state(0) == CrackState::kBroken) {
      r.u_at_break = u;
      break;
    }
  }
  return r;
}

TEST(CrackElement, two_triangles_get_one_crack_element) {
  Engine e(test::two_triangles(0.01, test::rock()));
  EXPECT_EQ(e.n_cracks(), 1u);
  EXPECT_EQ(e.n_nodes(), 6u);
  const auto tri = e.crack_triangles(0);
  EXPECT_EQ(tri[0], 0);
  EXPECT_EQ(tri[1], 1);
}

/// Pulls the element apart in mode I until it breaks; returns the energy
/// dissipated per unit length (total work minus the pre-peak (2/3) ft op).
double mode_I_dissipation(Engine& e, double h, const Material& m, int n, double& u_at_break) {
  const CrackConstants k = make_crack_constants(m);
  const double op = 2 * h * m.tensile_strength / k.pn;
  const PathResult r = drive(e, h, 0, 1, 1.2 * (op + k.open_range), n);
  u_at_break = r.u_at_break;
  return r.work_per_length - 2.0 / 3.0 * m.tensile_strength * op;
}

// Mode I: GfI per unit length within 2% (reference: or - op = GfI/(0.3863 ft)).
TEST(CrackElement, crack_law_mode_I_dissipates_GfI) {
  const double h = 0.01;
  const Material m = test::rock();
  Engine e(test::two_triangles(h, m));
  double u_break = -1;
  const double dissipated = mode_I_dissipation(e, h, m, 6000, u_break);
  ASSERT_GT(u_break, 0);
  EXPECT_EQ(e.crack_mode(0), FailureMode::kModeI);
  EXPECT_EQ(e.crack_broken_step(0), e.step_count() - 1);
  std::printf("mode I: dissipated %.4f J/m^2 for GfI = %.4f\n", dissipated, m.gf_I);
  EXPECT_NEAR(dissipated, m.gf_I, 0.02 * m.gf_I);
  const CrackConstants k = make_crack_constants(m);
  const double op = 2 * h * m.tensile_strength / k.pn;
  EXPECT_NEAR(u_break, op + k.open_range, 0.01 * k.open_range);
}

// Grouting (issue 7): a broken element re-joined where it is carries tension
// again from its new zero, up to ft, and dissipates GfI again (2%).
TEST(CrackElement, rejoined_crack_carries_tension_from_its_new_zero) {
  const double h = 0.01;
  const Material m = test::rock();
  Engine e(test::two_triangles(h, m));
  double u_break = -1;
  mode_I_dissipation(e, h, m, 3000, u_break);
  ASSERT_GT(u_break, 0);
  e.rejoin_crack(0, 0);
  EXPECT_EQ(e.crack_state(0), CrackState::kIntact);
  EXPECT_EQ(e.crack_broken_step(0), -1);
  const double again = mode_I_dissipation(e, h, m, 3000, u_break);
  ASSERT_GT(u_break, 0);
  EXPECT_NEAR(again, m.gf_I, 0.02 * m.gf_I);
}

// Mode II at zero normal stress: GfII per unit length within 5%.
TEST(CrackElement, crack_law_mode_II_dissipates_GfII) {
  const double h = 0.01;
  const Material m = test::rock();
  Engine e(test::two_triangles(h, m));
  const CrackConstants k = make_crack_constants(m);
  const double sp = 2 * h * m.cohesion / k.pt, range = k.slip_energy / m.cohesion;
  const PathResult r = drive(e, h, 1, 0, 1.2 * (sp + range), 6000);
  ASSERT_GT(r.u_at_break, 0);
  EXPECT_EQ(e.crack_mode(0), FailureMode::kModeII);
  const double dissipated = r.work_per_length - 2.0 / 3.0 * m.cohesion * sp;
  std::printf("mode II: dissipated %.4f J/m^2 for GfII = %.4f\n", dissipated, m.gf_II);
  EXPECT_NEAR(dissipated, m.gf_II, 0.05 * m.gf_II);
}

// Mixed path: opening and slip each reach only ~75% of their softening
// ranges, yet sqrt(a^2 + b^2) >= 1 (seed eq. 10) breaks the element; the
// same opening alone does not.
TEST(CrackElement, mixed_path_breaks_on_mixed_criterion) {
  const double h = 0.01;
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double op = 2 * h * m.tensile_strength / k.pn, sp = 2 * h * m.cohesion / k.pt;
  const double o_range = k.open_range, s_range = k.slip_energy / m.cohesion;
  const double len = std::hypot(o_range, s_range);
  Engine mixed(test::two_triangles(h, m));
  // Slip along -x (the element's tangent runs B->A) and opening along +y.
  const PathResult r = drive(mixed, h, s_range / len, o_range / len, 1.5 * len, 6000);
  ASSERT_GT(r.u_at_break, 0);
  EXPECT_EQ(mixed.crack_mode(0), FailureMode::kMixed);
  const double a = (r.u_at_break * o_range / len - op) / o_range;
  const double b = (r.u_at_break * s_range / len - sp) / s_range;
  EXPECT_LT(a, 0.85);
  EXPECT_LT(b, 0.85);
  EXPECT_NEAR(std::hypot(a, b), 1.0, 0.02);

  Engine opening_only(test::two_triangles(h, m));
  drive(opening_only, h, 0, 1, r.u_at_break * o_range / len, 3000);
  EXPECT_NE(opening_only.crack_state(0), CrackState::kBroken);
  EXPECT_EQ(opening_only.crack_state(0), CrackState::kYielding);
}

}  // namespace
}  // namespace rockfdem::fdem
