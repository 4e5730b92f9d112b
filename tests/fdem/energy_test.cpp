// Energy balance: work of external forces = change of the stored
// energies + what damping, fracture, friction and absorbing boundaries
// dissipated + what stage controls took out. Engine::energy_balance()
// computes every term on its own (closed forms for the stored ones,
// mechanisms accumulated every step for the others), so each test below
// can fail: a term booked twice, missed or taken at the wrong velocity shows
// as an imbalance. Where a test compares a term with a figure of its own
// (the energy a vibration lost, the sliding block's kinetic energy), that
// figure comes from the public state alone, not from the ledger.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/crack_law.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

void print(const char* what, const EnergyBalance& b) {
  std::printf(
      "%s: W %.5g | K %.5g U %.5g crack %.5g contact %.5g (initial %.5g) | damping %.5g "
      "fracture %.5g friction %.5g absorbing %.5g | softening %.4g removed %.4g | "
      "imbalance %.3g\n",
      what, b.external_work, b.kinetic, b.strain, b.crack_elastic, b.contact_elastic,
      b.initial_stored, b.damping, b.fracture, b.friction, b.absorbing, b.softening, b.removed,
      b.imbalance());
}

// --- 1. Elastic waves -------------------------------------------------------

/// A 1 m bar (test::bar) loaded at its left end for 0.2 L / c_p, by a
/// traction or a prescribed velocity, then left free (traction) or held
/// (velocity); the right end is free or absorbing.
struct WaveCase {
  const char* name;
  bool velocity;   ///< prescribed velocity instead of a traction
  bool fracture;   ///< crack elements on every edge (intact: they store energy)
  bool absorbing;  ///< absorbing right end
};

// No damping: the pulse travels, reflects (or is absorbed) and the balance
// closes within 1% at every check, from a tenth of the pulse on. At half a
// transit the pulse is all in the bar: kinetic and strain energy then each
// hold about half the work (here more than 30% each), so neither is trivially
// zero. With an absorbing end the dashpots take most of the work.
TEST(EnergyBalance, elastic_wave_closes_within_1_percent) {
  const WaveCase cases[] = {{"traction", false, false, false},
                            {"velocity", true, false, false},
                            {"traction, crack elements", false, true, false},
                            {"velocity, absorbing end", true, false, true}};
  for (const WaveCase& wc : cases) {
    const double length = 1.0;
    ModelInput in = test::bar(length, 125, wc.fracture);
    const auto rollers = in.boundary_conditions;
    BoundaryCondition load;
    load.tag = kTagLeft;
    if (wc.velocity) {
      load.x = Constraint::kVelocity;
      load.vx = 0.05;
    } else {
      load.tx = 2e6;  // pushes the end into the bar
    }
    BoundaryCondition right;
    right.tag = kTagRight;
    right.absorbing = wc.absorbing;
    in.boundary_conditions.push_back(load);
    in.boundary_conditions.push_back(right);
    in.threads = 1;  // 1000 triangles: threads would only add fork/join cost
    Engine e(in);
    const double transit = length / test::p_wave_speed(in.materials[0]);
    std::vector<BoundaryCondition> after = rollers;
    if (wc.velocity) {  // the piston stops and holds
      BoundaryCondition held;
      held.tag = kTagLeft;
      held.x = Constraint::kFixed;
      after.push_back(held);
    }
    after.push_back(right);
    bool unloaded = false;
    double worst = 0;
    for (double check : {0.05, 0.1, 0.2, 0.35, 0.5, 0.8, 1.0, 1.3, 1.6, 2.0}) {
      while (e.time() < check * transit) {
        if (!unloaded && e.time() >= 0.2 * transit) {
          e.set_boundary_conditions(after);
          unloaded = true;
        }
        e.step();
      }
      const EnergyBalance b = e.energy_balance();
      std::printf("%s, t = %.2f L/c_p: ", wc.name, check);
      print("", b);
      EXPECT_GT(b.external_work, 0.0);
      worst = std::max(worst, std::fabs(b.imbalance()));
      if (check == 0.5 && !wc.absorbing) {
        EXPECT_GT(b.kinetic, 0.3 * b.external_work) << wc.name;
        EXPECT_GT(b.strain + b.crack_elastic, 0.3 * b.external_work) << wc.name;
      }
      if (check == 2.0 && wc.absorbing) {
        EXPECT_GT(b.absorbing, 0.8 * b.external_work);
      }
    }
    std::printf("%s: largest |imbalance| %.3g\n", wc.name, worst);
    EXPECT_LT(worst, 0.01) << wc.name;
  }
}

