// Kirsch: a circular hole in a biaxial far field. With the exact Kirsch
// traction on the box, the only error left is the discretisation's, so the
// relative L2 stress error over a <= r <= 5a must fall under refinement and
// be below 1% at about 20k triangles; the wall's radial displacement must be
// within 2% of the plane-strain closed form (reference section 5).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "fixtures.hpp"

namespace rockfdem::insitu::test {
namespace {

struct KirschParam {
  const char* name;
  double sH, sV, angle_deg;
};

class KirschTest : public ::testing::TestWithParam<KirschParam> {};

TEST_P(KirschTest, exact_tractions_error_falls_with_refinement_and_is_below_1pct_at_20k) {
  const KirschParam p = GetParam();
  InsituSpec spec = seed_spec(p.sH, p.sV);
  spec.far_field.angle_deg = p.angle_deg;
  spec.loading = BoundaryLoading::kKirschExact;
  spec.kirsch_radius = 1.0;
  spec.alphas = {0.0};  // the core is removed: the open hole
  const KirschCase k = kirsch_case(spec, 1.0);

  std::vector<double> errors;
  KirschComparison finest;
  std::size_t finest_rock_triangles = 0;
  for (const int n_theta : {48, 96, 176}) {
    const mesh::Mesh m = polar_box_mesh({1.0, 8.0, n_theta, true, 0.0});
    const InsituField f = solve_insitu(m, spec).at(0);
    const KirschComparison c = compare_kirsch(m, f, k);
    std::printf(
        "  [%s] n_theta %3d: %6zu cells %7zu dofs  stress L2 %.4f%%  wall u_r %.4f%%  %s"
        " (%d it) reaction %.1e\n",
        p.name, n_theta, f.n_cells, f.n_dofs, 100 * c.stress_rel_l2, 100 * c.wall_ur_rel_l2,
        f.solver.c_str(), f.iterations, f.reaction_ratio);
    errors.push_back(c.stress_rel_l2);
    finest = c;
    finest_rock_triangles = f.n_cells;
    EXPECT_GT(c.n_triangles, 100u);
    EXPECT_EQ(c.n_wall_vertices, static_cast<std::size_t>(n_theta));
    // Self-equilibrated loads: the three constraints carry (almost) nothing;
    // what is left is the quadrature of the Kirsch traction on the box.
    EXPECT_LT(f.reaction_ratio, 1e-6);
  }
  // Refinement by ~2x in h each time: the error must drop each time, by at
  // least a third (P1 stresses converge at O(h) in L2).
  EXPECT_LT(errors[1], 0.67 * errors[0]);
  EXPECT_LT(errors[2], 0.67 * errors[1]);
  EXPECT_GT(finest_rock_triangles, 18000u);
  EXPECT_LT(finest.stress_rel_l2, 0.01);
  EXPECT_LT(finest.wall_ur_rel_l2, 0.02);
}

INSTANTIATE_TEST_SUITE_P(FarFields, KirschTest,
                         ::testing::Values(KirschParam{"seed_18_2_over_11_4", 18.2e6, 11.4e6, 0.0},
                                           KirschParam{"hydrostatic_15", 15e6, 15e6, 0.0},
                                           KirschParam{"seed_rotated_30deg", 18.2e6, 11.4e6, 30.0}),
                         [](const auto& info) { return std::string(info.param.name); });

// The open hole (a = 1) under Kirsch's exact tractions, the seed's field.
InsituSpec open_hole_spec() {
  InsituSpec spec = seed_spec();
  spec.loading = BoundaryLoading::kKirschExact;
  spec.kirsch_radius = 1.0;
  spec.alphas = {0.0};
  return spec;
}

std::vector<InsituField> solve_by(const mesh::Mesh& m, InsituSpec spec, const LinearSolver kind) {
  spec.solver.kind = kind;
  return solve_insitu(m, spec);
}

// At a tight tolerance CG and UMFPACK give the same field (the bound is the
// solver's, far below any difference of formulation).
TEST(Kirsch, amg_cg_and_direct_agree_and_cg_reports_iterations) {
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 96, true, 0.0});
  InsituSpec spec = open_hole_spec();
  spec.solver.tolerance = 1e-10;
  const InsituField direct = solve_by(m, spec, LinearSolver::kDirect).at(0);
  const InsituField cg = solve_by(m, spec, LinearSolver::kAmgCg).at(0);
  EXPECT_EQ(direct.solver, "direct");
  EXPECT_EQ(direct.iterations, 0);
  EXPECT_EQ(cg.solver, "amg-cg");
  EXPECT_GT(cg.iterations, 0);
  EXPECT_LT(cg.iterations, 200);
  EXPECT_LT(cg.unbalanced_ratio, 1e-9);
  EXPECT_LT(field_difference(cg, direct).u, 1e-7);
}

