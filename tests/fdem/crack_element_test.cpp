// One crack element between two triangles, driven quasi-statically through
// the engine: the upper triangle is translated rigidly (positions set, zero
// velocity) by u along a direction, one step evaluates the forces, and the
// crack's force on the upper triangle (the triangles carry no strain) gives
// the work by the trapezoid rule. Closed forms: total work per unit length
// = (2/3) ft op (pre-peak branch) + Gf (softening branch).
#include <gtest/gtest.h>

#include <cmath>

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

// Grouting: a broken element re-joined where it is carries tension
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

/// Places triangle 1 rotated rigidly by theta about its corner at A (0, 0),
/// triangle 0 as meshed, all at rest: the opening grows linearly from 0 at
/// A to about h theta at B. The next step's forces are those of this
/// placement.
void rotate_upper(Engine& e, double h, double theta) {
  const auto top = e.triangle_nodes(1), bottom = e.triangle_nodes(0);
  const double ref[4][2] = {{0, 0}, {h, 0}, {h / 2, -h}, {h / 2, h}};  // A, B, C, D
  const int top_vertex[3] = {0, 1, 3}, bottom_vertex[3] = {0, 2, 1};
  const double c = std::cos(theta), s = std::sin(theta);
  for (int k = 0; k < 3; ++k) {
    const double* p = ref[top_vertex[k]];
    e.set_node_state(top[k], c * p[0] - s * p[1], s * p[0] + c * p[1], 0, 0);
    const double* q = ref[bottom_vertex[k]];
    e.set_node_state(bottom[k], q[0], q[1], 0, 0);
  }
}

// Simpson's weights h/6, 2h/3, h/6 with the midpoint split in half are
// Simpson's rule for the consistent nodal forces int sigma N_i dx, exact
// when the traction is quadratic along the element (pre-peak tension
// under a linear opening). Reference: 400 Gauss-Legendre panels of the
// point law at o(x) = o0 (1 - x/h) + o1 x/h, from the reference definitions
// of t, e, n and delta. The trapezoid weights (h/2, 0, h/2) give the same
// forces for a uniform opening (every other test here) but none at A,
// against 35% of the total here.
TEST(CrackElement, hinge_opening_gets_the_consistent_nodal_forces) {
  const double h = 0.01;
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double op = 2 * h * m.tensile_strength / k.pn;
  Engine e(test::two_triangles(h, m));
  rotate_upper(e, h, 0.6 * op / h);  // o at B: 0.6 op, pre-peak everywhere
  const auto nd = e.crack_nodes(0);
  double x[4], y[4];
  for (int j = 0; j < 4; ++j) {
    x[j] = e.positions()[2 * nd[j]];
    y[j] = e.positions()[2 * nd[j] + 1];
  }
  e.step();
  ASSERT_EQ(e.crack_state(0), CrackState::kIntact);
  const double tx = 0.5 * (x[1] + x[2] - x[0] - x[3]), ty = 0.5 * (y[1] + y[2] - y[0] - y[3]);
  const double len = std::hypot(tx, ty), ex = tx / len, ey = ty / len, nx = -ey, ny = ex;
  const double o0 = (x[0] - x[3]) * nx + (y[0] - y[3]) * ny;
  const double o1 = (x[1] - x[2]) * nx + (y[1] - y[2]) * ny;
  const double s0 = (x[0] - x[3]) * ex + (y[0] - y[3]) * ey;
  const double s1 = (x[1] - x[2]) * ex + (y[1] - y[2]) * ey;
  // int_0^1 (sigma n + tau e) N_end(xi) h dxi for end 0 (N = 1 - xi) and 1.
  const double gx[2] = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  double fn[2] = {0, 0}, ft[2] = {0, 0};
  const int panels = 400;
  for (int i = 0; i < panels; ++i)
    for (double g : gx) {
      const double xi = (i + 0.5 + 0.5 * g) / panels, w = 0.5 / panels * len;
      double damage = 0;
      const CrackPoint p = crack_point(k, o0 + (o1 - o0) * xi, s0 + (s1 - s0) * xi, len, damage);
      fn[0] += w * p.sigma * (1 - xi);
      fn[1] += w * p.sigma * xi;
      ft[0] += w * p.tau * (1 - xi);
      ft[1] += w * p.tau * xi;
    }
  // A real gradient (1.8x here; end 0 happens to be B).
  ASSERT_GT(std::max(fn[0], fn[1]), 1.5 * std::min(fn[0], fn[1]));
  // Face (0, 1) receives -(tau e + sigma n) N, face (3, 2) the opposite.
  const int face[4] = {0, 1, 1, 0};
  const double sign[4] = {-1, -1, 1, 1};
  const double scale = fn[1];
  for (int j = 0; j < 4; ++j) {
    const int end = face[j];
    const auto f = e.node_force(nd[j]);
    EXPECT_NEAR(f[0], sign[j] * (ft[end] * ex + fn[end] * nx), 1e-9 * scale) << "node " << j;
    EXPECT_NEAR(f[1], sign[j] * (ft[end] * ey + fn[end] * ny), 1e-9 * scale) << "node " << j;
  }
}

// Breakage needs D >= 1 at two of the three points. Hinged open about A,
// end B reaches D = 1 at o_B = op + (or - op) but the element holds; it
// breaks only when the midpoint (o_B / 2) gets there, at o_B = 2 (or).
// A one-point rule would break at half that, a three-point rule never.
TEST(CrackElement, breaks_when_two_of_three_points_are_fully_damaged) {
  const double h = 0.01;
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double op = 2 * h * m.tensile_strength / k.pn, full = op + k.open_range;
  Engine e(test::two_triangles(h, m));
  const int n = 2000;
  double o_break = -1;
  for (int i = 1; i <= n && o_break < 0; ++i) {
    const double o_b = 2.5 * full * i / n;
    rotate_upper(e, h, std::asin(o_b / h));
    e.step();
    if (e.crack_state(0) == CrackState::kBroken) o_break = o_b;
  }
  ASSERT_GT(o_break, 0) << "never broke";
  // The opening at B is h sin(theta) up to the tangent's tilt (theta / 2,
  // a relative 3e-6 here); one increment is 0.125% of 2 (or).
  EXPECT_NEAR(o_break, 2 * full, 0.003 * full);
  EXPECT_EQ(e.crack_mode(0), FailureMode::kModeI);
}

}  // namespace
}  // namespace rockfdem::fdem
