// Inputs checked as an engineer would: bolts that do not start at the
// opening, run through it or leave the domain are refused naming the bolt;
// stresses and moduli a million times too small warn; `rockfdem mesh`
// draws the model before anything runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using rockfdem::test::error_of;
using rockfdem::test::has;
using rockfdem::test::kTestDir;
using rockfdem::test::read_json;
using rockfdem::test::read_text;
using rockfdem::test::Result;
using rockfdem::test::run;
using rockfdem::test::scratch;

namespace {

const std::string& kSeed = rockfdem::test::kSeedScene;

// A radial bolt at 30 deg with its collar `r` from the centre of a circular
// opening (radius 3 m), 2 m long, in `scene` (good_circular or the lined one,
// whose stage list then gets a bolts stage).
std::string bolt_at(const std::string& scene, double r) {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  std::string text = read_text(kTestDir + "/" + scene) + "\n[[bolt]]\nstart = [" +
                     std::to_string(r * c) + ", " + std::to_string(r * s) + "]\nend = [" +
                     std::to_string((r + 2) * c) + ", " + std::to_string((r + 2) * s) + "]\n";
  if (has(text, "[[stages]]")) text += "[[stages]]\nkind = \"bolts\"\n";
  return text;
}

std::string placement_error(const std::string& scene, double r) {
  return error_of([&] { workflows::parse_scene(bolt_at(scene, r), "bolted.toml", "."); });
}

}  // namespace

// Seed fans moved off the opening, into it and out of the box: exit 2, one
// line naming the fan, the bolt and where it is; nothing written.
TEST(InputChecks, misplaced_bolts_exit_two_naming_the_bolt_and_where_it_is) {
  struct Case {
    const char* set;
    std::vector<const char*> expect;
  };
  const Case cases[] = {
      {"bolt_fan[0].centre=[0.0, 20.0]",
       {"--set bolt_fan[0].centre=[0.0, 20.0]: bolt 1 of 9 of bolt_fan[0] (15 deg)",
        "starts at (x, y) = (5.46, 21.5) m, 17.7 m outside the excavation boundary"}},
      {"bolt_fan[0].radius=2.0",
       {"--set bolt_fan[0].radius=2.0: makes the scene invalid: ",
        "bolt 1 of 9 of bolt_fan[0] (15 deg) starts at (x, y) = (1.93, -0.732) m, 3.49 m inside "
        "the excavation boundary; allowed: a collar (start) on the boundary or in the lining (0.2 "
        "m thick), within 0.175 m (mesh.size_near / 2, at least 5 cm)\n"}},
      {"bolt_fan[1].length=40",
       {"--set bolt_fan[1].length=40: bolt 2 of 4 of bolt_fan[1] (80.625 deg) ends at (x, y) = "
        "(7.44, 43.8) m,",
        "outside the rock domain; allowed: x from -40 m to 40 m, y from -40 m to 40 m"}}};
  for (const Case& c : cases) {
    const fs::path out = scratch("bolts");
    const Result r = run("mesh " + kSeed + " --set '" + c.set + "' -o " + out.string());
    EXPECT_EQ(r.code, 2) << r.output;
    for (const char* e : c.expect) EXPECT_TRUE(has(r.output, e)) << e << " in " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

// The collar tolerance is max(mesh.size_near / 2, 5 cm): 0.25 m for
// good_circular (size_near 0.5 m), 0.075 m with the lined scene's 0.15 m,
// whose 0.3 m lining may hold the collar too. Exact for a circle: the
// collar's distance from the boundary is |r - 3 m|.
TEST(InputChecks, the_collar_lies_on_the_boundary_or_in_the_lining_within_the_tolerance) {
  EXPECT_EQ(placement_error("good_circular.toml", 3.0 + 0.24), "");
  EXPECT_TRUE(has(placement_error("good_circular.toml", 3.0 + 0.26),
                  "0.26 m outside the excavation boundary; allowed: a collar (start) on the "
                  "boundary, within 0.25 m"))
      << placement_error("good_circular.toml", 3.26);
  EXPECT_EQ(placement_error("good_circular.toml", 3.0 - 0.24), "");
  EXPECT_TRUE(has(placement_error("good_circular.toml", 3.0 - 0.26), "0.26 m inside"));
  const std::string lined = "lined_elastic_circular.toml";
  EXPECT_EQ(placement_error(lined, 3.0 - 0.3), "");  // on the lining's inner face
  EXPECT_EQ(placement_error(lined, 3.0 - 0.3 - 0.07), "");
  EXPECT_TRUE(has(placement_error(lined, 3.0 - 0.3 - 0.08),
                  "bolt[0] starts at (x, y) = (2.27, 1.31) m, 0.38 m inside the excavation "
                  "boundary; allowed: a collar (start) on the boundary or in the lining (0.3 m "
                  "thick), within 0.075 m"))
      << placement_error(lined, 2.62);
  EXPECT_TRUE(has(placement_error(lined, 3.0 + 0.08), "0.08 m outside"));
}

TEST(InputChecks, stresses_and_moduli_given_in_pa_for_mpa_warn) {
  const std::string good = kTestDir + "/good_circular.toml";
  EXPECT_TRUE(workflows::load_scene(kSeed).warnings.empty());
  const auto warnings = [&](std::vector<std::string> sets) {
    return workflows::load_scene(good, sets).warnings;
  };
  std::vector<std::string> w = warnings({"insitu.sigma_h=18.2"});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0],
            "--set insitu.sigma_h=18.2: an in-situ stress of 18.2 Pa is below 10 kPa: probably "
            "MPa given as Pa (18.2 MPa is 18.2e6)");
  w = warnings({"materials.rock.young=5000", "grout.young=200"});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_TRUE(
      has(w[0] + w[1], "--set materials.rock.young=5000: a modulus of 5000 Pa is below 1 MPa"));
  EXPECT_TRUE(has(w[0] + w[1], "--set grout.young=200: a modulus of 200 Pa"));
  // At the limits, nothing.
  EXPECT_TRUE(warnings({"insitu.sigma_v=1e4", "materials.rock.young=1e6"}).empty());
  EXPECT_EQ(warnings({"insitu.sigma_v=9999"}).size(), 1u);
  // From the file: its name and line.
  std::string text = read_text(good);
  text.replace(text.find("sigma_v = "), 10, "sigma_v = 11.4 #");
  w = workflows::parse_scene(text, "units.toml", ".").warnings;
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].find("units.toml:"), 0u) << w[0];
  EXPECT_TRUE(has(w[0], "key 'insitu.sigma_v' = 11.4: an in-situ stress of 11.4 Pa")) << w[0];
  // On stderr and in the summary's warnings; the command still runs.
  const fs::path out = scratch("units");
  const Result r = run("mesh " + good + " --set insitu.sigma_h=18.2 --set output.plots=false -o " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "rockfdem: warning: --set insitu.sigma_h=18.2: an in-situ stress"))
      << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  ASSERT_EQ(j["warnings"].size(), 1u) << j;
  EXPECT_TRUE(has(j["warnings"][0].get<std::string>(), "probably MPa given as Pa"));
  fs::remove_all(out);
}