// --- 2. Fracturing UCS --------------------------------------------------------

/// The 800-triangle UCS of the contact test: rough platens closing at 2 m/s
/// each (prescribed velocities: their reactions' work is the external work),
/// 10% viscous damping, local damping 0.05, contact with friction.
ModelInput fracturing_ucs(double friction_deg) {
  RectangleSpec grid = ucs_grid(0.02, 0.04, 800);
  Material m = test::rock();
  m.damping_ratio = 0.1;
  m.friction_deg = friction_deg;
  ModelInput in = ucs_specimen(grid, m, 2.0);
  in.damping.local = 0.05;
  in.contact.enabled = true;
  return in;
}

/// Sum over broken crack elements of their length times the fracture
/// energy of their mode (mixed: the mean of GfI and GfII).
double broken_fracture_energy(const Engine& e, const Material& m) {
  double sum = 0;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    if (e.crack_state(c) != CrackState::kBroken) continue;
    const auto n = e.crack_nodes(c);
    const auto& p = e.positions();
    const double h =
        0.5 * std::hypot(p[2 * n[1]] + p[2 * n[2]] - p[2 * n[0]] - p[2 * n[3]],
                         p[2 * n[1] + 1] + p[2 * n[2] + 1] - p[2 * n[0] + 1] - p[2 * n[3] + 1]);
    const FailureMode mode = e.crack_mode(c);
    sum += h * (mode == FailureMode::kModeI    ? m.gf_I
                : mode == FailureMode::kModeII ? m.gf_II
                                               : 0.5 * (m.gf_I + m.gf_II));
  }
  return sum;
}

// Past the peak, with 150 and more crack elements broken, the balance
// closes within 3% at every check. Fracture energy: each broken element
// released its pre-peak energy (negligible here) plus about the fracture
// energy of its mode times its length (exactly Gf for a pure mode; a mixed
// path differs), plus its compressive penalty energy net of what contact
// took over; damaged unbroken elements released part of theirs. Accepted:
// 0.8 to 1.5 times the broken elements' sum of Gf h.
//
// The same specimen with a friction angle of 0 (shear strength c, no
// Mohr-Coulomb coupling) must close within 0.5%: the coupling is the rock
// law's one non-conservative part (docs/engine.md), and without it what is
// left measures the ledger.
TEST(EnergyBalance, fracturing_ucs_closes_within_3_percent) {
  for (double friction_deg : {30.0, 0.0}) {
    ModelInput in = fracturing_ucs(friction_deg);
    in.threads = 1;
    Engine e(in);
    double worst = 0;
    for (int chunk = 1; chunk <= 10; ++chunk) {
      e.run(500);
      const EnergyBalance b = e.energy_balance();
      std::printf("phi %g, step %ld, broken %ld: ", friction_deg, e.step_count(),
                  e.broken_counts().total());
      print("", b);
      worst = std::max(worst, std::fabs(b.imbalance()));
    }
    const EnergyBalance b = e.energy_balance();
    const double gf_h = broken_fracture_energy(e, in.materials[0]);
    std::printf(
        "phi %g: largest |imbalance| %.3g; fracture %.4g J/m, broken elements' Gf h %.4g "
        "(ratio %.3f)\n",
        friction_deg, worst, b.fracture, gf_h, b.fracture / gf_h);
    EXPECT_GT(e.broken_counts().total(), 100);
    EXPECT_GT(e.contact_counters().touching, 0);
    EXPECT_GT(b.friction, 0.0);
    EXPECT_LT(worst, friction_deg > 0 ? 0.03 : 0.005);
    EXPECT_GT(b.fracture, 0.8 * gf_h);
    EXPECT_LT(b.fracture, 1.5 * gf_h);
  }
}

