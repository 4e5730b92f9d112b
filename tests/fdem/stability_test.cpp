// Stability limit and blow-up detection.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

/// A small free specimen with random velocities: 4 x 4 cells with crack
/// elements everywhere (fracture) or one shared-node cell of two triangles.
Engine vibrating_specimen(bool fracture) {
  RectangleSpec spec;
  spec.width = 0.02;
  spec.height = 0.02;
  spec.nx = spec.ny = fracture ? 4 : 1;
  spec.fracture = fracture;
  Engine e(structured_rectangle(spec, test::rock()));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> v(-0.01, 0.01);
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], v(rng), v(rng));
  return e;
}

/// Largest kinetic energy over n steps relative to the initial one.
double kinetic_growth(Engine& e, long n) {
  const double k0 = e.kinetic_energy();
  double worst = 0;
  for (long i = 0; i < n; ++i) {
    e.step();
    worst = std::max(worst, e.kinetic_energy() / k0);
  }
  return worst;
}

// At 0.9 of the computed limit the energy stays bounded (the kinetic energy
// never exceeds 1.5 times the initial total, which is all kinetic).
TEST(Stability, bounded_at_0_9_of_critical_dt) {
  for (bool fracture : {false, true}) {
    Engine e = vibrating_specimen(fracture);
    e.set_dt(0.9 * e.critical_dt());
    EXPECT_LT(kinetic_growth(e, 20000), 1.5) << "fracture " << fracture;
  }
}

// Above the limit set_dt refuses, naming the limit; forced, the run blows up
// and is stopped with a NumericalError naming step and element. (On larger
// shared-node meshes the element bound is conservative and 1.1 may still be
// stable: see the stability sweep in docs/engine.md.)
TEST(Stability, refused_and_detected_at_1_1_of_critical_dt) {
  for (bool fracture : {false, true}) {
    Engine e = vibrating_specimen(fracture);
    const double limit = e.critical_dt();
    try {
      e.set_dt(1.1 * limit);
      FAIL() << "dt above the limit accepted";
    } catch (const InputError& err) {
      EXPECT_NE(std::string(err.what()).find("stability limit"), std::string::npos);
    }
    e.set_dt(1.1 * limit, DtCheck::kForce);
    try {
      e.run(20000);
      FAIL() << "unstable run not detected, fracture " << fracture;
    } catch (const NumericalError& err) {
      const std::string what = err.what();
      EXPECT_NE(what.find("step"), std::string::npos);
      EXPECT_TRUE(what.find("triangle") != std::string::npos ||
                  what.find("node") != std::string::npos);
    }
  }
}

// A stage change that lowers the limit (stiffening by 4 halves it): an
// automatic dt follows; an explicit dt above the new limit is refused at the
// next step, and can then be lowered.
TEST(Stability, stage_change_rechecks_the_time_step) {
  Engine automatic = vibrating_specimen(false);
  const double before = automatic.critical_dt();
  for (std::size_t t = 0; t < automatic.n_triangles(); ++t) automatic.set_stiffness_factor(t, 4);
  automatic.step();
  EXPECT_LT(automatic.critical_dt(), 0.75 * before);
  EXPECT_NEAR(automatic.dt(), automatic.stable_dt(), 1e-20);

  Engine explicit_dt = vibrating_specimen(false);
  explicit_dt.set_dt(0.9 * explicit_dt.critical_dt());
  for (std::size_t t = 0; t < explicit_dt.n_triangles(); ++t)
    explicit_dt.set_stiffness_factor(t, 4);
  EXPECT_THROW(explicit_dt.step(), InputError);
  explicit_dt.set_dt(0.9 * explicit_dt.critical_dt());
  EXPECT_NO_THROW(explicit_dt.run(100));
}

// An inverted triangle (J <= 0) stops the run, naming step and element.
TEST(Stability, inverted_triangle_names_step_and_element) {
  ModelInput in;
  in.x = {0, 0.01, 0, 0.01};
  in.y = {0, 0, 0.01, 0.01};
  in.triangles = {{0, 1, 2}, {1, 3, 2}};
  in.material = {0, 0};
  in.fracture = {1, 1};  // own nodes: triangle 1 has nodes 3, 4, 5
  in.materials = {test::rock()};
  Engine e(in);
  // Node 5 is triangle 1's third corner (vertex 2): drive it through edge 1-3.
  e.set_node_state(5, 0, 0.01, 1e4, 0);
  try {
    e.run(1000);
    FAIL() << "inversion not detected";
  } catch (const NumericalError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("triangle 1"), std::string::npos) << what;
    EXPECT_NE(what.find("step "), std::string::npos) << what;
    EXPECT_NE(what.find("inverted"), std::string::npos) << what;
  }
}

// A non-finite velocity stops the run at the next step, naming the step
// and the node, whether the node is free (found through its block's
// velocity sums) or has a boundary record (checked on its own): a node deep
// in a large model, in its second node block, and a corner node held by a
// roller.
TEST(Stability, non_finite_velocity_names_the_node) {
  RectangleSpec spec;
  spec.nx = 20;
  spec.ny = 40;
  ModelInput in = structured_rectangle(spec, test::rock());
  BoundaryCondition roller;
  roller.tag = kTagBottom;
  roller.y = Constraint::kFixed;
  in.boundary_conditions = {roller};
  in.threads = 1;
  for (bool on_boundary : {false, true}) {
    Engine e(in);
    e.run(3);
    std::size_t node = 0;
    for (std::size_t n = 0; n < e.n_nodes(); ++n) {
      const double y = in.y[e.node_vertex()[n]];
      if (on_boundary ? y == 0.0 : (n > 700 && y > 0.0)) {
        node = n;
        break;
      }
    }
    e.set_node_state(node, e.positions()[2 * node], e.positions()[2 * node + 1],
                     std::numeric_limits<double>::quiet_NaN(), 0.0);
    try {
      e.step();
      FAIL() << "non-finite velocity not detected";
    } catch (const NumericalError& err) {
      const std::string what = err.what();
      EXPECT_NE(what.find("step "), std::string::npos) << what;
      EXPECT_NE(what.find("node " + std::to_string(node) + " (mesh vertex"), std::string::npos)
          << what;
      EXPECT_NE(what.find("non-finite velocity"), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace rockfdem::fdem