// Tunnel stages run to equilibrium; with no damping of any kind their
// vibration never decays and friction ratchets on it (docs/engine.md,
// "Sticking and undamped ratcheting"): a warning naming the key. Any one
// kind of damping silences it; a specimen's platen loading is no
// quasi-static stage.
TEST(InputChecks, quasi_static_stages_without_any_damping_warn) {
  const std::string good = kTestDir + "/good_circular.toml";
  const auto warnings = [&](const std::string& scene, std::vector<std::string> sets) {
    sets.insert(sets.begin(), {"engine.damping_ratio=0"});
    return workflows::load_scene(scene, sets).warnings;
  };
  EXPECT_TRUE(warnings(good, {}).empty());  // local damping 0.8 when not given
  std::vector<std::string> w = warnings(good, {"engine.local_damping=0"});
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0],
            "--set engine.local_damping=0: with no kinetic, mass, element (engine.damping_ratio) "
            "or contact damping the quasi-static stages (remove_core, equilibrium) run "
            "undamped: their vibration never decays, blocks held by friction ratchet down on it "
            "and equilibrium may not come; give engine.local_damping > 0 (0.8 when not given) "
            "or engine.kinetic_damping = true");
  // Damping the contact while contact is off damps nothing.
  EXPECT_EQ(warnings(good, {"engine.local_damping=0", "contact.enabled=false",
                            "contact.damping_ratio=0.1"})
                .size(),
            1u);
  EXPECT_TRUE(warnings(good, {"engine.local_damping=0.05"}).empty());
  for (const std::string damped : {"engine.kinetic_damping=true", "engine.mass_damping=1",
                                   "engine.damping_ratio=0.01", "contact.damping_ratio=0.1"})
    EXPECT_TRUE(warnings(good, {"engine.local_damping=0", damped}).empty()) << damped;
  EXPECT_TRUE(warnings(kTestDir + "/ucs_small.toml", {"engine.local_damping=0"}).empty());
}

