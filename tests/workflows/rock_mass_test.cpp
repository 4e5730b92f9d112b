// From the laboratory to the rock mass (rock_mass.hpp): the Hoek-Brown
// constants at their closed-form points, the Mohr-Coulomb fit against an
// independent least-squares line through the Hoek-Brown curve, the
// modulus reduction at its midpoint, and a scene with materials.rock.gsi
// whose model rock (and core) are the derived rock mass.
#include "rockfdem/workflows/rock_mass.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"

using namespace rockfdem::workflows;

namespace {

const std::string kScene = std::string(ROCKFDEM_TEST_DIR) + "/support_pair_supported.toml";

// The least-squares line sigma1 = A + B sigma3 through n + 1 equally
// spaced points of the Hoek-Brown curve over [lo, hi].
std::pair<double, double> least_squares(const RockMassFigures& f, double ci, double lo, double hi,
                                        int n) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i <= n; ++i) {
    const double x = lo + (hi - lo) * i / n, y = hoek_brown_sigma1(f, ci, x);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double m = n + 1, b = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return {(sy - b * sx) / m, b};
}

}  // namespace

// Intact rock (GSI 100, D 0): mb = mi, s = 1, a = 1/2 exactly; E keeps
// 0.02 + 1 / (1 + exp(-40/11)) of itself.
TEST(RockMass, intact_rock_has_the_hoek_brown_constants_of_the_lab) {
  const RockMassFigures f = hoek_brown_constants(10, 100, 0);
  EXPECT_DOUBLE_EQ(f.mb, 10);
  EXPECT_DOUBLE_EQ(f.s, 1);
  EXPECT_NEAR(f.a, 0.5, 1e-15);
  const RockMassFigures m = rock_mass({3e9, 10e6, 10}, 100, 0, 10e6);
  EXPECT_NEAR(m.young, 3e9 * (0.02 + 1 / (1 + std::exp(-40.0 / 11))), 1);
  // sigma_t = s sigma_ci / mb is where the curve meets sigma1 = sigma3.
  EXPECT_NEAR(hoek_brown_sigma1(m, 10e6, -m.tensile_strength), -m.tensile_strength, 1e-3);
  EXPECT_DOUBLE_EQ(m.tensile_strength, 1e6);
}

// Hoek-Diederichs at GSI = 60 + 15 D: the sigmoid is at its midpoint.
TEST(RockMass, modulus_reduction_is_at_its_midpoint_at_gsi_60_plus_15_d) {
  EXPECT_NEAR(rock_mass({3e9, 10e6, 10}, 60, 0, 10e6).young, 3e9 * 0.52, 1);
  EXPECT_NEAR(rock_mass({3e9, 10e6, 10}, 75, 1, 10e6).young, 3e9 * 0.27, 1);
}

// Hoek et al. (2002)'s c', phi' are the least-squares line of sigma1 on
// sigma3 over sigma_t < sigma3 < sigma3max: recomputed by regression over
// 20,001 points for three rocks, to 1e-4 of the line's values.
TEST(RockMass, mohr_coulomb_fit_is_the_least_squares_line_of_the_hoek_brown_curve) {
  struct Case {
    double ci, mi, gsi, d, s3max;
  };
  for (const Case& k : {Case{10.4e6, 10, 50, 0, 5e6}, Case{10.4e6, 10, 50, 0, 1e6},
                        Case{100e6, 25, 70, 0.5, 10e6}}) {
    const RockMassFigures f = hoek_brown_constants(k.mi, k.gsi, k.d);
    const auto [c, phi] = mohr_coulomb_fit(f, k.ci, k.s3max);
    const double sn = std::sin(phi * M_PI / 180);
    const double a = 2 * c * std::cos(phi * M_PI / 180) / (1 - sn), b = (1 + sn) / (1 - sn);
    const auto [a_ls, b_ls] = least_squares(f, k.ci, -f.s * k.ci / f.mb, k.s3max, 20000);
    EXPECT_NEAR(a, a_ls, 1e-4 * a_ls) << k.gsi;
    EXPECT_NEAR(b, b_ls, 1e-4 * b_ls) << k.gsi;
  }
}

// The global strength sigma_cm is the fit's uniaxial strength over
// sigma_t < sigma3 < sigma_ci / 4 (Hoek et al. 2002, eq. 18).
TEST(RockMass, global_strength_is_the_fits_ucs_up_to_a_quarter_of_sigma_ci) {
  const RockMassFigures m = rock_mass({3e9, 10.4e6, 10}, 45, 0, 11.4e6);
  const auto [c, phi] = mohr_coulomb_fit(m, 10.4e6, 10.4e6 / 4);
  EXPECT_NEAR(m.sigma_cm, mohr_coulomb_ucs(c, phi), 1e-9 * m.sigma_cm);
  EXPECT_NEAR(m.sigma_3max, m.sigma_cm * 0.47 * std::pow(m.sigma_cm / 11.4e6, -0.94), 1e-3);
}

