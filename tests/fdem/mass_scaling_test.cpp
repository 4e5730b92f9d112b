// Quasi-static mass scaling (MassScaling, mass_scaling.hpp): the densities
// change, the statics must not. Each test compares a mass-scaled run with a
// closed form or with the same model on its true masses.
//
// The model: a plate W x H graded along x (cells 20x narrower at the left
// than at the right, as a tunnel mesh grades away from the wall), rollers
// on the left and bottom sides, a traction on the right side: uniaxial
// stress sigma in plane strain, u_x(x) = sigma (1 - nu^2) / E x for
// constant-strain triangles without crack elements, up to the finite-strain
// law's departure from Hooke's, of the order of the strain (6e-5) itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kW = 1.0, kH = 0.5, kSigma = 2e6;

/// x in [0, W] mapped to W (e^(g x/W) - 1) / (e^g - 1): cell widths grow by
/// e^g (20x for g = 3) from left to right.
ModelInput graded_plate(bool fracture, double gravity = 0) {
  RectangleSpec spec;
  spec.width = kW;
  spec.height = kH;
  spec.nx = 24;
  spec.ny = 8;
  spec.fracture = fracture;
  ModelInput in = structured_rectangle(spec, test::rock());
  const double g = 3.0;
  for (double& x : in.x) x = kW * std::expm1(g * x / kW) / std::expm1(g);
  BoundaryCondition left, bottom, right;
  left.tag = kTagLeft;
  left.x = Constraint::kFixed;
  bottom.tag = kTagBottom;
  bottom.y = Constraint::kFixed;
  right.tag = kTagRight;
  right.tx = kSigma;
  in.boundary_conditions = {left, bottom, right};
  in.gravity_y = -gravity;
  in.damping.local = 0.8;
  // One thread: 384 triangles over tens of thousands of steps are all
  // barriers with more (ctest -j2 on 2 cores made this 30x slower).
  in.threads = 1;
  return in;
}

EquilibriumCriteria tight() {
  EquilibriumCriteria c;
  c.force_ratio = 1e-8;
  c.kinetic_ratio = 1e-10;
  c.check_interval = 50;
  c.max_steps = 400000;
  return c;
}

double max_abs_difference(const Engine& a, const Engine& b) {
  double d = 0;
  for (std::size_t n = 0; n < a.n_nodes(); ++n)
    for (int k = 0; k < 2; ++k)
      d = std::max(d, std::fabs(a.displacement(n)[k] - b.displacement(n)[k]));
  return d;
}

// Without crack elements: every node's u_x equals sigma (1 - nu^2) / E x
// within 2 strain (finite strain, above) of the right side's displacement,
// with true and with scaled masses, and the two runs agree within 1e-6 of
// it; the scaled run gets there in at least 3x fewer steps (measured 3.8x:
// 14,000 against 3,650; a larger target step changes nothing, a smaller one
// needs more steps: 0.5x 3,950, 0.25x 6,500).
TEST(MassScaling, elastic_plate_reaches_the_exact_static_answer_in_fewer_steps) {
  const Material rock = test::rock();
  const double strain = kSigma * (1 - rock.poisson * rock.poisson) / rock.young;
  long steps[2] = {0, 0};
  ModelInput in = graded_plate(false);
  Engine reference(in);
  for (int scaled = 0; scaled < 2; ++scaled) {
    in.mass_scaling.enabled = scaled == 1;
    Engine e(in);
    const EquilibriumResult r = e.run_to_equilibrium(tight());
    if (scaled == 0) reference.run_to_equilibrium(tight());
    ASSERT_TRUE(r.converged) << "scaled " << scaled << " ratio " << r.force_ratio;
    steps[scaled] = r.steps;
    double worst = 0;
    for (std::size_t n = 0; n < e.n_nodes(); ++n) {
      const double x = e.positions()[2 * n] - e.displacement(n)[0];
      worst = std::max(worst, std::fabs(e.displacement(n)[0] - strain * x));
    }
    EXPECT_LT(worst, 2 * strain * strain * kW) << "scaled " << scaled;
    EXPECT_LT(max_abs_difference(e, reference), 1e-6 * strain * kW);
    std::printf("%s masses: %ld steps of %.3g s, worst u_x error %.3g of the end's\n",
                scaled ? "scaled" : "true", r.steps, e.dt(), worst / (strain * kW));
  }
  EXPECT_LT(3 * steps[1], steps[0]);
}

