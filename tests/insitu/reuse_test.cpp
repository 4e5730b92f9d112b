// What the in-situ stage keeps from one alpha to the next (the host rock's
// stiffness, GAMG's hierarchy, the previous solution as CG's start) changes
// how fast a stage is solved, never what it solves: each field of a
// sequence must equal the field of a fresh solve of that alpha alone.
//
// The comparison is exact in the physics, not approximately: with a lining
// installed at alpha = 0.5 after the stage at alpha = 1 (where nothing
// moves, so the ring goes in strain-free), the sequence 1, 0.5, ... and the
// single alpha a (lining installed at once, strain-free) are one problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fixtures.hpp"

namespace rockfdem::insitu::test {
namespace {

InsituSpec lined_spec(LinearSolver kind) {
  InsituSpec spec = seed_spec();  // the seed's biaxial field
  spec.lining.active = true;
  spec.lining.install_alpha = 0.5;
  spec.solver.kind = kind;
  spec.solver.tolerance = 1e-10;  // the bounds below are this residual's
  return spec;
}

// Tolerances: CG stops at ||r|| <= 1e-10 ||F0|| whatever its start and
// preconditioner, so the sequence and the fresh solve differ by two such
// residuals; on this grid that is measured at 1e-9 of the largest stress
// and displacement at most (the direct solver: round-off, 1e-13). 1e-7 is
// far above both and far below any error of the formulation: a matrix left
// at the previous alpha's core stiffness, or a lining assembled twice,
// changes the fields by 1e-3 to 1e-1.
TEST(InsituReuse, every_alpha_of_a_sequence_equals_a_fresh_solve_of_that_alpha) {
  const mesh::Mesh m = polar_box_mesh({1.0, 20.0, 64, true, 0.1});
  for (const LinearSolver kind : {LinearSolver::kAmgCg, LinearSolver::kDirect}) {
    InsituSpec spec = lined_spec(kind);
    spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.01, 0.0};
    const auto sequence = solve_insitu(m, spec);
    ASSERT_EQ(sequence.size(), spec.alphas.size());
    for (const InsituField& f : sequence) {
      if (f.alpha == 1.0) continue;  // nothing moves: no fresh solve to compare
      InsituSpec single = spec;
      single.alphas = {f.alpha};
      const InsituField fresh = solve_insitu(m, single).at(0);
      const FieldDifference d = field_difference(f, fresh);
      std::printf("  %s alpha %4.2f: stress %.2e, displacement %.2e (iterations %d, fresh %d)\n",
                  kind == LinearSolver::kDirect ? "direct" : "amg-cg", f.alpha, d.s, d.u,
                  f.iterations, fresh.iterations);
      EXPECT_TRUE(f.lining_installed);
      EXPECT_LT(d.s, 1e-7) << "alpha " << f.alpha;
      EXPECT_LT(d.u, 1e-7) << "alpha " << f.alpha;
    }
  }
}

// keep_fields drops the arrays of the fields it does not name, after they
// are solved: the kept ones have the bits of a sequence that keeps all
// (the solves are the same), the others their reports and no arrays.
TEST(InsituReuse, fields_not_kept_have_no_arrays_and_the_kept_the_same_bits) {
  const mesh::Mesh m = polar_box_mesh({1.0, 20.0, 32, true, 0.1});
  InsituSpec spec = lined_spec(LinearSolver::kAmgCg);
  spec.alphas = {1.0, 0.5, 0.2, 0.0};
  const auto all = solve_insitu(m, spec);
  spec.keep_fields = {0.5, 0.0};
  const auto kept = solve_insitu(m, spec);
  ASSERT_EQ(kept.size(), all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(kept[i].alpha, all[i].alpha);
    EXPECT_EQ(kept[i].iterations, all[i].iterations);
    const bool keep = all[i].alpha == 0.5 || all[i].alpha == 0.0;
    if (!keep) {
      EXPECT_TRUE(kept[i].stress.empty() && kept[i].active.empty() && kept[i].ux.empty() &&
                  kept[i].uy.empty())
          << "alpha " << all[i].alpha;
      continue;
    }
    ASSERT_EQ(kept[i].stress.size(), all[i].stress.size());
    for (std::size_t t = 0; t < all[i].stress.size(); ++t) {
      EXPECT_EQ(kept[i].stress[t].sxx, all[i].stress[t].sxx);
      EXPECT_EQ(kept[i].stress[t].syy, all[i].stress[t].syy);
      EXPECT_EQ(kept[i].stress[t].sxy, all[i].stress[t].sxy);
    }
    EXPECT_EQ(kept[i].active, all[i].active);
    EXPECT_EQ(kept[i].ux, all[i].ux);
    EXPECT_EQ(kept[i].uy, all[i].uy);
  }
}

// on_field sees each field once, in alpha order, whole and before the next
// solve; arrays it takes stay taken, and the solves after it are the same
// bits (the sequence does not read a field once it is handed over).
TEST(InsituReuse, on_field_sees_each_field_whole_and_may_take_its_arrays) {
  const mesh::Mesh m = polar_box_mesh({1.0, 20.0, 32, true, 0.1});
  InsituSpec spec = lined_spec(LinearSolver::kAmgCg);
  spec.alphas = {1.0, 0.5, 0.2, 0.0};
  const auto all = solve_insitu(m, spec);
  std::vector<double> seen;
  std::vector<std::vector<double>> taken_ux;
  spec.on_field = [&](InsituField& f) {
    seen.push_back(f.alpha);
    EXPECT_EQ(f.ux.size(), m.n_vertices()) << "alpha " << f.alpha;
    taken_ux.push_back(std::move(f.ux));
    f.ux.clear();
  };
  const auto sampled = solve_insitu(m, spec);
  ASSERT_EQ(sampled.size(), all.size());
  EXPECT_EQ(seen, spec.alphas);
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_TRUE(sampled[i].ux.empty()) << "alpha " << all[i].alpha;
    EXPECT_EQ(taken_ux[i], all[i].ux) << "alpha " << all[i].alpha;
    EXPECT_EQ(sampled[i].uy, all[i].uy) << "alpha " << all[i].alpha;
  }
}

// The kept hierarchy must keep CG fast: every solve that used it needs at
// most twice the iterations of a fresh hierarchy for the same matrix (the
// rebuild rule allows 1.5 times the first solve after a build), and it must
// actually be kept for the alphas after the first of a grid.
TEST(InsituReuse, the_kept_hierarchy_keeps_cg_iterations_bounded) {
  const mesh::Mesh m = polar_box_mesh({1.0, 20.0, 64, true, 0.1});
  InsituSpec spec = lined_spec(LinearSolver::kAmgCg);
  spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.01};
  const auto sequence = solve_insitu(m, spec);
  int n_kept = 0;
  for (const InsituField& f : sequence) {
    if (!f.preconditioner_reused) continue;
    ++n_kept;
    InsituSpec single = spec;
    single.alphas = {f.alpha};
    const InsituField fresh = solve_insitu(m, single).at(0);
    EXPECT_FALSE(fresh.preconditioner_reused);
    EXPECT_GT(fresh.iterations, 0);
    EXPECT_LE(f.iterations, 2 * fresh.iterations) << "alpha " << f.alpha;
  }
  EXPECT_FALSE(sequence.front().preconditioner_reused);  // built for the first
  EXPECT_GE(n_kept, 3);
}

}  // namespace
}  // namespace rockfdem::insitu::test