// --- 3. Damping alone -----------------------------------------------------------

// A free bar (no supports) set vibrating by an initial velocity field, with
// one kind of damping at a time: viscous (eta D in the triangles), mass
// proportional, local. After 4000 steps the vibration has lost a good part of
// its energy (at least 20%); what the ledger calls damping equals that loss,
// measured from the state alone, within 1%.
TEST(EnergyBalance, damping_dissipates_what_the_vibration_loses) {
  enum Kind { kViscous, kMass, kLocal };
  for (Kind kind : {kViscous, kMass, kLocal}) {
    Material m = test::rock();
    if (kind == kViscous) m.damping_ratio = 0.3;
    ModelInput in = test::bar(0.2, 20, false);
    in.materials = {m};
    in.boundary_conditions.clear();
    if (kind == kMass) in.damping.mass_proportional = 2e4;
    if (kind == kLocal) in.damping.local = 0.02;
    in.threads = 1;
    Engine e(in);
    for (std::size_t n = 0; n < e.n_nodes(); ++n) {
      const int v = e.node_vertex()[n];
      const double x = in.x[v], y = in.y[v];
      e.set_node_state(n, x, y, 0.5 * std::sin(kPi * x / 0.2) + 0.4 * std::sin(6 * kPi * x / 0.2),
                       0.05 * std::cos(17 * x / 0.2 + y));
    }
    const double e0 = e.kinetic_energy();  // at rest position: all kinetic
    e.run(3999);
    const double e1 = test::energy_around_step(e);  // step 4000
    const EnergyBalance b = e.energy_balance();
    const double lost = e0 - e1;
    std::printf("damping kind %d: energy %.6g -> %.6g, lost %.6g, ledger damping %.6g (%.3g%%)\n",
                kind, e0, e1, lost, b.damping, 100 * (b.damping - lost) / lost);
    print("  balance", b);
    EXPECT_GT(lost, 0.2 * e0) << "kind " << kind;
    EXPECT_NEAR(b.damping, lost, 0.01 * lost) << "kind " << kind;
    EXPECT_LT(std::fabs(b.imbalance()), 0.01) << "kind " << kind;
  }
}

// --- 4. Friction ----------------------------------------------------------------

// A block thrown at 0.2 m/s along a fixed base under gravity (friction
// 20 deg, no damping) slides to rest in about g mu t. Friction then holds
// what the block lost: its kinetic energy plus the work of gravity (the
// block settles by the contact's penetration), minus the energy left in
// elastic vibration and in the contact; all from the public state (gravity's
// work from the nodes' heights) except the small contact term. Within 2%.
TEST(EnergyBalance, friction_dissipates_the_sliding_blocks_energy) {
  Material m = test::rock();
  m.residual_friction_deg = 20;
  ModelInput in = test::two_blocks(0.0, m);
  const double g = 9.81;
  in.gravity_y = -g;
  in.contact.enabled = true;
  in.threads = 1;
  Engine e(in);
  std::vector<char> upper(e.n_nodes(), 0);
  for (std::size_t t = 2 * (e.n_triangles() / 3); t < e.n_triangles(); ++t)
    for (int n : e.triangle_nodes(t)) upper[n] = 1;
  const double v0 = 0.2;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    if (upper[n]) e.set_node_state(n, e.positions()[2 * n], e.positions()[2 * n + 1], v0, 0);
  const double k0 = e.kinetic_energy();
  const std::vector<double> y0 = e.positions();
  const double t_stop = v0 / (g * std::tan(20 * kPi / 180));
  e.run(std::lround(1.3 * t_stop / e.dt()));
  double gravity_work = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    gravity_work -= e.node_mass()[n] * g * (e.positions()[2 * n + 1] - y0[2 * n + 1]);
  const EnergyBalance b = e.energy_balance();
  const double lost =
      k0 + gravity_work - e.kinetic_energy() - e.strain_energy() - b.contact_elastic;
  std::printf(
      "block: K0 %.6g, gravity work %.4g, left K %.4g U %.4g contact %.4g; lost %.6g, "
      "friction %.6g (%.3g%%)\n",
      k0, gravity_work, e.kinetic_energy(), e.strain_energy(), b.contact_elastic, lost, b.friction,
      100 * (b.friction - lost) / lost);
  print("  balance", b);
  EXPECT_LT(e.kinetic_energy(), 0.01 * k0) << "the block must have stopped";
  EXPECT_NEAR(b.friction, lost, 0.02 * lost);
  EXPECT_LT(std::fabs(b.imbalance()), 0.02);
}

