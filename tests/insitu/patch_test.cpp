// Patch tests: with the core in place (alpha = 1) the in-situ state is an
// exact equilibrium of the discrete problem (the loads of (3) in
// insitu_problem.cpp cancel cell by cell), so nothing may move and every
// triangle must carry sigma0 to round-off: 1e-10 relative is ~10^6 times
// machine epsilon, far above round-off and far below any real error (a
// wrong traction or a missing body force shows up at 1e-3 or more).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>

#include "fixtures.hpp"
#include "rockfdem/insitu/constants.hpp"

namespace rockfdem::insitu::test {
namespace {

/// sigma0 (tension positive) of a rotated biaxial field, with gravity.
Stress expected_stress(const InsituSpec& s, double y) {
  const double depth = s.gravity.reference_y - y;
  const double sV = s.far_field.sV + s.gravity.unit_weight * depth;
  const double sH =
      s.far_field.sH + s.far_field.sH / s.far_field.sV * s.gravity.unit_weight * depth;
  const double b = s.far_field.angle_deg * kPi / 180, c = std::cos(b), n = std::sin(b);
  Stress e;
  e.sxx = -(sH * c * c + sV * n * n);
  e.syy = -(sH * n * n + sV * c * c);
  e.sxy = -(sH - sV) * n * c;
  e.szz = (s.materials.rock ? s.materials.rock : s.materials.core)->nu * (e.sxx + e.syy);
  return e;
}

double max_stress_deviation(const mesh::Mesh& m, const InsituSpec& spec, const InsituField& f) {
  double worst = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const auto& tri = m.triangles[t];
    const double yc = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
    const Stress e = expected_stress(spec, yc);
    const Stress& h = f.stress[t];
    const double scale = std::max(std::abs(e.sxx), std::abs(e.syy));
    worst = std::max({worst, std::abs(h.sxx - e.sxx) / scale, std::abs(h.syy - e.syy) / scale,
                      std::abs(h.sxy - e.sxy) / scale, std::abs(h.szz - e.szz) / scale});
  }
  return worst;
}

double max_displacement(const InsituField& f) {
  double u = 0;
  for (std::size_t v = 0; v < f.ux.size(); ++v) u = std::max(u, std::hypot(f.ux[v], f.uy[v]));
  return u;
}

class PatchTest : public ::testing::TestWithParam<LinearSolver> {};

TEST_P(PatchTest, core_in_place_rotated_far_field_stress_is_sigma0_in_every_triangle) {
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 64, true, 0.0});
  InsituSpec spec = seed_spec();
  spec.far_field.angle_deg = 30;
  spec.solver.kind = GetParam();
  const auto fields = solve_insitu(m, spec);
  ASSERT_EQ(fields.size(), 1u);
  const InsituField& f = fields[0];
  for (const auto a : f.active) ASSERT_EQ(a, 1);
  EXPECT_LT(max_stress_deviation(m, spec, f), 1e-10);
  // Nothing moves: displacement far below anything elastic (S a / E ~ 1e-3 m).
  EXPECT_LT(max_displacement(f), 1e-12);
  EXPECT_LT(f.reaction_ratio, 1e-12);
}

TEST_P(PatchTest, gravity_gradient_stress_is_sigma0_at_each_centroid) {
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 64, true, 0.0});
  InsituSpec spec = seed_spec();
  spec.gravity.unit_weight = 27e3;  // N/m^3
  spec.gravity.reference_y = 0;
  spec.solver.kind = GetParam();
  const InsituField f = solve_insitu(m, spec).at(0);
  EXPECT_LT(max_stress_deviation(m, spec, f), 1e-10);
  EXPECT_LT(max_displacement(f), 1e-12);
  // The stress really varies: top and bottom rows differ by gamma * 2L.
  double lo = 0, hi = -1e300;
  for (const auto& s : f.stress) lo = std::min(lo, s.syy), hi = std::max(hi, s.syy);
  EXPECT_NEAR(hi - lo, 27e3 * 16, 27e3 * 16 * 0.1);
}

INSTANTIATE_TEST_SUITE_P(Solvers, PatchTest,
                         ::testing::Values(LinearSolver::kDirect, LinearSolver::kAmgCg),
                         [](const auto& info) {
                           return info.param == LinearSolver::kDirect ? "direct" : "amg_cg";
                         });

TEST(PatchTest, softened_body_without_rock_still_carries_the_box_tractions) {
  // Everything is core (no rock material given): softening lowers the
  // stiffness, but the box tractions still hold sigma0, so the stress stays
  // sigma0 while the body deforms by (1 - alpha)/alpha of its loading strain.
  mesh::Mesh m = polar_box_mesh({1.0, 4.0, 32, true, 0.0});
  for (auto& z : m.zone) z = mesh::kCore;
  InsituSpec spec = seed_spec();
  spec.materials.rock.reset();
  spec.solver.kind = LinearSolver::kDirect;
  spec.alphas = {1.0, 0.5};
  const auto fields = solve_insitu(m, spec);
  EXPECT_LT(max_stress_deviation(m, spec, fields[1]), 1e-8);
  EXPECT_GT(max_displacement(fields[1]), 1e-4);
}

TEST(Gravity, excavation_under_self_weight_stays_self_equilibrated) {
  // The core's body force is scaled with its stress, so every stage's loads
  // balance: the three constraints carry nothing, and the opening's crown
  // settles while its invert heaves relative to the (fixed) far field.
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 64, true, 0.0});
  InsituSpec spec = seed_spec();
  spec.gravity.unit_weight = 27e3;
  spec.alphas = {0.5, 0.0};
  for (const InsituField& f : solve_insitu(m, spec)) {
    EXPECT_LT(f.reaction_ratio, 1e-12);
    EXPECT_LT(f.unbalanced_ratio, 1e-12);
    int crown = 0, invert = 0;
    for (std::size_t v = 0; v < m.n_vertices(); ++v) {
      if (std::hypot(m.x[v], m.y[v]) > 1 + 1e-9 || std::abs(m.x[v]) > 1e-9) continue;
      if (m.y[v] > m.y[crown] || std::abs(m.x[crown]) > 1e-9) crown = static_cast<int>(v);
      if (m.y[v] < m.y[invert] || std::abs(m.x[invert]) > 1e-9) invert = static_cast<int>(v);
    }
    ASSERT_NEAR(m.y[crown], 1.0, 1e-12);
    ASSERT_NEAR(m.y[invert], -1.0, 1e-12);
    EXPECT_LT(f.uy[crown], 0);
    EXPECT_GT(f.uy[invert], 0);
  }
}

TEST(Runtime, openmp_thread_count_survives_init_and_solve) {
  const int before = omp_get_max_threads();
  const mesh::Mesh m = polar_box_mesh({1.0, 8.0, 32, true, 0.0});
  InsituSpec spec = seed_spec();
  spec.solver.kind = LinearSolver::kAmgCg;
  spec.alphas = {1.0, 0.0};
  const auto fields = solve_insitu(m, spec);
  EXPECT_EQ(fields.back().solver, "amg-cg");
  EXPECT_TRUE(ScopedParallelInit::active());
  EXPECT_EQ(omp_get_max_threads(), before);
}

}  // namespace
}  // namespace rockfdem::insitu::test
