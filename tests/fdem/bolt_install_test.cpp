// Installing a bolt in loaded rock (install_bolts with BoltStart). A bolt
// strip that keeps the rock's current stress (kKeepCurrentStress) must
// change nothing at installation: every triangle's stress, every node's
// force and the unbalanced-force ratio stay what they were, because
//   - each strip triangle's stress alpha (S0 + C:eps) with eps = 0 in its
//     installed shape and S0 = sigma / alpha is sigma again (up to the
//     rounding of F = I, about 1e-16 E alpha), and
//   - each re-joined crack (steel inside the strip, grout at its sides)
//     carries the normal and shear stress its rock law carried, so the
//     forces on the strip's nodes are the same sums.
// The stress-free start (kStressFree, the default) unloads the strip and
// its cracks: the same comparison then finds jumps of the order of the
// stress itself, which shows the comparison can tell.
#include "rockfdem/fdem/bolt_install.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kCell = 0.025;  // 20 x 10 cells of 25 mm
constexpr int kLoaded = 9;       // top edges over the left half: a heavier load

// A 0.5 x 0.25 m block of rock (fracture everywhere) in in-situ compression
// sxx = -8, syy = -12 MPa on rollers (left, bottom), its right and top
// faces loaded to match, the top's left half with -20 MPa: the block is
// squeezed unevenly, so that stresses and crack tractions (normal and
// shear) differ from triangle to triangle. A 25 mm bolt runs along the
// row 0.100 < y < 0.125 from x = 0.1 to 0.4 (its long sides on mesh lines:
// exactly that row, 24 triangles). Grout cohesion 6 MPa: stronger than
// the shear the block puts on the strip's sides (checked: no point clipped).
ModelInput loaded_block(std::vector<BoltSpec>& specs) {
  RectangleSpec spec;
  spec.width = 0.5;
  spec.height = 0.25;
  spec.nx = 20;
  spec.ny = 10;
  ModelInput in = structured_rectangle(spec, test::rock());
  in.initial_stress.assign(in.triangles.size(), {-8e6, -12e6, 0});
  for (auto& e : in.edges)
    if (e.tag == kTagTop && std::max(in.x[e.a], in.x[e.b]) <= 0.25 + 1e-12) e.tag = kLoaded;
  in.boundary_conditions = rollers_with_top_traction(-12e6);
  BoundaryCondition right, loaded;
  right.tag = kTagRight;
  right.tx = -8e6;
  loaded.tag = kLoaded;
  loaded.ty = -20e6;
  in.boundary_conditions.push_back(right);
  in.boundary_conditions.push_back(loaded);
  BoltSpec bolt;
  bolt.bolt = {{0.1, 0.1125}, {0.4, 0.1125}, 0.025};
  bolt.grout.young = 10e9;
  bolt.grout.tensile_strength = 1e6;
  bolt.grout.cohesion = 6e6;
  specs = {bolt};
  return in;
}

/// The block after 300 steps of uneven squeezing, brought to rest (zero
/// velocities: no viscous part in any force), its bolt installed with
/// `start` (none when null).
struct Installed {
  ModelInput in;
  BoltPlan plan;
  std::unique_ptr<Engine> engine;
  BoltInstallReport report;
};

Installed loaded_and_installed(const BoltStart* start) {
  Installed r;
  std::vector<BoltSpec> specs;
  r.in = loaded_block(specs);
  r.plan = plan_bolts(r.in, specs);
  r.engine = std::make_unique<Engine>(r.in);
  Engine& e = *r.engine;
  e.set_threads(1);
  e.run(300);
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], 0, 0);
  if (start) r.report = install_bolts(e, r.plan, *start);
  return r;
}

/// Largest |a - b| over every triangle's three stress components.
double largest_stress_change(const Engine& a, const Engine& b) {
  double worst = 0;
  for (std::size_t t = 0; t < a.n_triangles(); ++t) {
    const auto sa = a.triangle_stress(t), sb = b.triangle_stress(t);
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(sa[k] - sb[k]));
  }
  return worst;
}

/// Evaluates every node's force in the present state: one step so short
/// (1e-15 s) that nothing moves; node_force() is that step's force.
void evaluate_forces(Engine& e) {
  e.set_dt(1e-15);
  e.step();
}

double largest_force_change(const Engine& a, const Engine& b) {
  double worst = 0;
  for (std::size_t n = 0; n < a.n_nodes(); ++n)
    for (int k = 0; k < 2; ++k)
      worst = std::max(worst, std::fabs(a.node_force(n)[k] - b.node_force(n)[k]));
  return worst;
}

