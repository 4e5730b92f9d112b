// `rockfdem check` states bounds a run must keep: its peak memory bound
// must hold the run's peak resident memory (getrusage of the run's
// process), and the time step it states for the start must be the run's
// (the hand-off step's for tunnels, the only one for specimens), with no
// later stage stepping above it. Shipped scenes, shortened with --set, and
// two refined variants. Run times are not asserted (docs/benchmarks.md,
// "check's bounds against runs").
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

const std::string kScenes = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/";

// The number after `label` in check's output, in the unit's scale given.
double figure(const std::string& text, const std::string& label) {
  const std::regex re(label + R"(\s+([0-9.eE+-]+))");
  std::smatch m;
  if (!std::regex_search(text, m, re)) throw std::runtime_error("no '" + label + "' in " + text);
  return std::stod(m[1]);
}

struct Measured {
  int code = -1;
  double peak_rss_bytes = 0;
  double seconds = 0;  ///< wall time, printed, never asserted
};

// `rockfdem ARGS` as its own process (sh execs it), its peak resident
// memory from wait4.
Measured measure(const std::string& args) {
  const std::string cmd = "exec " + std::string(ROCKFDEM_BINARY) + " " + args + " > /dev/null 2>&1";
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  Measured m;
  m.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  m.peak_rss_bytes = double(usage.ru_maxrss) * 1024.0;
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

struct Case {
  std::string name, scene, sets;
  bool staged;
};

// The seed tunnel cut short: its four soften stages 25 steps each, grout
// and equilibrium 100 and 200, about the 300 steps the one-shot list took.
// check's probe hands over at the last alpha; the default hands over at
// its first crack, known only from the implicit solves (alpha 1.0 in its
// weak rock mass, where the step is 0.07% longer than at 0.5), so its
// list is cut there for the time step to be the run's.
const char kShortTunnel[] =
    " --set stages[1].max_steps=25 --set stages[2].max_steps=25 --set stages[3].max_steps=25"
    " --set stages[4].max_steps=25 --set stages[8].max_steps=100 --set stages[9].max_steps=200"
    " --set insitu.alpha=[1.0]";
// The one-shot seed tunnel (hand-off at its last alpha) cut to 300 steps.
const char kShortOneShot[] = " --set stages[4].max_steps=100 --set stages[5].max_steps=200";
const std::vector<Case> kCases = {
    {"tunnel-seed", "tunnel-seed.toml", kShortTunnel, true},
    {"tunnel-seed-oneshot, size_near 0.25", "tunnel-seed-oneshot.toml",
     std::string(kShortOneShot) + " --set mesh.size_near=0.25", true},
    {"tunnel-seed-unsupported", "tunnel-seed-unsupported.toml", " --set stages[2].max_steps=300",
     true},
    {"kirsch-circular, size_near 0.4", "kirsch-circular.toml", " --set mesh.size_near=0.4", true},
    {"ucs-33k", "ucs-33k.toml", " --set engine.steps=200", false},
    {"brazilian-disc", "brazilian-disc.toml", " --set engine.steps=300", false},
    {"brazilian-disc, size_near 0.0007", "brazilian-disc.toml",
     " --set engine.steps=200 --set mesh.size_near=0.0007", false},
};

}  // namespace

TEST(CheckBounds, run_memory_and_time_step_keep_to_what_check_states) {
  for (const Case& c : kCases) {
    const std::string scene = kScenes + c.scene + c.sets + " --set output.plots=false";
    const Result check = run("check " + scene + " -j 2");
    ASSERT_EQ(check.code, 0) << c.name << ": " << check.output;
    const double memory_bound = figure(check.output, "peak memory \\(bound\\):") * 1048576.0;
    const double dt_start = figure(check.output, "time step at the start:");
    const fs::path out = scratch("bounds");
    const Measured m = measure("run " + scene + " -q -j 2 --force -o " + out.string());
    ASSERT_EQ(m.code, 0) << c.name;
    const nlohmann::json s = read_json(out / "summary.json");
    EXPECT_LE(m.peak_rss_bytes, memory_bound) << c.name;
    // check prints 8 significant digits.
    const double dt_run =
        c.staged ? s["fdem"]["handoff_step"]["dt"].get<double>() : s["dt_max"].get<double>();
    EXPECT_NEAR(dt_run, dt_start, 1e-7 * dt_start) << c.name;
    EXPECT_LE(s["dt_max"].get<double>(), dt_start * (1 + 1e-7)) << c.name;
    std::printf(
        "  %-34s peak RSS %7.1f MiB (bound %7.1f), dt start %.6g s (run %.6g, max %.6g), "
        "run %.1f s (bound %.0f s)\n",
        c.name.c_str(), m.peak_rss_bytes / 1048576.0, memory_bound / 1048576.0, dt_start, dt_run,
        s["dt_max"].get<double>(), m.seconds, figure(check.output, "run time \\(bound\\):"));
    fs::remove_all(out);
  }
}

namespace {

// The elastic circular tunnel with `n` one-step equilibrium stages (the
// stages' own costs dominate: each is a stage change and an output).
fs::path one_step_stages(const std::string& name, int n) {
  const std::string base = read_text(kTestDir + "/elastic_circular.toml");
  std::string text = base.substr(0, base.find("[[stages]]")) + "[[stages]]\nkind = \"insitu\"\n";
  for (int i = 0; i < n; ++i) text += "[[stages]]\nkind = \"equilibrium\"\nmax_steps = 1\n";
  text += "[output]\nvtk = false\nplots = false\n";
  const fs::path path = scratch(name);
  fs::create_directories(path);
  std::ofstream(path / "scene.toml") << text;
  return path / "scene.toml";
}

}  // namespace

