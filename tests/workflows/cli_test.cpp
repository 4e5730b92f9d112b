// The command line as users meet it: exit codes, messages on stderr, and
// no output directory left behind by a refused scene.
#include "rockfdem/workflows/cli.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"

namespace fs = std::filesystem;

using rockfdem::test::kTestDir;
using rockfdem::test::Result;
using rockfdem::test::run;
using rockfdem::test::scratch;

TEST(Cli, help_and_version_exit_zero) {
  EXPECT_EQ(run("--help").code, 0);
  const Result v = run("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.output.find("rockfdem 0."), std::string::npos);
}

TEST(Cli, unknown_command_and_option_exit_two) {
  EXPECT_EQ(run("simulate x.toml").code, 2);
  const Result r = run("mesh " + kTestDir + "/good_circular.toml --frobnicate");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("frobnicate"), std::string::npos) << r.output;
  EXPECT_EQ(run("check " + kTestDir + "/good_circular.toml -j -3").code, 2);
}

// Each malformed scene: exit 2, one line naming the key, no directory made.
TEST(Cli, malformed_scenes_exit_two_and_leave_nothing) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(kTestDir + "/bad_scenes")) {
    std::ifstream in(entry.path());
    std::string first;
    std::getline(in, first);
    const std::string expect = first.substr(10);
    const fs::path out = scratch("bad");
    const Result r = run("mesh " + entry.path().string() + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << entry.path() << ": " << r.output;
    EXPECT_NE(r.output.find(expect), std::string::npos) << entry.path() << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(out)) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 15);
}

