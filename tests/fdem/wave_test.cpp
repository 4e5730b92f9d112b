// Dynamics: wave speed and energy conservation of the undamped scheme.
#include <gtest/gtest.h>

#include "rockfdem/fdem/constants.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

/// Node of the first engine node at the vertex nearest (x, y).
int node_near(const Engine& e, const ModelInput& in, double x, double y) {
  int best = 0;
  double d_best = 1e300;
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const int v = e.node_vertex()[n];
    const double d = std::hypot(in.x[v] - x, in.y[v] - y);
    if (d < d_best) d_best = d, best = static_cast<int>(n);
  }
  return best;
}

// A velocity step v0 at the left end reaches x = 0.8 L, at half amplitude,
// at 0.8 L / c_p within 2%.
TEST(Wave, p_wave_arrival_matches_cp) {
  const double length = 1.0, v0 = 0.1;
  ModelInput in = test::bar(length, 250, false);
  BoundaryCondition left;
  left.tag = kTagLeft;
  left.x = Constraint::kVelocity;
  left.vx = v0;
  in.boundary_conditions.push_back(left);
  Engine e(in);
  const int probe = node_near(e, in, 0.8 * length, length / 100);
  const double expect = 0.8 * length / test::p_wave_speed(in.materials[0]);
  double arrival = -1, prev_v = 0, prev_t = 0;
  while (e.time() < 1.5 * expect && arrival < 0) {
    e.step();
    const double v = e.velocities()[2 * probe];
    if (v >= 0.5 * v0) arrival = prev_t + (e.time() - prev_t) * (0.5 * v0 - prev_v) / (v - prev_v);
    prev_v = v;
    prev_t = e.time();
  }
  ASSERT_GT(arrival, 0);
  std::printf("arrival %.6g s, 0.8 L / c_p = %.6g s\n", arrival, expect);
  EXPECT_NEAR(arrival, expect, 0.02 * expect);
}

// A viscous absorbing end (-rho c_p v_n, -rho c_s v_t) swallows the front:
// after the step v0 has reached and "reflected" from it, the velocity near
// that end stays v0 within 5% (a free end would double it, a fixed one
// stop it).
TEST(Wave, absorbing_boundary_does_not_reflect) {
  const double length = 0.5, v0 = 0.1;
  ModelInput in = test::bar(length, 125, false);
  BoundaryCondition left, right;
  left.tag = kTagLeft;
  left.x = Constraint::kVelocity;
  left.vx = v0;
  right.tag = kTagRight;
  right.absorbing = true;
  in.boundary_conditions.push_back(left);
  in.boundary_conditions.push_back(right);
  in.threads = 1;
  Engine e(in);
  const int probe = node_near(e, in, 0.9 * length, length / 100);
  const double cp = test::p_wave_speed(in.materials[0]);
  const double t_end = 1.5 * length / cp;  // front at 0.9 L, end, and back past the probe
  while (e.time() < t_end) e.step();
  EXPECT_NEAR(e.velocities()[2 * probe], v0, 0.05 * v0);
}

// Undamped free vibration: kinetic (from the average of the half-step
// velocities around x_n) plus strain (plus crack) energy at x_n drifts by less
// than 0.5% over 1e4 steps, without and with crack elements on every edge.
TEST(Wave, undamped_vibration_conserves_energy) {
  for (bool fracture : {false, true}) {
    ModelInput in = test::bar(0.2, 40, fracture);
    in.boundary_conditions.clear();
    in.threads = 1;  // small model: threads would only add fork/join cost
    Engine e(in);
    for (std::size_t n = 0; n < e.n_nodes(); ++n) {
      const int v = e.node_vertex()[n];
      const double x = in.x[v], y = in.y[v];
      e.set_node_state(n, x, y, 0.5 * std::sin(kPi * x / 0.2), 0.05 * std::cos(7 * x / 0.2 + y));
    }
    const double e0 = test::energy_around_step(e);
    double worst = 0;
    for (int i = 0; i < 10000; ++i)
      worst = std::max(worst, std::fabs(test::energy_around_step(e) - e0) / e0);
    std::printf("fracture %d: largest energy deviation over 1e4 steps: %.3g\n", fracture, worst);
    EXPECT_LT(worst, 0.005);
    EXPECT_EQ(e.broken_counts().total(), 0);
  }
}

}  // namespace
}  // namespace rockfdem::fdem