// The default tolerance holds what the documentation claims of it, along a
// softening sequence where CG starts from the earlier alphas' solutions
// with a kept hierarchy (its error is largest there): every field within
// 4e-7 of UMFPACK's solution of the same equations in displacement and
// 1.5e-7 in stress. Measured at 1e-8: 1.5e-7 and 3.2e-8 at worst; a
// default of 1e-7 fails (4.6e-7 and 4.5e-7), 1e-10 gives 3.1e-9 and
// 2.5e-10. At the open hole that is also far below the mesh's own error
// against Kirsch (176 rays, 21,120 dofs: wall u_r 0.22%, stresses 0.9% in
// L2): under a thousandth of it.
TEST(Kirsch, the_default_tolerance_leaves_cg_error_far_below_the_mesh_error) {
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 176, true, 0.0});
  InsituSpec spec = open_hole_spec();
  spec.alphas = {1.0, 0.5, 0.2, 0.05, 0.01, 0.0};
  const auto direct = solve_by(m, spec, LinearSolver::kDirect);
  const auto cg = solve_by(m, spec, LinearSolver::kAmgCg);
  ASSERT_EQ(cg.size(), direct.size());
  for (std::size_t i = 1; i < cg.size(); ++i) {
    ASSERT_EQ(cg[i].solver, "amg-cg");
    const FieldDifference d = field_difference(cg[i], direct[i]);
    std::printf(
        "  tolerance %.0e, alpha %4.2f, %2d iterations: CG against UMFPACK du %.2e, ds %.2e\n",
        spec.solver.tolerance, cg[i].alpha, cg[i].iterations, d.u, d.s);
    EXPECT_LT(d.u, 4e-7) << "alpha " << cg[i].alpha;
    EXPECT_LT(d.s, 1.5e-7) << "alpha " << cg[i].alpha;
    // CG stops on its own recursive residual; the check assembles it anew.
    EXPECT_LT(cg[i].unbalanced_ratio, 2 * spec.solver.tolerance) << "alpha " << cg[i].alpha;
  }
  const KirschCase k = kirsch_case(spec, 1.0);
  const KirschComparison mesh_error = compare_kirsch(m, direct.back(), k);
  const FieldDifference open_hole = field_difference(cg.back(), direct.back());
  std::printf("  mesh error at the open hole: wall u_r %.2e, stress L2 %.2e\n",
              mesh_error.wall_ur_rel_l2, mesh_error.stress_rel_l2);
  EXPECT_LT(open_hole.u, 1e-3 * mesh_error.wall_ur_rel_l2);
  EXPECT_LT(open_hole.s, 1e-3 * mesh_error.stress_rel_l2);
}

TEST(Kirsch, far_field_tractions_on_a_finite_box_leave_a_box_error) {
  // The same hole with sigma0 . n on the box instead: the error no longer
  // vanishes with h (the box is finite), so exact tractions must beat it.
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 96, true, 0.0});
  InsituSpec spec = seed_spec();
  spec.alphas = {0.0};
  const KirschCase k = kirsch_case(spec, 1.0);
  const double far = compare_kirsch(m, solve_insitu(m, spec).at(0), k).stress_rel_l2;
  spec.loading = BoundaryLoading::kKirschExact;
  spec.kirsch_radius = 1.0;
  const double exact = compare_kirsch(m, solve_insitu(m, spec).at(0), k).stress_rel_l2;
  std::printf("  box 16a: far-field tractions %.3f%%, exact tractions %.3f%%\n", 100 * far,
              100 * exact);
  EXPECT_LT(exact, far);
}

}  // namespace
}  // namespace rockfdem::insitu::test
