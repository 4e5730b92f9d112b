// Boundary conditions: consistent traction split, pressure, gravity,
// kinematic conditions and their reactions.
#include <gtest/gtest.h>

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

// A column under gravity on a fixed base: at equilibrium the base reaction
// equals the weight (0.1%), and the vertical stress at mid-height is
// -rho g (H - y) (3%; the base is clamped, so not exactly uniaxial).
TEST(Boundary, gravity_column_reaction_equals_weight) {
  RectangleSpec spec;
  spec.width = 0.02;
  spec.height = 0.1;
  spec.nx = 4;
  spec.ny = 20;
  spec.fracture = false;
  const Material m = test::rock();
  ModelInput in = structured_rectangle(spec, m);
  BoundaryCondition base;
  base.tag = kTagBottom;
  base.x = base.y = Constraint::kFixed;
  in.boundary_conditions = {base};
  in.gravity_y = -9.81;
  in.damping.local = 0.8;
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