// An unknown instruction set for the vector kernels in the environment:
// exit 2, one line naming the variable, its value and the allowed ones, no
// directory made (the check runs before the mesh is written).
TEST(Cli, unknown_instruction_set_request_exits_two_and_leaves_nothing) {
  const fs::path out = scratch("isa");
  setenv("ROCKFDEM_ISA", "AVX2", 1);
  const Result r = run("run " + kTestDir + "/good_circular.toml -o " + out.string());
  unsetenv("ROCKFDEM_ISA");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("ROCKFDEM_ISA = 'AVX2'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("allowed sse2, avx2, avx512"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// A bolt design the engine cannot model on the mesh (steel 16,600 times
// stiffer than a 1 MPa rock) is refused before anything is written, with
// the scene and the keys to change; the engine's reason alone named
// neither. Steel whose hardening range is empty is refused by the scene.
TEST(Cli, bolt_design_the_engine_refuses_names_the_scene_and_keys) {
  const fs::path out = scratch("bolts");
  const std::string seed = rockfdem::test::kSeedScene;
  // A low in-situ stress keeps the soft rock's implicit field sound (E = 1e6
  // under 18 MPa would invert triangles, refused first).
  Result r = run("run " + seed +
                 " --set materials.rock.young=1e6 --set insitu.sigma_h=1e4"
                 " --set insitu.sigma_v=1e4 -o " +
                 out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(seed + ": the bolt design cannot be modelled"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("materials.rock.young"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(out));
  r = run("check " + seed + " --set bolts.ultimate_strength=400e6");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("must be above bolts.yield_strength"), std::string::npos) << r.output;
}

TEST(Cli, set_override_is_validated_like_the_file) {
  const fs::path out = scratch("set");
  const Result r =
      run("mesh " + kTestDir + "/good_circular.toml --set mesh.size_near=0 -o " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("--set mesh.size_near=0: out of range"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, check_prints_estimates_and_writes_nothing) {
  const Result r = run("check " + kTestDir + "/good_circular.toml");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("triangles (meshed)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stable time step"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("run time (bound)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("peak memory (bound)"), std::string::npos) << r.output;
}

// A mesh far beyond any machine's memory (1 mm triangles over the whole
// domain: billions) is refused by check and by run before meshing: exit 2,
// naming the key, and no output directory.
TEST(Cli, scene_larger_than_the_machine_is_refused_before_meshing) {
  const fs::path out = scratch("too-large");
  for (const char* cmd : {"check", "run"}) {
    const Result r = run(std::string(cmd) + " " + kTestDir +
                         "/good_circular.toml --set mesh.size_near=0.001 --set "
                         "mesh.size_far=0.001 -o " +
                         out.string());
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("mesh.size_near"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("GiB"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(Cli, mesh_writes_msh_vtu_and_summary) {
  const fs::path out = scratch("mesh");
  const Result r = run("mesh " + kTestDir + "/good_circular.toml -q -j 2 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "mesh.msh"));
  EXPECT_TRUE(fs::exists(out / "mesh.vtu"));
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_GT(j["counts"]["triangles"].get<int>(), 500);
  EXPECT_EQ(j["threads"].get<int>(), 2);
  for (const char* key :
       {"rockfdem_version", "scene", "counts", "steps", "dt", "simulated_time", "timings",
        "throughput", "skipped", "broken", "monitors", "insitu", "state_hash"})
    EXPECT_TRUE(j.contains(key)) << key;
  // No temporary files are left beside the outputs.
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  // A second scene may not reuse the directory without --force.
  const Result other =
      run("mesh " + kTestDir + "/good_circular.toml --set tunnel.radius=2.5 -o " + out.string());
  EXPECT_EQ(other.code, 2) << other.output;
  EXPECT_NE(other.output.find("--force"), std::string::npos) << other.output;
  fs::remove_all(out);
}

// `rockfdem insitu` on the Kirsch scene: the implicit field is compared with
// the closed form and written with every output the contract names. The
// 1% bound at ~20k triangles is pinned in tests/insitu; here a coarser mesh
// (size_near 0.3 m) must stay within 2.5%.
TEST(Cli, insitu_compares_with_kirsch_and_writes_outputs) {
  const fs::path out = scratch("insitu");
  const Result r =
      run("insitu " + std::string(ROCKFDEM_SOURCE_DIR) +
          "/scenes/kirsch-circular.toml --set mesh.size_near=0.3 -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"insitu.vtu", "insitu.pvd", "insitu_00.vtu", "insitu_vs_analytic.csv",
                        "mesh.msh", "summary.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const double err = j["insitu"]["kirsch_rel_l2"].get<double>();
  EXPECT_GT(err, 0.0);
  EXPECT_LT(err, 0.025);
  EXPECT_EQ(j["insitu"]["alpha"].size(), 1u);
  fs::remove_all(out);
}

// `rockfdem run` on the Kirsch scene (alpha 0: the core is out before the
// default stages remove it again): it completes, its continuum counterpart
// is the one open excavation (sequence [0]), and the FDEM stress agrees
// with the closed form within 2.5% on a 0.4 m mesh (1.4% measured).
TEST(Cli, run_of_the_kirsch_scene_completes_against_the_closed_form) {
  const fs::path out = scratch("kirsch-run");
  const std::string scene = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/kirsch-circular.toml";
  const Result r = run("run " + scene +
                       " --set mesh.size_near=0.4 --set output.plots=false -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = rockfdem::test::read_json(out / "summary.json");
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["continuum_comparison"]["sequence_alpha"], nlohmann::json::array({0.0}));
  EXPECT_LT(j["comparison"]["fdem_vs_kirsch_rel_l2"].get<double>(), 0.025);
  fs::remove_all(out);
}

TEST(Cli, insitu_refuses_a_specimen) {
  const Result r = run("insitu " + std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/ucs-33k.toml -o " +
                       scratch("spec").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("model.kind"), std::string::npos) << r.output;
}

// A small elastic tunnel through the whole staged sequence: the engine must
// start from the implicit hand-off in equilibrium (unbalanced-force ratio
// below 1e-6 at the first step, where a start from zero stress would be
// out of balance by order 1), write every output, and give the same state
// hash for 1 and 2 threads.
TEST(Cli, tunnel_run_starts_in_equilibrium_and_is_thread_count_independent) {
  std::string hashes[2];
  for (int threads : {1, 2}) {
    const fs::path out = scratch("tunnel" + std::to_string(threads));
    const Result r =
        run("run " + kTestDir + "/good_circular.toml -q -j " + std::to_string(threads) +
            " --set insitu.alpha=[1.0,0.2] --set engine.steps=300"
            " --set output.every_steps=100 --set output.plots=false -o " +
            out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(out / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_LT(j["fdem"]["unbalanced_ratio_at_start"].get<double>(), 1e-6);
    // Energy closes through hand-off, softening and relaxation (measured 0.06%).
    EXPECT_LT(std::abs(j["energy"]["relative_imbalance"].get<double>()), 0.01);
    EXPECT_GT(j["energy"]["initial_stored"].get<double>(), 0.0);
    EXPECT_GT(j["monitors"]["vault_settlement_mm"].get<double>(), 0.0);
    // One hand-off step, then the stage stops at equilibrium or after 300 steps.
    const long steps = j["steps"].get<long>();
    EXPECT_GT(steps, 1);
    EXPECT_LE(steps, 301);
    EXPECT_EQ(j["threads"].get<int>(), threads);
    hashes[threads - 1] = j["state_hash"].get<std::string>();
    std::ifstream hist(out / "history.csv");
    std::string line, last;
    int rows = -1;  // the header
    while (std::getline(hist, line)) {
      ++rows;
      last = line;
    }
    EXPECT_GE(rows, 2);  // the hand-off, then one row per 100 steps
    const std::string after_stage = last.substr(last.find(',') + 1);  // stage, step, ...
    EXPECT_EQ(std::stol(after_stage.substr(0, after_stage.find(','))), steps);
    for (const char* f : {"fdem.pvd", "fdem_0000.vtu", "fdem_0001.vtu", "insitu.vtu", "mesh.msh"})
      EXPECT_TRUE(fs::exists(out / f)) << f;
    fs::remove_all(out);
  }
  EXPECT_EQ(hashes[0].size(), 16u);
  EXPECT_EQ(hashes[0], hashes[1]);
}

// Elastic circular tunnel through implicit hand-off (alpha 0.2), explicit
// core removal and relaxation to a ratio of 1e-5: the wall displacements
// must match Kirsch's plane-strain closed form within 2% (a = 3 m in a
// 100 m box: the finite box and the mesh account for about 1%):
//   u_r(a, theta) = -(a / 4G) [(sH + sV) + (sH - sV)(3 - 4 nu) cos 2 theta]
TEST(Cli, elastic_tunnel_wall_displacement_matches_kirsch) {
  const fs::path out = scratch("kirsch-run");
  const Result r = run("run " + kTestDir + "/elastic_circular.toml -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const double a = 3.0, E = 5e9, nu = 0.25, G = E / (2 * (1 + nu)), sH = 18.2e6, sV = 11.4e6;
  const double vault = a / (4 * G) * ((sH + sV) - (sH - sV) * (3 - 4 * nu));  // theta = 90 deg
  const double wall = a / (4 * G) * ((sH + sV) + (sH - sV) * (3 - 4 * nu));   // theta = 0
  EXPECT_NEAR(j["monitors"]["vault_settlement_mm"].get<double>(), 1000 * vault,
              0.02 * 1000 * vault);
  EXPECT_NEAR(j["monitors"]["wall_chord_convergence_mm"].get<double>(), 2000 * wall,
              0.02 * 2000 * wall);
  EXPECT_TRUE(j["fdem"]["stages"][1]["converged"].get<bool>());
  // The relaxed FDEM stresses stay within 1% of the implicit open-hole
  // field on the same triangles (relative L2 over a <= r <= 5a).
  EXPECT_LT(j["comparison"]["fdem_vs_insitu_rel_l2"].get<double>(), 0.01);
  EXPECT_GT(j["comparison"]["triangles"].get<int>(), 500);
  EXPECT_TRUE(fs::exists(out / "fdem_vs_continuum.csv"));
  // The elastic counterpart's sequence (1, 0.2, then 0 at remove_core) ends
  // at the open hole: the same stress error as the open-hole comparison
  // (computed apart), and the vault displacement of Kirsch within 2%.
  const nlohmann::json& c = j["continuum_comparison"];
  EXPECT_EQ(c["sequence_alpha"], nlohmann::json({1.0, 0.2, 0.0}));
  EXPECT_NEAR(c["stress_rel_l2_end"].get<double>(),
              j["comparison"]["fdem_vs_insitu_rel_l2"].get<double>(), 1e-6);
  EXPECT_NEAR(c["key_points"]["vault"]["continuum_end_mm"][1].get<double>(), -1000 * vault,
              0.02 * 1000 * vault);
  EXPECT_TRUE(fs::exists(out / "continuum_profiles.csv"));
  fs::remove_all(out);
}

// The Mohr-Coulomb counterpart through the scene keys: the same circular
// tunnel in hydrostatic 18.2 MPa, c = 2 MPa, phi = 30, psi = 0, released
// from the hand-off (alpha 0.2, lambda 0.8) to the open hole. Its vault
// displacement within 3% of the closed form (docs/insitu.md), its yielded
// depth along the vault ray within one element (0.15 m) and a ray sample
// (0.1 m) of Salencon's R_pl - a.
TEST(Cli, mohr_coulomb_counterpart_matches_the_closed_form) {
  const fs::path out = scratch("mc-run");
  const Result r = run("run " + kTestDir + "/elastic_circular.toml -q -o " + out.string() +
                       " --set insitu.sigma_v=18.2e6 --set insitu.continuum=\"mohr_coulomb\""
                       " --set materials.rock.cohesion=2e6 --set mesh.size_near=0.15"
                       " --set stages[2].max_steps=100");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = rockfdem::test::read_json(out / "summary.json");
  const nlohmann::json& c = j["continuum_comparison"];
  ASSERT_EQ(c["model"], "mohr_coulomb") << j.dump();
  const double a = 3.0, E = 5e9, nu = 0.25, G = E / (2 * (1 + nu)), p0 = 18.2e6;
  const double s = std::sin(30 * 3.14159265358979323846 / 180), k = (1 + s) / (1 - s);
  const double scm = 2 * 2e6 * std::cos(std::asin(s)) / (1 - s);
  const double R = a * std::sqrt(2 * (p0 * (k - 1) + scm) / ((1 + k) * scm));  // k - 1 = 2
  // u(a) for psi = 0 (K_psi = 1), from the flow rule with Hooke's law on
  // sigma - p0 in the plastic ring (docs/insitu.md, "The closed form").
  const double pcr = (2 * p0 - scm) / (1 + k), B = scm / (k - 1), rho = R / a;
  const double C1 = (1 - nu) - nu * k + ((1 - nu) * k - nu);
  const double u =
      rho * (p0 - pcr) * R / (2 * G) - a / (2 * G) *
                                           (B * C1 * (std::pow(rho, 1 + k) - 1) / (1 + k) -
                                            (B + p0) * (1 - 2 * nu) * 2 * (rho * rho - 1) / 2);
  EXPECT_NEAR(c["key_points"]["vault"]["continuum_end_mm"][1].get<double>(), -1000 * u,
              0.03 * 1000 * u);
  EXPECT_NEAR(c["yielded_depth_m"]["vault"].get<double>(), R - a, 0.25);
  EXPECT_GT(c["yielded_triangles"].get<long>(), 100);
  EXPECT_TRUE(fs::exists(out / "continuum_profiles.csv"));
  fs::remove_all(out);
}

// Quasi-static mass scaling (on for tunnels by default) changes the path,
// not the answer: the elastic Kirsch tunnel relaxed to a ratio of 1e-5 on
// true and on scaled masses gives the same wall and vault displacements
// within 0.2% of each other, and the scaled run needs fewer steps
// (measured 8,501 against 5,501 at a 29x larger step: what takes the
// steps at the end is the creep of the walls under local damping 0.8, which
// the settle criterion waits for, not the waves); its summary reports the
// scaling, the true-mass one says it was off.
TEST(Cli, mass_scaling_changes_the_steps_not_the_elastic_answer) {
  double vault[2], wall[2];
  long steps[2];
  const char* modes[2] = {"off", "on"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch(std::string("mass-") + modes[k]);
    const Result r =
        run("run " + kTestDir + "/elastic_circular.toml -q --set engine.mass_scaling=" + modes[k] +
            " -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json j = rockfdem::test::read_json(out / "summary.json");
    ASSERT_TRUE(j["fdem"]["stages"][1]["converged"].get<bool>()) << modes[k];
    vault[k] = j["monitors"]["vault_settlement_mm"].get<double>();
    wall[k] = j["monitors"]["wall_chord_convergence_mm"].get<double>();
    steps[k] = j["steps"].get<long>();
    EXPECT_EQ(j["mass_scaling"]["enabled"].get<bool>(), k == 1);
    if (k == 1) {
      EXPECT_GT(j["mass_scaling"]["max_factor"].get<double>(), 10.0);
      // The engine's arrays one by one add up to its total, exactly; the
      // density factors of mass scaling are among them.
      long parts = 0;
      const nlohmann::json arrays = j["memory_breakdown_bytes"].flatten();
      for (const auto& [name, bytes] : arrays.items()) parts += bytes.get<long>();
      EXPECT_EQ(parts, j["memory_bytes"].get<long>());
      EXPECT_GT(j["memory_breakdown_bytes"]["tris"].value("mass_scale", 0L), 0L);
    }
    fs::remove_all(out);
  }
  EXPECT_NEAR(vault[1], vault[0], 0.002 * vault[0]);
  EXPECT_NEAR(wall[1], wall[0], 0.002 * wall[0]);
  EXPECT_LT(1.3 * double(steps[1]), double(steps[0]));
}

// Equilibrium needs the monitors settled, not only balanced forces: with
// a ratio tolerance every state meets (1), the stage stops once the
// criteria have held at `hold` (2) consecutive outputs when settle = 0,
// and goes on while the walls still converge when settle = 1e-4 (the core
// removal moves them by millimetres per 100 steps at first); its report
// carries the settle measure.
TEST(Cli, equilibrium_waits_for_the_monitors_to_settle) {
  long steps[2];
  const char* settle[2] = {"0", "1e-4"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch(std::string("settle") + std::to_string(k));
    const Result r = run("run " + kTestDir + "/elastic_circular.toml -q --set stages[2].ratio=1" +
                         " --set stages[2].every_steps=100 --set stages[2].settle=" + settle[k] +
                         " -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json j = rockfdem::test::read_json(out / "summary.json");
    const nlohmann::json& stage = j["fdem"]["stages"][1];
    EXPECT_TRUE(stage["converged"].get<bool>());
    steps[k] = stage["steps"].get<long>();
    if (k == 1) {
      EXPECT_LE(stage["settle"].get<double>(), 1e-4);
    }
    fs::remove_all(out);
  }
  EXPECT_EQ(steps[0], 200);
  EXPECT_GT(steps[1], 500);
}

// Key points can settle while cracks still break away from them. With a
// ratio every state meets and settle off, the unsupported weak-rock tunnel's
// equilibrium stage stops after `hold` (2) outputs of 100 steps; with
// broken_settle = 1e-3 it goes on while its broken count still grows by
// more than 0.1% of itself per 1000 steps, and its report says how fast it
// grew: at most the limit where it converged, else the status names it.
TEST(Cli, equilibrium_can_wait_for_the_broken_count_to_settle) {
  long steps[2];
  const char* limit[2] = {"0", "1e-3"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch(std::string("broken-settle") + std::to_string(k));
    const Result r = run("run " + kTestDir +
                         "/support_pair_unsupported.toml -q --set stages[2].ratio=1"
                         " --set stages[2].settle=0 --set stages[2].every_steps=100"
                         " --set stages[2].max_steps=2000 --set stages[2].broken_settle=" +
                         limit[k] + " -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json j = rockfdem::test::read_json(out / "summary.json");
    const nlohmann::json& stage = j["fdem"]["stages"][1];
    steps[k] = stage["steps"].get<long>();
    EXPECT_EQ(stage["criteria"]["broken_settle"].get<double>(), std::stod(limit[k]));
    ASSERT_TRUE(stage["broken_growth"].is_number()) << stage.dump();
    const double growth = stage["broken_growth"].get<double>();
    if (k == 0) {
      EXPECT_GT(growth, 1e-3);
    } else if (stage["converged"].get<bool>()) {
      EXPECT_LE(growth, 1e-3);
    } else {
      const std::string why = j.value("status_reason", std::string());
      EXPECT_NE(why.find("broken count growing"), std::string::npos) << why;
    }
    fs::remove_all(out);
  }
  EXPECT_EQ(steps[0], 200);
  EXPECT_GT(steps[1], 400);
}

// A scene whose only stage is the implicit one: `run` skips the explicit
// engine, says so, and still reports the Kirsch comparison (open hole).
TEST(Cli, elastic_only_scene_skips_the_engine) {
  const fs::path out = scratch("elastic-only");
  const Result r = run("run " + kTestDir + "/elastic_only.toml -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["steps"].get<long>(), 0);
  EXPECT_NE(j["skipped"].dump().find("fdem"), std::string::npos) << j["skipped"].dump();
  EXPECT_LT(j["insitu"]["kirsch_rel_l2"].get<double>(), 0.05);
  EXPECT_FALSE(fs::exists(out / "fdem.pvd"));
  fs::remove_all(out);
}

// Support works: the same weak-rock tunnel with lining and bolts settles
// less at the vault and breaks fewer crack elements than without
// (measured 14 mm / 656 against 49 mm / 952 after 3000 steps).
TEST(Cli, support_reduces_vault_settlement_and_broken_cracks) {
  double vault[2], broken[2];
  const char* scenes[2] = {"support_pair_supported.toml", "support_pair_unsupported.toml"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch("support" + std::to_string(k));
    const Result r = run("run " + kTestDir + "/" + scenes[k] + " -q -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(out / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    vault[k] = j["monitors"]["vault_settlement_mm"].get<double>();
    broken[k] = j["broken"]["mode_I"].get<double>() + j["broken"]["mode_II"].get<double>() +
                j["broken"]["mixed"].get<double>();
    if (k == 0) {
      EXPECT_EQ(j["counts"]["bolts"].get<int>(), 8);
    }
    fs::remove_all(out);
  }
  EXPECT_GT(vault[0], 0.0);
  EXPECT_LT(vault[0], 0.6 * vault[1]);
  EXPECT_LT(broken[0], broken[1]);
}

// A time step above the stability limit is refused before any explicit
// step (exit 2, naming engine.dt and --force-dt); forced, the run diverges
// and stops with a diagnostic (exit 3) naming the step, keeping a valid
// summary marked "failed" and the history written so far.
TEST(Cli, dt_above_the_limit_is_refused_and_forced_it_stops_with_a_diagnostic) {
  const std::string scene = kTestDir + "/ucs_small.toml --set engine.dt=2e-6 -q";
  const fs::path out = scratch("force-dt");
  const Result refused = run("run " + scene + " -o " + out.string());
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_NE(refused.output.find("engine.dt"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--force-dt"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(out / "history.csv"));

  const Result forced = run("run " + scene + " --force-dt --force -o " + out.string());
  EXPECT_EQ(forced.code, 3) << forced.output;
  EXPECT_NE(forced.output.find("step"), std::string::npos) << forced.output;
  std::ifstream in(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["status"].get<std::string>(), "failed");
  EXPECT_NE(j["failure"].get<std::string>().find("step"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "history.csv"));
  EXPECT_TRUE(fs::exists(out / "fdem_0000.vtu"));

  // At 3x the limit no velocity grows for long: crack elements break
  // instead and the specimen shatters. Energy is then created from nothing,
  // which the energy check at the first output interval (100 steps) names.
  // The sound run of the same specimen closes within 3% (measured 0.4%).
  const std::string three_limits = "3.07062e-07";  // 3 x this mesh's limit (refusal message)
  const Result shattered =
      run("run " + kTestDir + "/ucs_small.toml -q --set engine.dt=" + three_limits +
          " --force-dt --force -o " + out.string());
  EXPECT_EQ(shattered.code, 3) << shattered.output;
  EXPECT_NE(shattered.output.find("step 100: energy balance broken"), std::string::npos)
      << shattered.output;
  const Result sound = run("run " + kTestDir + "/ucs_small.toml -q --force -o " + out.string());
  ASSERT_EQ(sound.code, 0) << sound.output;
  std::ifstream again(out / "summary.json");
  const nlohmann::json k = nlohmann::json::parse(again);
  EXPECT_LT(std::abs(k["energy"]["relative_imbalance"].get<double>()), 0.03);
  EXPECT_GT(k["energy"]["fracture"].get<double>(), 0.0);
  fs::remove_all(out);
}

// An explicit failure under an in-situ stress far above the rock's
// stiffness names that likely cause (the stress-to-modulus ratio and its
// keys) besides the dt advice; at the seed's ratio it does not. Both runs
// are forced to diverge with a dt 10x the limit (0.28 ms).
TEST(Cli, explicit_failure_names_a_large_stress_to_modulus_ratio) {
  const fs::path out = scratch("stress-ratio");
  const std::string base = "run " + kTestDir +
                           "/restart_support.toml -q --force --force-dt --set engine.dt=3e-3 "
                           "--set output.vtk=false -o " +
                           out.string();
  const Result seed = run(base);  // 18.2 MPa on 3 GPa: 0.006
  ASSERT_EQ(seed.code, 3) << seed.output;
  EXPECT_EQ(seed.output.find("Likely cause"), std::string::npos) << seed.output;
  const Result high = run(base + " --set insitu.sigma_h=1e8");  // 100 MPa on 3 GPa
  ASSERT_EQ(high.code, 3) << high.output;
  for (const std::string& text :
       {high.output,
        rockfdem::test::read_json(out / "summary.json")["failure"].get<std::string>()}) {
    EXPECT_NE(text.find("Likely cause: the in-situ stress"), std::string::npos) << text;
    EXPECT_NE(text.find("is 0.0333 times the rock's Young's modulus"), std::string::npos) << text;
    EXPECT_NE(text.find("'insitu.sigma_h' = 1e+08"), std::string::npos) << text;
    EXPECT_NE(text.find("'materials.rock.young' = 3e+09"), std::string::npos) << text;
  }
  fs::remove_all(out);
}

// The lining-rock interface is a ring of crack elements re-joined with the
// [lining_interface] bond when the lining is installed. A 1 kPa bond lets
// the squeezed lining (a 20 GPa shotcrete here, stiff enough to matter)
// slip (most of the 48 broken); a 1 GPa bond holds every element. Which
// of the two settles the vault more after these 1000 steps, short of
// equilibrium, changed with the mesh (9.67 against 10.25 mm on one, 11.27
// against 9.94 on another), so the vault is not compared. Grouting is kept
// from triggering so it cannot re-join the broken bonds.
TEST(Cli, lining_interface_debonds_when_weak_and_holds_when_strong) {
  nlohmann::json lining[2];
  const char* strength[2] = {"1e3", "1e9"};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = scratch("interface" + std::to_string(k));
    const std::string s = strength[k];
    const Result r = run("run " + kTestDir + "/restart_support.toml -q -o " + out.string() +
                         " --set output.vtk=false --set stages[4].trigger_broken=100000"
                         " --set stages[4].max_steps=0 --set materials.lining.young=20e9"
                         " --set lining_interface.cohesion=" +
                         s + " --set lining_interface.tensile_strength=" + s);
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(out / "summary.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    lining[k] = j["lining"];
    EXPECT_EQ(j["fdem"]["stages"][0]["changes"]["interface_cracks"], lining[k]["interface_cracks"]);
    fs::remove_all(out);
  }
  EXPECT_GT(lining[0]["interface_cracks"].get<long>(), 20);
  EXPECT_GT(lining[0]["interface_broken"].get<long>(),
            lining[0]["interface_cracks"].get<long>() / 4);
  EXPECT_EQ(lining[1]["interface_broken"].get<long>(), 0);
}

// A --set value with a line break: TOML read the first line as the value
// and the rest as other keys, which were dropped without a word (exit 0).
// Now exit 2 naming the --set, with the break shown as an escape.
TEST(Cli, set_value_with_a_line_break_is_refused) {
  const std::string seed = rockfdem::test::kSeedScene;
  const std::pair<const char*, const char*> breaks[] = {{"\n", "\\n"}, {"\r", "\\r"}};
  for (const auto& [brk, shown] : breaks) {
    const Result r =
        run("check " + seed + " --set 'engine.dt_safety=0.5" + brk + "mesh.size_near=9'");
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("--set engine.dt_safety=0.5" + std::string(shown) +
                            "mesh.size_near=9: the value holds a line break"),
              std::string::npos)
        << r.output;
  }
}

// A --set path into an array of tables needs a whole-number index the scene
// has: anything else is bad input (exit 2, one line naming the path and the
// indices allowed), not an internal error.
TEST(Cli, set_with_a_bad_array_index_exits_two_naming_it) {
  const std::string seed = rockfdem::test::kSeedScene;
  const std::pair<const char*, const char*> cases[] = {
      {"stages[x].max_steps=1", "allowed: stages[0] to stages[9]"},
      {"stages[].max_steps=1", "allowed: stages[0] to stages[9]"},
      {"stages[99999999999999999999].max_steps=1", "allowed: stages[0] to stages[9]"},
      {"stages[-1].max_steps=1", "allowed: stages[0] to stages[9]"},
      {"bolt_fan[a].count=1", "allowed: bolt_fan[0] to bolt_fan[2]"},
      {"bolt[0].kind=cable", "the scene has no [[bolt]]"}};
  for (const auto& [set, allowed] : cases) {
    const Result r = run("check " + seed + " --set '" + set + "'");
    EXPECT_EQ(r.code, 2) << set << ": " << r.output;
    EXPECT_NE(r.output.find(std::string("--set ") + set), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(allowed), std::string::npos) << set << ": " << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}
