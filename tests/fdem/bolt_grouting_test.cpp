// Grouting (seed sec. 2.3) with grout_broken_cracks: two separate
// two-triangle pairs are pulled apart until both crack elements break; the
// zone selects one of them; it is re-joined with grout (ft = 1 MPa) and,
// pulled again, carries tension from its new zero up to the grout strength
// (closed form: peak traction = ft_grout, 1%), while the other stays broken.
#include "rockfdem/fdem/bolt_grouting.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "rockfdem/fdem/structured_mesh.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kH = 0.01;

/// Two pairs (test::two_triangles), the second shifted by 3 h along x.
ModelInput two_pairs(const Material& rock, const Material& grout) {
  ModelInput in = test::two_triangles(kH, rock);
  const ModelInput b = test::two_triangles(kH, rock);
  for (std::size_t v = 0; v < b.x.size(); ++v) {
    in.x.push_back(b.x[v] + 3 * kH);
    in.y.push_back(b.y[v]);
  }
  for (auto t : b.triangles) in.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  in.material = {0, 0, 0, 0};
  in.fracture = {1, 1, 1, 1};
  in.materials = {rock, grout};
  return in;
}

/// Lifts the upper triangles (1 and 3) rigidly by u in n increments from
/// where they are; returns the largest traction on triangle 1 [Pa].
double lift(Engine& e, double u_max, int n) {
  std::vector<int> nodes;
  std::vector<double> ref;
  for (int t = 0; t < 4; ++t)
    for (int node : e.triangle_nodes(t)) {
      nodes.push_back(node);
      ref.push_back(e.positions()[2 * node]);
      ref.push_back(e.positions()[2 * node + 1]);
    }
  double peak = 0;
  for (int i = 1; i <= n; ++i) {
    const double u = u_max * i / n;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const bool upper = (k / 3) % 2 == 1;
      e.set_node_state(nodes[k], ref[2 * k], ref[2 * k + 1] + (upper ? u : 0), 0, 0);
    }
    e.step();
    double fy = 0;
    for (int node : e.triangle_nodes(1)) fy += e.node_force(node)[1];
    peak = std::max(peak, -fy / kH);
  }
  return peak;
}

TEST(BoltGrouting, regrouted_cracks_carry_tension_up_to_grout_strength) {
  const Material rock = test::rock();
  Material grout = rock;
  grout.tensile_strength = 1e6;
  grout.cohesion = 3e6;
  Engine e(two_pairs(rock, grout));
  ASSERT_EQ(e.n_cracks(), 2u);
  const double first = lift(e, 2e-5, 500);  // rock: or = op + 2.589 GfI / ft = 5.2e-6 m
  EXPECT_NEAR(first, rock.tensile_strength, 0.01 * rock.tensile_strength);
  ASSERT_EQ(e.broken_counts().total(), 2);
  // Grout only the left pair: its crack's midpoint lies at x = h / 2.
  const GroutingResult r =
      grout_broken_cracks(e, 1, [](std::size_t, const Point2& mid) { return mid[0] < 2 * kH; });
  ASSERT_EQ(r.count, 1);
  EXPECT_EQ(r.cracks[0], 0);
  EXPECT_NEAR(r.midpoints[0][0], kH / 2, 1e-12);
  EXPECT_NEAR(r.midpoints[0][1], 1e-5, 1e-7);  // half the 2e-5 opening
  EXPECT_EQ(e.broken_counts().total(), 2 - r.count);
  EXPECT_EQ(e.crack_state(0), CrackState::kIntact);
  EXPECT_EQ(e.crack_state(1), CrackState::kBroken);
  const double again = lift(e, 4e-5, 500);  // grout: or = op + 2.589 GfI / ft = 2.6e-5 m
  std::printf("grouted crack: peak traction %.4f MPa for ft_grout = %.4f MPa\n", again / 1e6,
              grout.tensile_strength / 1e6);
  EXPECT_NEAR(again, grout.tensile_strength, 0.01 * grout.tensile_strength);
  EXPECT_EQ(e.crack_state(0), CrackState::kBroken);  // and broke again, at the grout's strength
  // A zone given as triangles: nothing broken touches triangle 0 now but crack 0.
  const GroutingResult z = grout_broken_cracks(e, 1, cracks_touching(e, {0}));
  EXPECT_EQ(z.count, 1);
  EXPECT_EQ(e.broken_counts().total(), 1);
}

// broken_counts() is kept with the states rather than counted: after a
// fracturing UCS (with contact, 2 threads), after grouting half of its
// broken elements and after loading on, it equals a count of every
// element's state and mode through the public accessors, mode by mode.
TEST(BoltGrouting, broken_counts_follow_breakage_and_grouting) {
  auto counted = [](const Engine& e) {
    BrokenCounts b;
    for (std::size_t c = 0; c < e.n_cracks(); ++c) {
      if (e.crack_state(c) != CrackState::kBroken) continue;
      const FailureMode m = e.crack_mode(c);
      if (m == FailureMode::kModeI)
        ++b.mode_I;
      else if (m == FailureMode::kModeII)
        ++b.mode_II;
      else
        ++b.mixed;
    }
    return b;
  };
  auto expect_same = [](const BrokenCounts& kept, const BrokenCounts& scan, const char* when) {
    EXPECT_EQ(kept.mode_I, scan.mode_I) << when;
    EXPECT_EQ(kept.mode_II, scan.mode_II) << when;
    EXPECT_EQ(kept.mixed, scan.mixed) << when;
  };
  Material m = test::rock();
  m.damping_ratio = 0.1;
  ModelInput in = ucs_specimen(ucs_grid(0.02, 0.04, 800), m, 2.0);
  in.materials.push_back(m);  // the grout: the rock's law again
  in.threads = 2;
  in.contact.enabled = true;
  Engine e(in);
  e.run(4000);
  const BrokenCounts after_loading = e.broken_counts();
  expect_same(after_loading, counted(e), "after loading");
  ASSERT_GT(after_loading.total(), 20);
  EXPECT_GT(after_loading.mode_I + after_loading.mode_II, 0);
  const GroutingResult r = grout_broken_cracks(
      e, 1, [](std::size_t c, const Point2&) { return c % 2 == 0; });  // about half
  ASSERT_GT(r.count, 0);
  EXPECT_EQ(e.broken_counts().total(), after_loading.total() - long(r.count));
  expect_same(e.broken_counts(), counted(e), "after grouting");
  e.run(1000);
  expect_same(e.broken_counts(), counted(e), "after loading on");
}

}  // namespace
}  // namespace rockfdem::fdem