// With crack elements (intact, penalty 10 E) no closed form is at hand: the
// scaled run must land on the true-mass run's equilibrium, every node
// within 1e-6 of the largest displacement, in at least 1.6x fewer steps
// (measured 2.0x: 30,500 against 15,000; the stiff crack penalties inside
// each element, not the grading, then set the conditioning); the scaled
// run's first 2,000 steps are the same bits with 1 and 2 threads.
TEST(MassScaling, cracked_plate_lands_on_the_true_mass_equilibrium) {
  ModelInput in = graded_plate(true);
  Engine reference(in);
  const EquilibriumResult r0 = reference.run_to_equilibrium(tight());
  ASSERT_TRUE(r0.converged);
  in.mass_scaling.enabled = true;
  Engine e(in);
  const EquilibriumResult r = e.run_to_equilibrium(tight());
  ASSERT_TRUE(r.converged);
  const double u_end = std::fabs(reference.displacement(reference.n_nodes() - 1)[0]);
  EXPECT_LT(max_abs_difference(e, reference), 1e-6 * u_end);
  EXPECT_LT(1.6 * r.steps, r0.steps);
  std::printf("cracked plate: %ld steps true, %ld scaled\n", r0.steps, r.steps);
  std::string hash[2];
  for (int threads : {1, 2}) {
    in.threads = threads;
    Engine t(in);
    t.run(2000);
    hash[threads - 1] = t.state_hash();
  }
  EXPECT_EQ(hash[0], hash[1]);
}

// The factors: the target is the least constrained node's own limit (here
// 5x the true-mass step), the model's step lands within [0.8, 1.5] of it
// (Lanczos against the node bound), the finest triangles carry
// factors above 20 (measured 43) and the node masses add up to the
// factors' masses.
TEST(MassScaling, every_node_is_brought_to_the_target_step) {
  ModelInput in = graded_plate(true);
  const double true_dt = Engine(in).critical_dt();
  in.mass_scaling.enabled = true;
  Engine e(in);
  const MassScalingReport r = e.mass_scaling_report();
  ASSERT_TRUE(r.enabled);
  EXPECT_GT(r.target_dt, 5 * true_dt);
  EXPECT_GT(e.critical_dt(), 0.8 * r.target_dt);
  EXPECT_LT(e.critical_dt(), 1.5 * r.target_dt);
  EXPECT_GT(r.max_factor, 20.0);
  EXPECT_GT(r.mass_ratio, 1.0);
  double mass = 0;
  for (double m : e.node_mass()) mass += m;
  // Each node's mass as stored (test::kStored), the sum in double.
  EXPECT_NEAR(mass, r.mass_ratio * test::rock().density * kW * kH, 2 * test::kStored * mass);
  std::printf(
      "target %.3g s (true-mass limit %.3g s), limit now %.3g s, max factor %.3g, "
      "mass ratio %.3g\n",
      r.target_dt, true_dt, e.critical_dt(), r.max_factor, r.mass_ratio);
}

// Gravity acts on the true masses: a plate on rollers under its own weight
// (no traction) pushes on its base with rho g W H, scaled masses or not.
TEST(MassScaling, gravity_loads_the_true_weight) {
  const double g = 9.81;
  ModelInput in = graded_plate(false, g);
  in.boundary_conditions.pop_back();  // no traction
  in.mass_scaling.enabled = true;
  Engine e(in);
  const EquilibriumResult r = e.run_to_equilibrium(tight());
  ASSERT_TRUE(r.converged);
  const double weight = test::rock().density * g * kW * kH;
  EXPECT_NEAR(e.boundary_force(kTagBottom)[1], weight, 1e-6 * weight);
}

// Stage changes keep the target: stiffening a corner of the plate a
// hundredfold (as a bolt's steel does) raises its factors, not the
// model's step; switching the scaling off restores the true masses.
TEST(MassScaling, stage_changes_keep_the_target_step) {
  ModelInput in = graded_plate(true);
  in.mass_scaling.enabled = true;
  Engine e(in);
  const double target = e.mass_scaling_report().target_dt, limit = e.critical_dt();
  for (std::size_t t = 0; t < 8; ++t) e.set_stiffness_factor(t, 100.0);
  EXPECT_EQ(e.mass_scaling_report().target_dt, target);
  EXPECT_GT(e.critical_dt(), 0.9 * limit);
  e.run(200);  // stable at the retained step
  EXPECT_LT(e.kinetic_energy(), 1.0);
  const double true_mass = test::rock().density * kW * kH;
  e.set_mass_scaling(MassScaling{});
  double mass = 0;
  for (double m : e.node_mass()) mass += m;
  EXPECT_NEAR(mass, true_mass, test::kStored * true_mass);  // each mass as stored
  EXPECT_FALSE(e.mass_scaling_report().enabled);
}

