// Kinetic damping (DampingSettings::kinetic, Cundall's dynamic relaxation):
// a plate under a suddenly applied traction relaxes to the static closed
// form, the energy ledger books what the velocity resets take out, and a
// run restarted from a checkpoint, or run with another thread count, is the
// same bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kPressure = 1e6;  // [Pa] on the top side

/// A 1 x 1 m plate of 2 n x n elastic triangles (no crack elements) on
/// rollers at the bottom (y fixed) and left (x fixed), loaded on top by a
/// downward traction p applied at once; mass scaling on, kinetic damping
/// with `local` local damping.
ModelInput plate(int n, double local, int threads) {
  RectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nx = spec.ny = n;
  spec.fracture = false;
  ModelInput in = structured_rectangle(spec, test::rock());
  in.boundary_conditions = rollers_with_top_traction(-kPressure);
  in.damping.kinetic = true;
  in.damping.local = local;
  in.mass_scaling.enabled = true;
  in.threads = threads;
  return in;
}

/// Steps until the unbalanced-force ratio is at or below `ratio`, checked
/// every 10 steps; returns the steps taken (or max_steps).
long relax(Engine& e, double ratio, long max_steps) {
  while (e.step_count() < max_steps) {
    e.run(10);
    if (e.unbalanced_force_ratio() <= ratio) break;
  }
  return e.step_count();
}

/// Mean displacement (x of the right side, y of the top) of plate(n, ...).
std::array<double, 2> side_displacements(const Engine& e, const ModelInput& in) {
  double right = 0, top = 0;
  int n_right = 0, n_top = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const int v = e.node_vertex()[n];
    if (in.x[v] == 1.0) right += e.displacement(n)[0], ++n_right;
    if (in.y[v] == 1.0) top += e.displacement(n)[1], ++n_top;
  }
  return {right / n_right, top / n_top};
}

// Uniaxial stress sigma_yy = -p in plane strain (sigma_xx = 0): the top
// moves by u_y = -(1 - nu^2) p H / E and the right side by
// u_x = nu (1 + nu) p W / E. Constant strain: the triangles represent it
// exactly, up to the finite-strain law's departure from Hooke's law (of the
// order of the strain, 3e-5). Kinetic damping with local damping 0.3 brings
// the force ratio to 1e-5, with velocity resets on the way, and the
// displacements within 3e-4 of the closed form (what a force ratio of 1e-5
// leaves: 1.5e-4 in u_x, 7e-5 in u_y). The balance closes within
// 1%: a dead load applied at once does twice the strain energy it leaves,
// so damping holds half the work (within 1%), and the ledger closes only
// if the resets' share is booked.
TEST(KineticDamping, plate_under_sudden_traction_relaxes_to_the_static_closed_form) {
  const ModelInput in = plate(16, 0.3, 1);
  Engine e(in);
  const long steps = relax(e, 1e-5, 20000);
  const Material& m = in.materials[0];
  const double nu = m.poisson;
  const double ux = nu * (1 + nu) * kPressure / m.young, uy = -(1 - nu * nu) * kPressure / m.young;
  const auto [right, top] = side_displacements(e, in);
  const EnergyBalance b = e.energy_balance();
  std::printf(
      "steps %ld, resets %ld, ratio %.3g: u_x %.6e (closed form %.6e), u_y %.6e (%.6e); "
      "work %.6g, strain %.6g, damping %.6g, imbalance %.3g\n",
      steps, e.kinetic_damping_resets(), e.unbalanced_force_ratio(), right, ux, top, uy,
      b.external_work, b.strain, b.damping, b.imbalance());
  EXPECT_LE(e.unbalanced_force_ratio(), 1e-5);
  EXPECT_GT(e.kinetic_damping_resets(), 2);
  EXPECT_NEAR(right, ux, 3e-4 * std::fabs(ux));
  EXPECT_NEAR(top, uy, 3e-4 * std::fabs(uy));
  EXPECT_NEAR(b.damping, 0.5 * b.external_work, 0.01 * b.external_work);
  EXPECT_LT(std::fabs(b.imbalance()), 0.01);
}

// Kinetic damping alone on the same plate, 1500 steps (resets every few
// steps once the stiffest modes carry most of the kinetic energy): the
// resets are the only dissipation, so the ledger's damping is what they
// took out, more than a third of the work, and the balance closes within
// 2% (measured: -0.9%; without the resets' booking it would be off by
// half the work). What it misses is central differences' own energy error:
// for a quadratic potential the scheme conserves v^2/2 + x(n) K x(n+1)/2,
// while the ledger counts v^2/2 + U(x(n+1/2)), more by dt^2 v K v / 8.
// A reset books the ledger's kinetic energy, and that excess, which the
// scheme never had, goes with it: about (w dt)^2/8 of the kinetic energy
// of a mode w, large for the stiffest modes (w dt up to 1.6). Booking
// U(x(n)) / 2 + U(x(n+1)) / 2 - U(x(n+1/2)) less would close it (three
// energy sums per reset); docs/engine.md.
TEST(KineticDamping, energy_ledger_books_what_the_resets_take_out) {
  Engine e(plate(16, 0.0, 1));
  e.run(1500);
  const EnergyBalance b = e.energy_balance();
  std::printf("resets %ld: work %.6g, kinetic %.6g, strain %.6g, damping %.6g, imbalance %.3g\n",
              e.kinetic_damping_resets(), b.external_work, b.kinetic, b.strain, b.damping,
              b.imbalance());
  EXPECT_GT(e.kinetic_damping_resets(), 100);
  EXPECT_GT(b.damping, b.external_work / 3);
  EXPECT_LT(std::fabs(b.imbalance()), 0.02);
}

std::string save(const Engine& e) {
  std::ostringstream out;
  e.save_state(out);
  return out.str();
}

// Kinetic damping with local damping 0.3 on a 2 x 80 x 80 plate (6561
// nodes: two blocks of the kinetic energy's fixed-block sum): run straight
// with 1 thread; with 2 threads to step 700 (between resets, the kinetic
// energy rising), saved and continued in an engine of 1 thread; and straight
// with 2 threads. Same hash, resets, kinetic energy and saved state at the end.
TEST(KineticDamping, restart_and_thread_count_give_the_same_bits) {
  constexpr long kSave = 700, kEnd = 1500;
  Engine a(plate(80, 0.3, 1));
  a.run(kEnd);
  Engine b(plate(80, 0.3, 2));
  b.run(kSave);
  const long resets_at_save = b.kinetic_damping_resets();
  std::istringstream state(save(b));
  Engine c(plate(80, 0.3, 1));
  c.load_state(state);
  c.run(kEnd - kSave);
  std::printf("resets %ld at the save, %ld at the end; hash %s\n", resets_at_save,
              a.kinetic_damping_resets(), a.state_hash().c_str());
  EXPECT_GT(resets_at_save, 0);
  EXPECT_GT(a.kinetic_damping_resets(), resets_at_save);
  EXPECT_EQ(c.state_hash(), a.state_hash());
  EXPECT_EQ(c.kinetic_damping_resets(), a.kinetic_damping_resets());
  EXPECT_EQ(c.kinetic_energy(), a.kinetic_energy());
  EXPECT_TRUE(save(c) == save(a));
  Engine d(plate(80, 0.3, 2));  // straight through with 2 threads
  d.run(kEnd);
  EXPECT_EQ(d.state_hash(), a.state_hash());
  EXPECT_EQ(d.kinetic_damping_resets(), a.kinetic_damping_resets());
}

}  // namespace
}  // namespace rockfdem::fdem
