// Boundary conditions: consistent traction split, pressure, gravity,
// kinematic conditions and their reactions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

/// Sum of the nodal forces over the engine nodes of each mesh vertex.
std::map<int, std::array<double, 2>> force_per_vertex(const Engine& e) {
  std::map<int, std::array<double, 2>> f;
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    auto& v = f[e.node_vertex()[n]];
    v[0] += e.node_force(n)[0];
    v[1] += e.node_force(n)[1];
  }
  return f;
}

// A constant traction t on an edge of length L puts t L / 2 on each end:
// interior boundary vertices get t h, corners t h / 2 (exact to rounding).
TEST(Boundary, traction_consistent_split) {
  for (bool fracture : {false, true}) {
    RectangleSpec spec;
    spec.width = 0.03;
    spec.height = 0.04;
    spec.nx = 3;
    spec.ny = 4;
    spec.fracture = fracture;
    ModelInput in = structured_rectangle(spec, test::rock());
    BoundaryCondition right, top;
    right.tag = kTagRight;
    right.tx = 2e6;
    right.ty = -1e6;
    top.tag = kTagTop;
    top.pressure = 3e6;  // pushes into the body: -y
    in.boundary_conditions = {right, top};
    Engine e(in);
    const double h = 0.01;
    for (const auto& [v, f] : force_per_vertex(e)) {
      const double x = in.x[v], y = in.y[v];
      double ex = 0, ey = 0;
      if (std::fabs(x - 0.03) < 1e-12) {
        const double share = (y < 1e-12 || y > 0.04 - 1e-12) ? 0.5 : 1.0;
        ex += 2e6 * h * share;
        ey += -1e6 * h * share;
      }
      if (std::fabs(y - 0.04) < 1e-12) {
        const double share = (x < 1e-12 || x > 0.03 - 1e-12) ? 0.5 : 1.0;
        ey += -3e6 * h * share;
      }
      EXPECT_NEAR(f[0], ex, 1e-9 * 2e4) << "vertex " << v << " fracture " << fracture;
      EXPECT_NEAR(f[1], ey, 1e-9 * 2e4) << "vertex " << v << " fracture " << fracture;
    }
  }
}

/// An elastic 0.02 x 0.1 m column of nx x ny cells on a fixed base under
/// gravity, with local damping 0.8.
ModelInput gravity_column(int nx, int ny) {
  RectangleSpec spec;
  spec.width = 0.02;
  spec.height = 0.1;
  spec.nx = nx;
  spec.ny = ny;
  spec.fracture = false;
  ModelInput in = structured_rectangle(spec, test::rock());
  BoundaryCondition base;
  base.tag = kTagBottom;
  base.x = base.y = Constraint::kFixed;
  in.boundary_conditions = {base};
  in.gravity_y = -9.81;
  in.damping.local = 0.8;
  return in;
}

// A column under gravity on a fixed base: at equilibrium the base reaction
// equals the weight (0.1%), and the vertical stress at mid-height is
// -rho g (H - y) (3%; the base is clamped, so not exactly uniaxial).
TEST(Boundary, gravity_column_reaction_equals_weight) {
  const Material m = test::rock();
  const ModelInput in = gravity_column(4, 20);
  Engine e(in);
  EquilibriumCriteria c;
  c.force_ratio = 1e-6;
  c.kinetic_ratio = 1e-8;
  c.max_steps = 100000;
  EXPECT_TRUE(e.run_to_equilibrium(c).converged);
  const double weight = m.density * 9.81 * 0.02 * 0.1;
  const auto reaction = e.boundary_force(kTagBottom);
  EXPECT_NEAR(reaction[1], weight, 1e-3 * weight);
  EXPECT_NEAR(reaction[0], 0.0, 1e-3 * weight);
  double syy = 0;
  int n = 0;
  for (std::size_t t = 0; t < e.n_triangles(); ++t) {
    const auto nodes = e.triangle_nodes(t);
    double yc = 0;
    for (int k : nodes) yc += in.y[e.node_vertex()[k]] / 3;
    if (std::fabs(yc - 0.05) < 0.005) {
      syy += e.triangle_stress(t)[1];
      ++n;
    }
  }
  syy /= n;
  const double expect = -m.density * 9.81 * 0.05;
  EXPECT_NEAR(syy, expect, 0.03 * std::fabs(expect));
}