/// Small pseudo-random velocities on every node (a disturbed state).
void shake(Engine& e, double amplitude) {
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const double a = std::sin(12.9898 * double(n)) * 43758.5453;
    const double r = a - std::floor(a) - 0.5;
    e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], amplitude * r,
                     -amplitude * r);
  }
}

// Absorbing dashpots are explicit (-C v_old) and set a limit of their own
// (c dt / m < 2) that the Lanczos iteration does not see; the node bound and
// the factors include them. With absorbing right and top sides on the
// plate's coarsest cells, a disturbed plate on scaled masses at the default
// step stays stable and loses its energy through the dashpots (before they
// were in the limit it blew up at step 11).
TEST(MassScaling, absorbing_sides_stay_stable_on_scaled_masses) {
  for (const bool scaled : {false, true}) {
    ModelInput in = graded_plate(true);
    in.boundary_conditions.pop_back();  // no traction
    in.damping.local = 0;
    for (int tag : {kTagRight, kTagTop}) {
      BoundaryCondition bc;
      bc.tag = tag;
      bc.absorbing = true;
      in.boundary_conditions.push_back(bc);
    }
    in.mass_scaling.enabled = scaled;
    Engine e(in);
    shake(e, 0.05);
    ASSERT_NO_THROW(e.run(1));
    const double k0 = e.kinetic_energy();
    ASSERT_NO_THROW(e.run(20000)) << "scaled " << scaled;
    EXPECT_LT(e.kinetic_energy(), 0.5 * k0) << "scaled " << scaled;
    EXPECT_GT(e.energy_balance().absorbing, 0.0);
  }
}

// Mass-proportional damping c m v caps any step at 2 / c however heavy
// the nodes: the factors stop at 80% of that cap instead of growing
// without bound (they reached 1.8e12 before), and the model still steps.
TEST(MassScaling, strong_mass_damping_caps_the_target_not_the_factors) {
  ModelInput in = graded_plate(true);
  in.mass_scaling.enabled = true;
  Engine e(in);
  const double target = e.mass_scaling_report().target_dt * std::sqrt(1.0 + in.damping.local);
  const double base_factor = e.mass_scaling_report().max_factor;
  const double c = 10 * 2.0 / target;  // a cap 10x below the target
  e.set_damping({in.damping.local, c});
  const MassScalingReport r = e.mass_scaling_report();
  EXPECT_LT(r.max_factor, 10 * base_factor) << r.max_factor;
  EXPECT_GT(e.critical_dt(), 0.5 * 2.0 / (1.25 * c) / std::sqrt(1.0 + in.damping.local));
  ASSERT_NO_THROW(e.run(500));
}

// A rescale keeps each node's momentum: stiffening a third of a moving
// plate's triangles (their factors rise) takes kinetic energy out, never
// puts it in (with the velocities kept it rose), and the ledger books the
// change exactly.
TEST(MassScaling, rescaling_keeps_momentum_and_adds_no_energy) {
  ModelInput in = graded_plate(true);
  in.mass_scaling.enabled = true;
  Engine e(in);
  shake(e, 0.05);
  e.run(50);
  double p0[2] = {0, 0};
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    for (int k = 0; k < 2; ++k) p0[k] += e.node_mass()[n] * e.velocities()[2 * n + k];
  const EnergyBalance b0 = e.energy_balance();
  const double k0 = e.kinetic_energy();
  for (std::size_t t = 0; t < e.n_triangles(); t += 3) e.set_stiffness_factor(t, 50.0);
  e.node_mass();  // brings the masses up to date: the new factors
  const double k1 = e.kinetic_energy();
  double p1[2] = {0, 0}, scale = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    for (int k = 0; k < 2; ++k) {
      p1[k] += e.node_mass()[n] * e.velocities()[2 * n + k];
      scale += std::fabs(e.node_mass()[n] * e.velocities()[2 * n + k]);
    }
  EXPECT_LE(k1, k0);
  EXPECT_LT(k1, 0.9 * k0);  // the stiffened triangles' nodes did get heavier
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(p1[k], p0[k], 1e-12 * scale);
  // The change is booked exactly: the residual is where it was (the
  // shake's own discretisation residual stays as it is). The booked change
  // includes the strain energy's, which is measured at the half-step
  // placement x - v dt/2 and so moves with the velocities.
  const EnergyBalance b1 = e.energy_balance();
  EXPECT_NE(b1.removed, b0.removed);
  EXPECT_NEAR(b1.residual(), b0.residual(), 1e-9 * (b1.stored() + b1.dissipated()));
}

}  // namespace
}  // namespace rockfdem::fdem