// --- 5. Determinism ---------------------------------------------------------------

// The fracturing UCS with contact and all damping kinds: every term of the
// balance is the same double with 1 and 2 threads.
TEST(EnergyBalance, identical_for_1_and_2_threads) {
  auto run = [](int threads) {
    ModelInput in = fracturing_ucs(30);
    in.damping.mass_proportional = 10;
    in.threads = threads;
    Engine e(in);
    e.run(3000);
    return e.energy_balance();
  };
  const EnergyBalance one = run(1), two = run(2);
  print("1 thread", one);
  EXPECT_GT(one.fracture, 0.0);
  EXPECT_GT(one.friction, 0.0);
  const double EnergyBalance::*terms[] = {
      &EnergyBalance::external_work,   &EnergyBalance::kinetic,
      &EnergyBalance::strain,          &EnergyBalance::crack_elastic,
      &EnergyBalance::contact_elastic, &EnergyBalance::initial_stored,
      &EnergyBalance::damping,         &EnergyBalance::fracture,
      &EnergyBalance::friction,        &EnergyBalance::absorbing,
      &EnergyBalance::softening,       &EnergyBalance::removed};
  for (auto term : terms) EXPECT_EQ(one.*term, two.*term);
}

// --- 6. Stage controls ----------------------------------------------------------------

// A pre-stressed fracture block (uniform (-10, -6, 2) MPa, matching
// tractions, crack elements pre-stressed) with local damping: the centre
// triangles are softened to alpha = 0.3, later to 0.05, then removed. Each
// change moves stored energy without work (booked as softening resp.
// removed); the block then deforms towards its new equilibrium, with the
// tractions working. The balance closes within 1% at the end of each stage.
TEST(EnergyBalance, softening_and_removal_are_booked) {
  const std::array<double, 3> s0{-10e6, -6e6, 2e6};
  RectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nx = spec.ny = 10;
  ModelInput in = structured_rectangle(spec, test::rock());
  in.initial_stress.assign(in.triangles.size(), s0);
  in.boundary_conditions = test::side_tractions(s0);
  in.damping.local = 0.3;
  in.threads = 1;
  Engine e(in);
  std::vector<std::size_t> core;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    double cx = 0, cy = 0;
    for (int v : in.triangles[t]) cx += in.x[v] / 3, cy += in.y[v] / 3;
    if (std::hypot(cx - 0.5, cy - 0.5) < 0.2) core.push_back(t);
  }
  e.run(100);
  double worst = 0;
  auto stage = [&](const char* what) {
    e.run(3000);
    const EnergyBalance b = e.energy_balance();
    print(what, b);
    worst = std::max(worst, std::fabs(b.imbalance()));
    return b;
  };
  for (std::size_t t : core) e.set_stiffness_factor(t, 0.3);
  const EnergyBalance soft = stage("alpha 0.3");
  for (std::size_t t : core) e.set_stiffness_factor(t, 0.05);
  const EnergyBalance softer = stage("alpha 0.05");
  for (std::size_t t : core) e.set_active(t, false);
  const EnergyBalance gone = stage("removed");
  EXPECT_GT(soft.external_work, 0.0);  // the tractions push the block in
  EXPECT_NE(softer.softening, soft.softening);
  EXPECT_NE(gone.removed, 0.0);
  EXPECT_LT(worst, 0.01);
}