// A scene with gsi: the model's rock and the core (which gives none of
// its own) are the rock mass; the lab set is kept for the report.
TEST(RockMass, a_scene_with_gsi_runs_on_the_rock_mass) {
  const Scene lab = load_scene(kScene);
  const Scene s = load_scene(kScene, {"materials.rock.gsi=45", "materials.rock.hoek_brown_mi=10",
                                      "materials.rock.disturbance=0.3"});
  ASSERT_TRUE(s.rock_mass);
  const MaterialSpec& l = lab.materials.at(rockfdem::mesh::kRock);
  const RockMassFigures m = rock_mass({l.young, mohr_coulomb_ucs(l.cohesion, l.friction_angle), 10},
                                      45, 0.3, lab.insitu.sigma_v);
  for (auto zone : {rockfdem::mesh::kRock, rockfdem::mesh::kCore}) {
    const MaterialSpec& r = s.materials.at(zone);
    EXPECT_DOUBLE_EQ(r.young, m.young);
    EXPECT_DOUBLE_EQ(r.cohesion, m.cohesion);
    EXPECT_DOUBLE_EQ(r.friction_angle, m.friction_angle);
    EXPECT_DOUBLE_EQ(r.tensile_strength, m.tensile_strength);
    EXPECT_LE(r.residual_friction_angle, m.friction_angle);
    EXPECT_DOUBLE_EQ(r.fracture_energy_I, l.fracture_energy_I);
  }
  EXPECT_LT(m.young, 0.3 * l.young);
  EXPECT_DOUBLE_EQ(s.rock_mass->lab.young, l.young);
  // Undisturbed unless said (materials.rock.disturbance's default, 0).
  const Scene d = load_scene(kScene, {"materials.rock.gsi=45", "materials.rock.hoek_brown_mi=10"});
  EXPECT_EQ(d.rock_mass->disturbance, 0.0);
  EXPECT_DOUBLE_EQ(d.materials.at(rockfdem::mesh::kRock).young,
                   rock_mass(d.rock_mass->intact, 45, 0, lab.insitu.sigma_v).young);
}

// `rockfdem check` shows the rock mass the run would use, with the figures
// rock_mass() gives (printed to 3 significant digits), before any run.
TEST(RockMass, check_prints_the_derived_rock_mass) {
  const Scene lab = load_scene(kScene);
  const MaterialSpec& l = lab.materials.at(rockfdem::mesh::kRock);
  const RockMassFigures m = rock_mass({l.young, mohr_coulomb_ucs(l.cohesion, l.friction_angle), 10},
                                      45, 0.3, lab.insitu.sigma_v);
  const rockfdem::test::Result r =
      rockfdem::test::run("check " + kScene +
                          " --set materials.rock.gsi=45 --set materials.rock.hoek_brown_mi=10"
                          " --set materials.rock.disturbance=0.3");
  ASSERT_EQ(r.code, 0) << r.output;
  char line[200];
  std::snprintf(line, sizeof line, "rock mass (GSI 45, mi 10, D 0.3): E %.3g GPa, c %.3g MPa",
                m.young / 1e9, m.cohesion / 1e6);
  EXPECT_NE(r.output.find(line), std::string::npos) << line << " in\n" << r.output;
  std::snprintf(line, sizeof line, "ft %.3g MPa", m.tensile_strength / 1e6);
  EXPECT_NE(r.output.find(line), std::string::npos) << line << " in\n" << r.output;
  // Without gsi the model's rock is the section itself: no such line.
  EXPECT_EQ(rockfdem::test::run("check " + kScene).output.find("rock mass ("), std::string::npos);
}

// gsi where it has no meaning, or without what it needs: exit-2 errors
// naming the key.
TEST(RockMass, gsi_without_mi_on_a_specimen_or_mi_alone_is_refused) {
  using rockfdem::test::error_of;
  const auto refused = [](const std::string& scene, const std::vector<std::string>& sets) {
    try {
      load_scene(scene, sets);
    } catch (const rockfdem::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refused(kScene, {"materials.rock.gsi=45"}).find("materials.rock.hoek_brown_mi"),
            std::string::npos);
  EXPECT_NE(
      refused(kScene, {"materials.rock.hoek_brown_mi=10"}).find("applies with materials.rock.gsi"),
      std::string::npos);
  EXPECT_NE(refused(std::string(ROCKFDEM_TEST_DIR) + "/ucs_small.toml",
                    {"materials.rock.gsi=45", "materials.rock.hoek_brown_mi=10"})
                .find("a laboratory specimen is intact rock"),
            std::string::npos);
  EXPECT_NE(refused(kScene, {"materials.rock.gsi=5", "materials.rock.hoek_brown_mi=10"})
                .find("in [10, 100]"),
            std::string::npos);
}

// materials.rock.mass_ft_over_ucs: the mass's ft is that fraction of the
// mass's own Mohr-Coulomb UCS (the rock's and the core's), c and phi as
// without it; refused without gsi.
TEST(RockMass, mass_ft_over_ucs_sets_the_mass_tensile_strength) {
  const std::vector<std::string> gsi = {"materials.rock.gsi=45", "materials.rock.hoek_brown_mi=4"};
  const Scene hb = load_scene(kScene, gsi);
  std::vector<std::string> with = gsi;
  with.push_back("materials.rock.mass_ft_over_ucs=0.1");
  const Scene s = load_scene(kScene, with);
  const MaterialSpec& h = hb.materials.at(rockfdem::mesh::kRock);
  const double ucs = mohr_coulomb_ucs(h.cohesion, h.friction_angle);
  for (auto zone : {rockfdem::mesh::kRock, rockfdem::mesh::kCore}) {
    const MaterialSpec& r = s.materials.at(zone);
    EXPECT_NEAR(r.tensile_strength, 0.1 * ucs, 1e-9 * ucs);
    EXPECT_DOUBLE_EQ(r.cohesion, h.cohesion);
    EXPECT_DOUBLE_EQ(r.young, h.young);
  }
  // Hoek-Brown's own ft here is below a tenth of the UCS: the key changes it.
  EXPECT_LT(h.tensile_strength, 0.05 * ucs);
  try {
    load_scene(kScene, {"materials.rock.mass_ft_over_ucs=0.1"});
    ADD_FAILURE() << "accepted without gsi";
  } catch (const rockfdem::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("applies with materials.rock.gsi"), std::string::npos);
  }
}