TEST(BoltInstall, keeping_current_stress_changes_no_stress_and_no_force) {
  const BoltStart keep = BoltStart::kKeepCurrentStress, free = BoltStart::kStressFree;
  Installed none = loaded_and_installed(nullptr);
  Installed kept = loaded_and_installed(&keep);
  Installed freed = loaded_and_installed(&free);
  ASSERT_EQ(kept.report.triangles, 24);
  ASSERT_GT(kept.report.grout_cracks, 0);
  EXPECT_EQ(kept.report.clipped_points, 0);  // the grout carries every traction it takes over
  // The strip's stress before installation: the scale of both comparisons.
  double scale = 0;
  for (int t : none.plan.owned[0])
    for (double s : none.engine->triangle_stress(t)) scale = std::max(scale, std::fabs(s));
  ASSERT_GT(scale, 8e6);
  // The strip did carry load, and the start can tell: stress-free, its
  // triangles lose it all.
  const double kept_stress = largest_stress_change(*kept.engine, *none.engine);
  const double freed_stress = largest_stress_change(*freed.engine, *none.engine);
  // The kept stress is stored as an initial stress over alpha: rounded to
  // test::kStored of itself and times alpha as stored, nothing more.
  EXPECT_LE(kept_stress, 2 * test::kStored * scale) << kept_stress << " Pa";
  EXPECT_GE(freed_stress, 0.5 * scale) << freed_stress << " Pa";
  // Nodal forces: a node's force scale is the stress times a cell edge.
  for (Installed* r : {&none, &kept, &freed}) evaluate_forces(*r->engine);
  const double force_scale = scale * kCell;
  const double kept_force = largest_force_change(*kept.engine, *none.engine);
  const double freed_force = largest_force_change(*freed.engine, *none.engine);
  EXPECT_LE(kept_force, 4 * test::kStored * force_scale) << kept_force << " N/m";
  EXPECT_GE(freed_force, 0.1 * force_scale) << freed_force << " N/m";
  const double ratio = none.engine->unbalanced_force_ratio();
  EXPECT_NEAR(kept.engine->unbalanced_force_ratio(), ratio, 4 * test::kStored * ratio);
  EXPECT_GT(freed.engine->unbalanced_force_ratio(), 2 * ratio);
  std::printf(
      "strip stress scale %.4g Pa; largest stress change kept %.3g, free %.3g Pa; "
      "largest node force change kept %.3g, free %.3g N/m; unbalanced ratio "
      "none %.6g kept %.6g free %.6g\n",
      scale, kept_stress, freed_stress, kept_force, freed_force, ratio,
      kept.engine->unbalanced_force_ratio(), freed.engine->unbalanced_force_ratio());
}

// The index made at installation lists each bolt's crack elements as the
// definition says, checked here element by element from the marks: steel
// with both triangles in the strip, grout with one, in crack order. A
// plan without bolts indexes nothing.
TEST(BoltInstall, crack_index_matches_the_marks_element_by_element) {
  const BoltStart free = BoltStart::kStressFree;
  Installed r = loaded_and_installed(&free);
  ASSERT_EQ(r.plan.cracks.size(), 1u);
  BoltCracks expected;
  for (std::size_t c = 0; c < r.engine->n_cracks(); ++c) {
    const auto tri = r.engine->crack_triangles(c);
    const int in = int(r.plan.marks.owner[tri[0]] == 0) + int(r.plan.marks.owner[tri[1]] == 0);
    if (in == 2) expected.steel.push_back(int(c));
    if (in == 1) expected.grout.push_back(int(c));
  }
  const BoltCracks indexed = bolt_cracks(*r.engine, r.plan, 0);
  EXPECT_EQ(indexed.steel, expected.steel);
  EXPECT_EQ(indexed.grout, expected.grout);
  BoltPlan unindexed = r.plan;
  unindexed.cracks.clear();
  const BoltCracks searched = bolt_cracks(*r.engine, unindexed, 0);
  EXPECT_EQ(searched.steel, expected.steel);
  EXPECT_EQ(searched.grout, expected.grout);
  EXPECT_GT(expected.steel.size(), 0u);
  EXPECT_GT(expected.grout.size(), 0u);
  BoltPlan none;
  index_bolt_cracks(*r.engine, none);
  EXPECT_TRUE(none.cracks.empty());
}

}  // namespace
}  // namespace rockfdem::fdem