// --- Contact potential --------------------------------------------------------------

// The contact test's two triangles overlapping by a thin strip of depth
// delta over [x1, x2]: near its base the target's potential is 3 y / H,
// near its top edge the contactor's 3 (delta - y) / Hc, so the stored energy
// p int (phi_T + phi_C) dA is 3/2 p delta^2 (x2 - x1) (1/H + 1/Hc), whose
// delta-derivative is the contact test's force (0.1%; the strip's ends add
// O(delta / (x2 - x1))). A tiny dt keeps the overlap as built.
TEST(EnergyBalance, contact_potential_matches_the_overlap_closed_form) {
  using P = test::PressedTriangles;
  const double delta = 2e-6, p = 3e10;
  ModelInput in = P::model(delta);
  in.contact.enabled = true;
  in.contact.penalty = p;
  in.dt = 1e-10;
  Engine e(in);
  e.step();
  const double expected = 1.5 * p * delta * delta * (P::x2 - P::x1) * (1 / P::H + 1 / P::hc);
  const double stored = e.energy_balance().contact_elastic;
  std::printf("contact energy %.6g J/m, closed form %.6g\n", stored, expected);
  EXPECT_NEAR(stored, expected, 1e-3 * expected);
}

// --- The crack law's potential ------------------------------------------------------

// crack_point_potential is the potential of the laws at fixed damage: its
// derivatives by o and s are the law's sigma and tau (central differences,
// 1e-6 of the strength), for rock (tension, compression with Mohr-Coulomb
// shear, beyond the peak, damaged) and bolt steel; in compression the rock
// potential's o-derivative also holds the stated coupling term.
TEST(EnergyBalance, crack_point_potential_derivatives_are_the_tractions) {
  const double h = 0.01;
  for (const Material& mat : {test::rock(), test::bolt_steel()}) {
    const CrackConstants k = make_crack_constants(mat);
    const double op = h * k.op_per_h, sp = h * k.c * k.two_over_pt;
    const double points[][3] = {{0.4 * op, 0.3 * sp, 0.0},
                                {-0.5 * op, -0.6 * sp, 0.0},
                                {1.0 * op + 0.1 * k.open_range, 0.2 * sp, 0.3},
                                {0.2 * op, -0.5 * sp, 0.6}};
    for (const auto& pt : points) {
      const double o = pt[0], s = pt[1], damage = pt[2];
      double dd = damage;  // the law may not raise it at these points
      const CrackPoint law = crack_point(k, o, s, h, dd);
      ASSERT_EQ(dd, damage);
      const double eps_o = 1e-6 * op, eps_s = 1e-6 * sp;
      const double sigma = (crack_point_potential(k, o + eps_o, s, h, damage) -
                            crack_point_potential(k, o - eps_o, s, h, damage)) /
                           (2 * eps_o);
      const double tau = (crack_point_potential(k, o, s + eps_s, h, damage) -
                          crack_point_potential(k, o, s - eps_s, h, damage)) /
                         (2 * eps_s);
      // Closed rock: the shear strength fs = c - (pn o / h) tan(phi) makes
      // the shear potential depend on o, a term sigma does not carry (the
      // law's non-conservative part): d/do of -|s|^3 pt^2 / (12 h^2 fs).
      double coupling = 0.0;
      if (mat.crack_law == CrackLaw::kRock && o < 0.0) {
        const double fs = k.c - k.pn * o / h * k.tan_phi;
        coupling = std::pow(std::fabs(s), 3) * k.pt * k.pt / (12 * h * h * fs * fs) *
                   (-k.pn * k.tan_phi / h);
      }
      EXPECT_NEAR(sigma, law.sigma + coupling, 1e-6 * k.ft)
          << "o " << o << " s " << s << " D " << damage;
      EXPECT_NEAR(tau, law.tau, 1e-6 * k.c) << "o " << o << " s " << s << " D " << damage;
    }
  }
}

}  // namespace
}  // namespace rockfdem::fdem
