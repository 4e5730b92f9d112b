// Pull-out of a grouted bolt from a rock block through the whole bolt
// pipeline (mark, plan, install, outputs). Closed form: with a friction-free
// grout (phi = 0, so the Mohr-Coulomb strength is c whatever the normal
// stress) the interface can carry at most its cohesion on both faces of the
// bonded length, P = 2 c L_b. The grout's softening range (GfII = 5000 J/m^2,
// sr - sp = 6.5 mm) is far above the slip difference along the bond at the
// peak (bolt and block stretch, about 0.04 mm with a 300 GPa block), and
// the Evans-Marathe curve is flat at D = 0 (z'(0) = 0), so the whole bond
// is near its peak together: the measured peak must be 2 c L_b within 3%
// (the tip face's tension, ft d = 1.1% of P, and the remaining progressive
// debonding share that). With a 30 GPa block and GfII = 1000 the same test
// peaks at 76% of 2 c L_b: the rock's stretch (0.1 mm) debonds the head first.
#include <gtest/gtest.h>

#include <algorithm>

#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/bolt_output.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

// Block 0.5 x 0.125 m (20 x 5 cells of 25 mm, rock without fracture), bolt
// d = 25 mm along the middle row from x = 0.2 to the right face; the last
// column of rock (x > 0.475) is removed, so the bolt's head sticks out and
// the bond runs over L_b = 0.275 m on the top and bottom faces. The block's
// left face is held; the bolt head is pulled at 0.02 m/s.
TEST(BoltPullout, load_rises_peaks_at_grout_capacity_and_drops) {
  RectangleSpec spec;
  spec.width = 0.5;
  spec.height = 0.125;
  spec.nx = 20;
  spec.ny = 5;
  spec.fracture = false;
  Material rock = test::rock();
  rock.young = 300e9;  // a stiff block: its stretch along the bond stays small (see below)
  ModelInput in = structured_rectangle(spec, rock);
  constexpr int kFree = 9;
  for (auto& e : in.edges)  // only the bolt's end face keeps the right tag
    if (e.tag == kTagRight && std::min(in.y[e.a], in.y[e.b]) != in.y[2 * 21]) e.tag = kFree;
  BoltSpec bolt;
  bolt.bolt = {{0.5, 0.0625}, {0.2, 0.0625}, 0.025};  // head A on the right face
  Material& grout = bolt.grout;
  grout.young = 10e9;
  grout.tensile_strength = 0.5e6;
  grout.cohesion = 2e6;
  grout.friction_deg = 0;
  grout.gf_I = 500;  // a ductile opening range too: the bond also opens a little (mixed damage)
  grout.gf_II = 5000;
  BoltPlan plan = plan_bolts(in, {bolt});
  ASSERT_EQ(plan.owned[0].size(), 24u);
  BoundaryCondition held, pull;
  held.tag = kTagLeft;
  held.x = held.y = Constraint::kFixed;
  pull.tag = kTagRight;
  pull.x = Constraint::kVelocity;
  pull.vx = 0.02;
  in.boundary_conditions = {held, pull};
  in.damping.local = 0.7;
  Engine e(in);
  e.set_threads(1);
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const auto& v = in.triangles[t];
    const double cx = (in.x[v[0]] + in.x[v[1]] + in.x[v[2]]) / 3;
    if (cx > 0.475 && plan.marks.owner[t] < 0) e.set_active(t, false);
  }
  const BoltInstallReport report = install_bolts(e, plan);
  EXPECT_EQ(report.triangles, 24);
  EXPECT_EQ(report.steel_cracks, 23);  // 11 across, 12 diagonals
  const double capacity = 2 * grout.cohesion * 0.275;
  double peak = 0, u_peak = 0, u = 0, load = 0, steel_at_peak = 0;
  while (u < 8e-3) {
    if (u > 6e-4 && pull.vx < 0.5) {  // well past the peak: speed up (the peak is read before)
      pull.vx = 0.5;
      e.set_boundary_conditions({held, pull});
    }
    e.run(50);
    u += 50 * e.dt() * pull.vx;
    load = e.boundary_force(kTagRight)[0];
    if (load > peak && pull.vx < 0.5) {
      peak = load;
      u_peak = u;
      const auto profile = bolt_axial_profile(e, plan, 0);  // the free cell's two triangles
      steel_at_peak = 0.5 * (profile[0].force_per_metre + profile[1].force_per_metre);
    }
  }
  const BoltCounts counts = bolt_counts(e, plan, 0);
  std::printf(
      "pull-out: peak %.1f kN/m at %.3e m (2 c L_b = %.1f kN/m), head strip %.1f kN/m, "
      "end load %.1f kN/m, grout broken %ld of %ld\n",
      peak / 1e3, u_peak, capacity / 1e3, steel_at_peak / 1e3, load / 1e3, counts.grout_broken,
      counts.grout_cracks);
  EXPECT_NEAR(peak, capacity, 0.03 * capacity);
  EXPECT_GT(u_peak, 1e-6);        // it rose first
  EXPECT_LT(load, 0.3 * peak);    // and dropped
  EXPECT_EQ(counts.yielding, 0);  // the steel stayed elastic (44 MPa)
  EXPECT_EQ(counts.broken, 0);
  EXPECT_GT(counts.grout_broken, 20);
  // The free cell carries the pull: its force per metre matches the load (3%).
  EXPECT_NEAR(steel_at_peak, peak, 0.03 * peak);
}

}  // namespace
}  // namespace rockfdem::fdem
