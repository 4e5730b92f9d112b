// The crack laws at one integration point: the Evans-Marathe curve, the
// energy-exact softening constant, and the energies of the rock and
// bolt-steel laws along monotonic paths (closed forms in each test).
#include "rockfdem/fdem/crack_law.hpp"

#include <gtest/gtest.h>

#include "rockfdem/fdem/constants.hpp"
#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

TEST(CrackLaw, evans_marathe_curve_runs_from_one_to_zero) {
  EXPECT_NEAR(evans_marathe_z(0.0), 1.0, 1e-12);
  EXPECT_NEAR(evans_marathe_z(1.0), 0.0, 1e-12);
  for (int i = 1; i <= 100; ++i)  // monotonic decrease
    EXPECT_LT(evans_marathe_z(i / 100.0), evans_marathe_z((i - 1) / 100.0));
}

TEST(CrackLaw, tabulated_curve_matches_exact_within_1e_6) {
  EXPECT_EQ(softening_z(0.0), 1.0);
  EXPECT_EQ(softening_z(1.0), 0.0);
  for (int i = 0; i <= 10007; ++i) {
    const double d = i / 10007.0;
    EXPECT_NEAR(softening_z(d), evans_marathe_z(d), 1e-6);
  }
}

// Reference sec. 2: the integral of z over [0, 1] is 0.3863, so the exact
// softening range is or - op = 2.589 GfI / ft (independent check: 1e5-point
// midpoint rule gives 0.386307).
TEST(CrackLaw, softening_integral_gives_exact_range_constant) {
  EXPECT_NEAR(rock_softening_integral(), 0.386307, 2e-6);
  EXPECT_NEAR(1.0 / rock_softening_integral(), 2.589, 5e-4);
  // The common 3 GfI / ft rule dissipates 3 * 0.3863 = 1.16 GfI.
  EXPECT_NEAR(3.0 * rock_softening_integral(), 1.159, 1e-3);
}

/// Work per unit length of one point along a monotonic path (o, s) = u dir,
/// by the trapezoid rule, until the damage reaches 1.
double point_work(const CrackConstants& k, double h, double dir_o, double dir_s, double u_max,
                  int n) {
  double damage = 0, work = 0, prev = 0;
  for (int i = 1; i <= n && damage < 1.0; ++i) {
    const double u = u_max * i / n;
    const CrackPoint p = crack_point(k, u * dir_o, u * dir_s, h, damage);
    const double f = p.sigma * dir_o + p.tau * dir_s;
    work += 0.5 * (f + prev) * (u_max / n);
    prev = f;
  }
  return work;
}

// Pure mode I at a point: work = (2/3) ft op (pre-peak) + GfI (softening).
TEST(CrackLaw, rock_mode_I_point_work_is_prepeak_plus_GfI) {
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double h = 0.01, op = 2 * h * m.tensile_strength / k.pn;
  const double work = point_work(k, h, 1, 0, op + k.open_range, 200000);
  EXPECT_NEAR(work - 2.0 / 3.0 * m.tensile_strength * op, m.gf_I, 1e-3 * m.gf_I);
}

TEST(CrackLaw, rock_mode_II_point_work_is_prepeak_plus_GfII) {
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double h = 0.01, sp = 2 * h * m.cohesion / k.pt;
  const double work = point_work(k, h, 0, 1, sp + k.slip_energy / m.cohesion, 200000);
  EXPECT_NEAR(work - 2.0 / 3.0 * m.cohesion * sp, m.gf_II, 1e-3 * m.gf_II);
}

// Compression raises the shear strength: fs = c - sigma tan(phi).
TEST(CrackLaw, rock_shear_strength_follows_mohr_coulomb) {
  const Material m = test::rock();
  const CrackConstants k = make_crack_constants(m);
  const double h = 0.01, o = -1e-7;  // closed: sigma = pn o / h
  const double sigma = k.pn * o / h;
  const double fs = m.cohesion - sigma * std::tan(m.friction_deg * kPi / 180);
  double damage = 0;
  const CrackPoint p = crack_point(k, o, 2 * h * fs / k.pt, h, damage);  // s = sp: peak
  EXPECT_NEAR(p.sigma, sigma, 1e-6 * std::fabs(sigma));
  EXPECT_NEAR(p.tau, fs, 1e-6 * fs);
  EXPECT_EQ(damage, 0.0);
  // In tension (tension positive: sigma > 0) the strength stays c; the
  // compression formula would lower it to c - sigma tan(phi).
  const double op = 2 * h * m.tensile_strength / k.pn, sp = 2 * h * m.cohesion / k.pt;
  double open_damage = 0;
  const CrackPoint t = crack_point(k, 0.5 * op, sp, h, open_damage);
  ASSERT_GT(t.sigma, 0.5 * m.tensile_strength);
  EXPECT_NEAR(t.tau, m.cohesion, 1e-9 * m.cohesion);
  EXPECT_EQ(open_damage, 0.0);
}

// Seed eqs. 11-19: yield at op, axial stress sigma_y + D (sigma_u - sigma_y),
// and eq. 14 makes the hardening branch carry exactly GfI.
TEST(CrackLaw, bolt_steel_hardens_from_yield_to_ultimate_and_carries_GfI) {
  const Material m = test::bolt_steel();
  const CrackConstants k = make_crack_constants(m);
  const double h = 0.01, op = 2 * h * m.yield_strength / k.pn;
  double damage = 0;
  EXPECT_NEAR(crack_point(k, op, 0, h, damage).sigma, m.yield_strength, 1e-9 * m.yield_strength);
  damage = 0;
  const CrackPoint half = crack_point(k, op + 0.5 * k.open_range, 0, h, damage);
  EXPECT_NEAR(damage, 0.5, 1e-12);
  EXPECT_NEAR(half.sigma, 500e6, 1e-9 * 500e6);
  const double work = point_work(k, h, 1, 0, op + k.open_range, 200000);
  EXPECT_NEAR(work - 2.0 / 3.0 * m.yield_strength * op, m.gf_I, 2e-3 * m.gf_I);
  const double sp = 2 * h * m.shear_yield_strength / k.pt;
  const double shear = point_work(k, h, 0, 1, sp + k.slip_energy / m.shear_yield_strength, 200000);
  EXPECT_NEAR(shear - 2.0 / 3.0 * m.shear_yield_strength * sp, m.gf_II, 2e-3 * m.gf_II);
}

}  // namespace
}  // namespace rockfdem::fdem