// Per-stage costs: 999 one-step stages (as many as a scene may hold) on
// 1,378 triangles took 13-16 s here, 13 ms per stage outside its steps,
// when check's bound counted only steps and outputs (about 8 s). The bound
// now counts each stage change at 10 ms + 8 us per triangle: asserted here
// as arithmetic on check's own figures (run times are machine figures, not
// test results; docs/benchmarks.md "check's bounds against runs"), and the
// run must complete every stage.
TEST(CheckBounds, many_stages_are_counted_in_the_time_check_states) {
  const fs::path scene = one_step_stages("many-stages", 999);
  const std::string args = scene.string() + " -j 2 --set mesh.size_near=2.0";
  const Result check = run("check " + args);
  ASSERT_EQ(check.code, 0) << check.output;
  EXPECT_TRUE(has(check.output, "+ 999 stage changes at")) << check.output;
  const double triangles = figure(check.output, "triangles \\(meshed\\):");
  const double per_stage = figure(check.output, "999 stage changes at");
  EXPECT_NEAR(per_stage, 0.010 + 8e-6 * triangles, 0.005 * per_stage) << check.output;
  const double margin = figure(check.output, "s each, x");
  EXPECT_GE(figure(check.output, "run time \\(bound\\):"), margin * 999 * per_stage * 0.999)
      << check.output;
  const fs::path out = scene.parent_path() / "out";
  const Measured m = measure("run " + args + " -q -o " + out.string());
  ASSERT_EQ(m.code, 0);
  const nlohmann::json j = read_json(out / "summary.json");
  EXPECT_EQ(j["fdem"]["stages"].size(), 999u);
  std::printf("  999 one-step stages: run %.1f s, check's bound %.0f s (printed, not asserted)\n",
              m.seconds, figure(check.output, "run time \\(bound\\):"));
  fs::remove_all(scene.parent_path());
}

// More stages than any construction sequence (20,000 one-step
// stages) are bad input: exit 2 naming the key and the limit, for check
// and run alike, and nothing written.
TEST(CheckBounds, more_stages_than_the_limit_are_refused) {
  const fs::path scene = one_step_stages("too-many-stages", 20000);
  const fs::path out = scene.parent_path() / "out";
  for (const std::string command : {"check", "run"}) {
    const Result r = run(command + " " + scene.string() + " -q -o " + out.string());
    EXPECT_EQ(r.code, 2) << command << ": " << r.output.substr(0, 2000);
    EXPECT_TRUE(has(r.output, "key 'stages' = ")) << r.output.substr(0, 2000);
    EXPECT_TRUE(has(r.output,
                    ": holds 20001 entries; allowed: at most 1000 (each costs a stage "
                    "change and an output beyond its steps)"))
        << r.output.substr(0, 2000);
    EXPECT_LT(r.output.size(), 1000u) << command;
    EXPECT_FALSE(fs::exists(out)) << command;
  }
  fs::remove_all(scene.parent_path());
}

// A rock set no real rock has (E lowered tenfold: UCS/E 0.035 against
// intact rock's 0.001-0.01) is warned of by check before the run and by
// the run in summary.json's warnings and rock_plausibility; E as shipped
// (UCS/E 0.0035) draws no such warning.
TEST(CheckBounds, an_implausible_rock_set_is_warned_of_by_check_and_run) {
  const std::string scene = kTestDir + "/support_pair_supported.toml -q ";
  const std::string soft = "--set materials.rock.young=0.3e9 ";
  const std::string said = "the rock's ucs_over_young = 0.0346 is outside [0.001, 0.01]";
  const std::string checked = run("check " + scene + soft).output;
  EXPECT_TRUE(has(checked, "warning: " + said));
  // The verdict closes the output: both warnings (the rock set and its
  // l_ch, which falls with E) listed; as shipped, the l_ch one alone.
  EXPECT_TRUE(has(checked, "verdict: valid, with 2 warnings:\n  - the fracture zone's")) << checked;
  EXPECT_TRUE(has(checked, "\n  - " + said)) << checked;
  const std::string shipped = run("check " + scene).output;
  EXPECT_FALSE(has(shipped, "ucs_over_young = "));
  EXPECT_TRUE(has(shipped, "verdict: valid, with 1 warning:\n")) << shipped;
  const fs::path out = scratch("implausible-rock");
  const Result r = run("run " + scene + soft + "-j 1 --set 'stages[4].max_steps=20' " +
                       "--set output.plots=false --set output.vtk=false -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  bool warned = false;
  for (const auto& w : j["warnings"]) warned = warned || has(w.get<std::string>(), said);
  EXPECT_TRUE(warned) << j["warnings"];
  // l_ch = E GfI / ft^2 falls with E too: 0.009 m against elements of 0.3 m.
  EXPECT_EQ(j["rock_plausibility"]["outside"],
            nlohmann::json::array({"ucs_over_young", "h_over_l_ch"}));
  EXPECT_TRUE(has(read_text(out / "report.md"), "| ucs_over_young | 0.0346 | 0.001 - 0.01"));
  fs::remove_all(out);
}