// Gravity pulls a softened triangle (stiffness factor below 1: the
// excavation's core) with that factor of its weight, a stiffened one (a bolt
// strip, factor above 1) with its true weight: the base reaction of the
// column at equilibrium is 0.4 and 1 times the weight (0.1%).
TEST(Boundary, gravity_scales_with_softening_not_with_stiffening) {
  const double weight = test::rock().density * 9.81 * 0.02 * 0.1;
  for (const double factor : {0.4, 2.0}) {
    Engine e(gravity_column(2, 10));
    for (std::size_t t = 0; t < e.n_triangles(); ++t) e.set_stiffness_factor(t, factor);
    EquilibriumCriteria c;
    c.force_ratio = 1e-6;
    c.kinetic_ratio = 1e-8;
    c.max_steps = 100000;
    EXPECT_TRUE(e.run_to_equilibrium(c).converged) << "factor " << factor;
    const double expect = std::min(factor, 1.0) * weight;
    EXPECT_NEAR(e.boundary_force(kTagBottom)[1], expect, 1e-3 * weight) << "factor " << factor;
  }
}

// A block detached from the rock above an opening falls at g: the upper of
// two blocks, 10 mm above the lower, falls g t^2 / 2 in 30 ms (4.4 mm, before
// it lands; 0.1%). Local damping takes alpha |f| against the motion, so
// under the quasi-static stages' damping (alpha = 0.3) the same block falls
// at (1 - alpha) g: a loose block's fall is slowed, never stopped, and its
// time is not real time (docs/engine.md).
TEST(Boundary, detached_block_falls_at_g_or_at_the_damped_rate) {
  for (const double local : {0.0, 0.3}) {
    ModelInput in = test::two_blocks(0.01, test::rock());
    in.gravity_y = -9.81;
    in.contact.enabled = true;
    in.damping.local = local;
    in.threads = 1;
    Engine e(in);
    std::vector<char> upper(e.n_nodes(), 0);
    for (std::size_t t = 2 * (e.n_triangles() / 3); t < e.n_triangles(); ++t)
      for (int n : e.triangle_nodes(t)) upper[n] = 1;
    const long steps = std::lround(0.03 / e.dt());
    e.run(steps);
    double fall = 0, mass = 0;
    for (std::size_t n = 0; n < e.n_nodes(); ++n)
      if (upper[n]) {
        fall -= e.node_mass()[n] * e.displacement(n)[1];
        mass += e.node_mass()[n];
      }
    fall /= mass;
    const double t = steps * e.dt(), expect = 0.5 * (1 - local) * 9.81 * t * t;
    std::printf("local damping %.1f: fell %.6g m in %.4g s, (1 - alpha) g t^2 / 2 = %.6g m\n",
                local, fall, t, expect);
    EXPECT_NEAR(fall, expect, 1e-3 * expect) << "local damping " << local;
  }
}

// Inactive triangles carry no mass or force; crack elements need both sides.
TEST(Boundary, inactive_triangles_drop_mass_and_cracks) {
  Engine e(test::two_triangles(0.01, test::rock()));
  const double m_all = e.node_mass()[0] + e.node_mass()[3];
  e.set_active(1, false);
  EXPECT_DOUBLE_EQ(e.node_mass()[3], 0.0);
  EXPECT_DOUBLE_EQ(e.node_mass()[0], m_all / 2);
  e.set_node_state(3, 0, 0.001, 0, 0);  // would open the crack if it acted
  e.step();
  EXPECT_DOUBLE_EQ(e.node_force(0)[1], 0.0);
  EXPECT_EQ(e.crack_state(0), CrackState::kIntact);
  e.set_active(1, true, ActivationReference::kCurrent);
  EXPECT_GT(e.node_mass()[3], 0.0);
}

}  // namespace
}  // namespace rockfdem::fdem