// preview.png under Xvfb; without a display, or with output.plots off,
// the summary says why there is none.
TEST(InputChecks, mesh_writes_a_preview_or_says_why_not) {
  const std::string scene = kSeed + " --set mesh.size_near=0.4 -q";
  const fs::path out = scratch("preview");
  Result r = run("mesh " + scene + " -o " + out.string(), "env -u DISPLAY");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "preview.png"));
  nlohmann::json j = read_json(out / "summary.json");
  EXPECT_TRUE(has(j["skipped"].dump(), "plot preview.png: ")) << j["skipped"];
  r = run("mesh " + scene + " --set output.plots=false --force -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(
      has(read_json(out / "summary.json")["skipped"].dump(), "plots: output.plots = false"));
  if (std::string(ROCKFDEM_XVFB_RUN).empty()) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string xvfb =
      std::string(ROCKFDEM_XVFB_RUN) + " -n " + std::to_string(100 + getpid() % 800) + " -a";
  r = run("mesh " + scene + " --force -o " + out.string(), xvfb);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_text(out / "preview.png").substr(1, 3), "PNG");
  EXPECT_FALSE(has(read_json(out / "summary.json")["skipped"].dump(), "preview"));
  fs::remove_all(out);
}

// A gravity gradient without the weight it holds would set the box moving:
// a tunnel run refuses it first, before a restart's checkpoint is read (here
// one that does not exist), with exit 2 and nothing written.
TEST(InputChecks, a_tunnel_run_refuses_a_gradient_without_gravity_before_its_checkpoint) {
  const fs::path out = scratch("gravity");
  // A round density for a round figure in the message.
  const Result r =
      run("run " + kSeed +
          " --set materials.rock.density=2500 --set insitu.unit_weight=27000 --restart " +
          (out / "none" / "checkpoint_000100.bin").string() + " -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output,
                  "key 'insitu.unit_weight' = 27000: the explicit stages need the weight this "
                  "gradient holds; allowed: 0, or set engine.gravity (unit_weight / "
                  "materials.rock.density = 10.8 m/s^2)"))
      << r.output;
  EXPECT_FALSE(has(r.output, "checkpoint")) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// Values outside any physical range are bad input, not a run that fails at
// its first step (the reproducers: the shipped Brazilian disc, where both
// inverted triangle 69 at step 1, exit 3). Each is exit 2 naming the key
// and the range, before anything is written, for check and run alike.
TEST(InputChecks, absurd_density_and_platen_speed_are_refused_naming_the_range) {
  const fs::path out = scratch("absurd");
  const std::string disc = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/brazilian-disc.toml";
  const std::pair<std::string, std::string> cases[] = {
      {"loading.platen_velocity=1e300",
       "--set loading.platen_velocity=1e300: the platens would strike the specimen, not load it; "
       "allowed: 0 < loading.platen_velocity <= 346.6 m/s (0.1 x the rock's P-wave speed 3467 "
       "m/s"},
      {"materials.rock.density=1e300",
       "--set materials.rock.density=1e300: out of range; allowed: in (0, 100000] (kg/m^3)"}};
  for (const auto& [set, expect] : cases)
    for (const char* cmd : {"check", "run"}) {
      const Result r =
          run(std::string(cmd) + " " + disc + " -q --set " + set + " -o " + out.string());
      EXPECT_EQ(r.code, 2) << cmd << " " << set << ": " << r.output;
      EXPECT_TRUE(has(r.output, expect)) << cmd << " " << set << ": " << r.output;
      EXPECT_FALSE(fs::exists(out)) << cmd << " " << set;
    }
  // The bound is the rock's: the shipped disc's own 0.5 m/s and a fast
  // dynamic test's 300 m/s pass.
  for (const char* v : {"0.5", "300"})
    EXPECT_EQ(run("check " + disc + " -q --set loading.platen_velocity=" + std::string(v)).code, 0)
        << v;
}
