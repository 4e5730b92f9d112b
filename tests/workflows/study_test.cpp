// `rockfdem sweep` and `rockfdem calibrate` on a small elastic circular
// tunnel (study_elastic.toml: 1.1k triangles, no fracture, the implicit
// stage excavates fully, so the key points move as 1/E) and a small
// fracturing Brazilian disc (study_brazilian.toml).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"

extern char** environ;

namespace fs = std::filesystem;

using namespace rockfdem::test;  // run, scratch, read_json, read_text, kTestDir

namespace {

const std::string kScene = kTestDir + "/study_elastic.toml";
const std::string kGrid =
    " --vary materials.rock.young=3e9,6e9 --vary insitu.sigma_h=12e6,18e6 -j 1 -q";

std::vector<std::vector<std::string>> csv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_text(p));
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// Starts `rockfdem ARGS` (words split at spaces) with its output in `log`.
pid_t start(const std::string& args, const fs::path& log) {
  std::vector<std::string> words{ROCKFDEM_BINARY};
  std::istringstream in(args);
  for (std::string w; in >> w;) words.push_back(w);
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, ROCKFDEM_BINARY, &files, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&files);
  return pid;
}

// The last write time of every file named `name` under `dir`.
std::map<fs::path, fs::file_time_type> write_times(const fs::path& dir, const std::string& name) {
  std::map<fs::path, fs::file_time_type> times;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() == name) times[e.path()] = fs::last_write_time(e.path());
  return times;
}

// Polls `ready` until it holds or the process has ended (then false; the
// caller reaps it). The cap only ends a hung test.
bool wait_for(pid_t pid, const std::function<bool()>& ready) {
  for (int i = 0; i < 12000; ++i) {
    if (ready()) return true;
    if (waitpid(pid, nullptr, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

// ` --target NAME=VALUE` from a run of `scene` with `sets` (into `truth`):
// its summary.json specimen.<key> divided by `scale`, to 17 digits.
std::string own_target(const std::string& scene, const std::string& sets, const fs::path& truth,
                       const std::string& name, const char* key, double scale) {
  const Result r = run("run " + scene + " " + sets + " -j 1 -q -o " + truth.string());
  if (r.code != 0) throw std::runtime_error("the truth run failed: " + r.output);
  const auto specimen = read_json(truth / "summary.json")["specimen"];
  if (!specimen[key].is_number())
    throw std::runtime_error(std::string("no specimen.") + key + " in " + specimen.dump());
  std::ostringstream target;
  target.precision(17);
  target << " --target " << name << "=" << specimen[key].get<double>() / scale;
  return target.str();
}

}  // namespace

// Four variants, named by their values; in linear elasticity with the same
// stress, halving E doubles every displacement (to round-off: 1e-9). The
// second invocation runs nothing: it says so, and no summary.json changes.
TEST(Study, sweep_runs_each_variant_once_and_resumes) {
  const fs::path out = scratch("sweep");
  const Result first = run("sweep " + kScene + kGrid + " -o " + out.string());
  ASSERT_EQ(first.code, 0) << first.output;
  EXPECT_NE(first.output.find("4 run now, 0 taken from earlier runs"), std::string::npos)
      << first.output;
  const auto rows = csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  const std::size_t vault = column(rows[0], "vault_radial_mm"), status = column(rows[0], "status");
  std::map<std::string, double> u;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][status], "completed") << rows[r][0];
    EXPECT_TRUE(fs::exists(out / "variants" / rows[r][0] / "summary.json")) << rows[r][0];
    u[rows[r][0]] = std::stod(rows[r][vault]);
  }
  // A symmetric pair's column is the mean of its two points' readings.
  const std::size_t walls = column(rows[0], "walls_radial_mm"),
                    left = column(rows[0], "left_wall_radial_mm"),
                    right = column(rows[0], "right_wall_radial_mm");
  for (std::size_t r = 1; r < rows.size(); ++r)
    EXPECT_DOUBLE_EQ(std::stod(rows[r][walls]),
                     (std::stod(rows[r][left]) + std::stod(rows[r][right])) / 2);
  const double soft = u.at("materials.rock.young=3e9_insitu.sigma_h=12e6");
  const double stiff = u.at("materials.rock.young=6e9_insitu.sigma_h=12e6");
  EXPECT_NEAR(soft / stiff, 2.0, 1e-9);

  const auto written = write_times(out / "variants", "summary.json");
  const std::string table = read_text(out / "sweep.csv");
  // What is drawn and written changes no result: no variant reruns for it.
  const Result again = run("sweep " + kScene + kGrid +
                           " --set output.vtk=true --set output.plots=true -o " + out.string());
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("0 run now, 4 taken from earlier runs"), std::string::npos)
      << again.output;
  for (const auto& [path, time] : written) EXPECT_EQ(fs::last_write_time(path), time) << path;
  EXPECT_EQ(read_text(out / "sweep.csv"), table);
  fs::remove_all(out);
}

// Synthetic targets from the tool itself at E = 7 GPa; the fit starts at
// the scene's 5 GPa within 2 to 20 GPa and must land within 1% of 7 GPa.
// The sensitivity of a displacement to E at the optimum is the elastic
// elasticity -1 (u ~ 1/E), within the finite difference's 2%.
TEST(Study, calibrate_recovers_young_modulus_from_its_own_targets) {
  const fs::path truth = scratch("truth"), out = scratch("calibrate");
  ASSERT_EQ(
      run("run " + kScene + " --set materials.rock.young=7e9 -j 1 -q -o " + truth.string()).code,
      0);
  const auto monitors = read_json(truth / "summary.json")["monitors"];
  std::ostringstream targets;
  targets.precision(17);
  targets << " --target vault=" << monitors["vault"]["radial_mm"].get<double>()
          << " --target walls="
          << (monitors["left_wall"]["radial_mm"].get<double>() +
              monitors["right_wall"]["radial_mm"].get<double>()) /
                 2;
  const Result r =
      run("calibrate " + kScene + targets.str() +
          " --free materials.rock.young=2e9:2e10 --max-evals 40 -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto s = read_json(out / "calibration_summary.json");
  EXPECT_NEAR(s["parameters"][0]["fitted"].get<double>(), 7e9, 0.01 * 7e9) << r.output;
  for (const auto& e : s["sensitivity"]) EXPECT_NEAR(e["elasticity"].get<double>(), -1.0, 0.02);
  const auto rows = csv(out / "calibration.csv");
  EXPECT_GT(rows.size(), 3u);
  // The best is the lowest objective of every run made, not the optimiser's
  // last point nor its own "best": the smallest in the table, and its variant.
  const std::size_t col = std::find(rows[0].begin(), rows[0].end(), "objective") - rows[0].begin();
  ASSERT_LT(col, rows[0].size());
  std::size_t lowest = 1;
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (std::stod(rows[i][col]) < std::stod(rows[lowest][col])) lowest = i;
  EXPECT_DOUBLE_EQ(s["objective"].get<double>(), std::stod(rows[lowest][col]));
  EXPECT_EQ(s["best_variant"].get<std::string>(), rows[lowest][1]);
  EXPECT_EQ(run("check " + (out / "best_scene.toml").string()).code, 0);
  fs::remove_all(truth);
  fs::remove_all(out);
}

// Runs that stop before their criteria hold (here an unreachable force
// ratio) give figures that are not equilibrium figures: each scores 100 plus
// its misfit, and the summary and console say the best met no criteria.
TEST(Study, calibrate_ranks_runs_not_at_equilibrium_behind_and_says_so) {
  const fs::path out = scratch("calibrate-unmet");
  const Result r = run("calibrate " + kScene +
                       " --set stages[1].ratio=1e-30 --target vault=20 --free "
                       "materials.rock.young=2e9:2e10 --max-evals 3 -j 1 -o " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("no run met its criteria"), std::string::npos) << r.output;
  const auto s = read_json(out / "calibration_summary.json");
  EXPECT_EQ(s["best_status"], "not_at_equilibrium");
  EXPECT_FALSE(s["best_met_its_criteria"].get<bool>());
  const double misfit = s["targets"][0]["relative_misfit"].get<double>();
  EXPECT_NEAR(s["objective"].get<double>(), 100 + misfit * misfit, 1e-12);
  // Cut off at 3 runs: the stop says how far from converged.
  const std::string stop = s["stop_reason"].get<std::string>();
  EXPECT_EQ(stop.find("stopped at --max-evals, not converged: "), 0u) << stop;
  const nlohmann::json& last = s["last_improvement"];
  if (last.is_null()) {
    EXPECT_NE(stop.find("no run improved on the first"), std::string::npos) << stop;
  } else {
    EXPECT_GE(last["run"].get<int>(), 2);
    EXPECT_LE(last["run"].get<int>(), 3);
    EXPECT_GT(last["step_of_range"].get<double>(), 1e-6);
    EXPECT_GT(last["objective_drop"].get<double>(), 0.0);
  }
  fs::remove_all(out);
}

// The same sweep on one process and on two MPI ranks gives the same table,
// every figure bit for bit (the state hashes included); only the measured
// wall time, the last column, differs.
TEST(Study, sweep_table_is_the_same_on_one_and_two_ranks) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  const fs::path one = scratch("ranks1"), two = scratch("ranks2");
  ASSERT_EQ(run("sweep " + kScene + kGrid + " -o " + one.string()).code, 0);
  const Result r = run("sweep " + kScene + kGrid + " -o " + two.string(),
                       "mpirun --allow-run-as-root --oversubscribe -np 2");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto a = csv(one / "sweep.csv"), b = csv(two / "sweep.csv");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].size(), b[i].size());
    for (std::size_t c = 0; c + 1 < a[i].size(); ++c) EXPECT_EQ(a[i][c], b[i][c]) << i << "," << c;
  }
  fs::remove_all(one);
  fs::remove_all(two);
}

// Each bad study flag: exit 2, a message naming the flag, nothing written.
TEST(Study, bad_study_flags_exit_two_naming_the_flag) {
  const std::pair<std::string, std::string> cases[] = {
      {"sweep --vary materials.rock.young", "--vary materials.rock.young: expected"},
      {"sweep --vary materials.rock.young=soft,6e9", "--vary materials.rock.young=soft"},
      {"sweep --vary materials.rock.young=-1,6e9", "--vary materials.rock.young=-1"},
      {"sweep --vary nosuch.key=1,2", "unknown scene key 'nosuch.key'"},
      {"sweep --vary materials.rock.young=1e9:2e9", "needs --samples N"},
      {"sweep --samples 4 --vary materials.rock.young=1e9,2e9", "KEY=LO:HI"},
      {"sweep --samples 4 --vary tunnel.shape=0:1", "not a real-valued key"},
      {"calibrate --target vault=4 --free materials.rock.young=5e9:1e9", "--free"},
      {"calibrate --target vault=4 --free materials.rock.young=0:1e9",
       "--free materials.rock.young=0"},
      {"calibrate --target crown=4 --free materials.rock.young=1e9:5e9",
       "--target crown=4: unknown name 'crown'; allowed for this scene's model: vault"},
      {"calibrate --target vault=0 --free materials.rock.young=1e9:5e9", "--target vault=0"},
      {"calibrate --target vault=4 --weight wall=2 --free materials.rock.young=1e9:5e9",
       "--weight wall=2"},
      {"calibrate --target vault=4 --free materials.rock.young=1e9:5e9 --method simplex",
       "--method simplex: allowed: bobyqa, cobyla"},
      {"run --vary materials.rock.young=1e9,2e9", "--vary belongs to `rockfdem sweep`"},
      {"sweep --realisations 1", "--realisations 1: allowed: a whole number of runs from 2"},
      {"sweep --realisations 0 --vary materials.rock.young=1e9,2e9", "--realisations 0: allowed"},
      {"sweep --realisations 3", "--realisations 3: materials.rock.heterogeneity is 0"},
      {"sweep --set materials.rock.heterogeneity=5 --realisations 2 --vary "
       "materials.rock.heterogeneity_seed=1,2",
       "--realisations 2: 'materials.rock.heterogeneity_seed' is given twice"},
      {"calibrate --target vault=4 --free materials.rock.young=1e9:5e9 --realisations 1",
       "--realisations 1: allowed: a whole number of runs from 2"},
      {"calibrate --target vault=4 --free materials.rock.young=1e9:5e9 --realisations 4",
       "--realisations 4: materials.rock.heterogeneity is 0"},
      {"run --realisations 3",
       "--realisations belongs to `rockfdem sweep` or `rockfdem calibrate`"}};
  for (const auto& [args, expect] : cases) {
    const fs::path out = scratch("badstudy");
    const std::string command = args.substr(0, args.find(' '));
    const Result r =
        run(command + " " + kScene + args.substr(args.find(' ')) + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << args << ": " << r.output;
    EXPECT_NE(r.output.find(expect), std::string::npos) << args << ": " << r.output;
    EXPECT_FALSE(fs::exists(out)) << args;
  }
}

// Three realisations (heterogeneity seeds) of a heterogeneous disc (Weibull
// modulus 5) at each of two tensile strengths: ensemble.csv has one row per
// strength and figure, and its n, mean, standard deviation and 95% interval
// are those of sweep.csv's rows of that strength (t_{0.975,2} = 4.3026527).
// The seeds give different peaks, or the spread would say nothing.
TEST(Study, sweep_realisations_give_each_group_its_ensemble_statistics) {
  const fs::path out = scratch("ensemble");
  const std::string disc = kTestDir + "/study_brazilian.toml";
  const Result r =
      run("sweep " + disc + " --set materials.rock.heterogeneity=5 --realisations 3" +
          " --vary materials.rock.tensile_strength=4e6,5e6 -j 1 -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(r.output, (out / "ensemble.csv").string())) << r.output;
  const auto rows = csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 7u);
  const std::size_t ft = column(rows[0], "materials.rock.tensile_strength"),
                    peak = column(rows[0], "peak_stress_MPa");
  std::map<std::string, std::vector<double>> peaks;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i][column(rows[0], "status")], "completed") << rows[i][0];
    peaks[rows[i][ft]].push_back(std::stod(rows[i][peak]));
  }
  const auto ensemble = csv(out / "ensemble.csv");
  const std::vector<std::string>& head = ensemble[0];
  std::size_t checked = 0;
  for (std::size_t i = 1; i < ensemble.size(); ++i) {
    const std::vector<std::string>& e = ensemble[i];
    if (e[column(head, "figure")] != "peak_stress_MPa") continue;
    const std::vector<double>& p = peaks.at(e[column(head, "materials.rock.tensile_strength")]);
    ASSERT_EQ(p.size(), 3u);
    const double mean = (p[0] + p[1] + p[2]) / 3;
    double squares = 0;
    for (double v : p) squares += (v - mean) * (v - mean);
    const double sd = std::sqrt(squares / 2), half = 4.302652729749464 * sd / std::sqrt(3.0);
    EXPECT_GT(sd, 1e-3 * mean) << "the seeds gave the same disc";
    EXPECT_EQ(e[column(head, "n")], "3");
    EXPECT_EQ(e[column(head, "excluded")], "0");
    EXPECT_NEAR(std::stod(e[column(head, "mean")]), mean, 1e-12 * mean);
    EXPECT_NEAR(std::stod(e[column(head, "std")]), sd, 1e-9 * sd);
    EXPECT_NEAR(std::stod(e[column(head, "ci95_low")]), mean - half, 1e-9 * mean);
    EXPECT_NEAR(std::stod(e[column(head, "ci95_high")]), mean + half, 1e-9 * mean);
    EXPECT_EQ(std::stod(e[column(head, "min")]), *std::min_element(p.begin(), p.end()));
    EXPECT_EQ(std::stod(e[column(head, "max")]), *std::max_element(p.begin(), p.end()));
    ++checked;
  }
  EXPECT_EQ(checked, 2u);
  fs::remove_all(out);
}

// calibrate --realisations 2 on the heterogeneous disc, one search point
// and its two sensitivity points: each point's figure in calibration.csv is
// the mean of its two seeds' peaks (read from their own summaries), its std
// their sample standard deviation |a - b| / sqrt(2), n = 2, and the
// objective the relative misfit of the mean. The same command again runs
// nothing and writes the same table.
TEST(Study, calibrate_realisations_fit_the_mean_of_the_seeds) {
  const fs::path out = scratch("calibrate-ensemble");
  const std::string fit =
      " --target tensile_strength=9 --free materials.rock.tensile_strength=3e6:8e6";
  const std::string ensemble = " --set materials.rock.heterogeneity=5 --realisations 2";
  const std::string args = "calibrate " + kTestDir + "/study_brazilian.toml" + fit + ensemble +
                           " --max-evals 1 -j 1 -q -o " + out.string();
  const Result r = run(args);
  ASSERT_EQ(r.code, 0) << r.output;
  const auto summary = read_json(out / "calibration_summary.json");
  EXPECT_EQ(summary["realisations"], 2);
  EXPECT_TRUE(summary["targets"][0]["fitted_std"].is_number()) << summary.dump();
  const auto rows = csv(out / "calibration.csv");
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<std::string>& head = rows[0];
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::vector<std::string>& row = rows[i];
    double peak[2];
    for (int s = 0; s < 2; ++s)
      peak[s] = read_json(out / "variants" /
                          (row[column(head, "variant")] +
                           "_materials.rock.heterogeneity_seed=" + std::to_string(s + 1)) /
                          "summary.json")["specimen"]["peak_stress"]
                    .get<double>() /
                1e6;
    const double mean = (peak[0] + peak[1]) / 2, sd = std::abs(peak[0] - peak[1]) / std::sqrt(2.0);
    EXPECT_GT(sd, 1e-3 * mean) << "the seeds gave the same disc";
    EXPECT_EQ(row[column(head, "n")], "2");
    EXPECT_EQ(row[column(head, "status")], "completed");
    EXPECT_NEAR(std::stod(row[column(head, "tensile_strength_MPa")]), mean, 1e-12 * mean);
    EXPECT_NEAR(std::stod(row[column(head, "tensile_strength_std_MPa")]), sd, 1e-9 * sd);
    EXPECT_NEAR(std::stod(row[column(head, "objective")]), std::pow((mean - 9) / 9, 2), 1e-12);
  }
  const std::string table = read_text(out / "calibration.csv");
  const auto written = write_times(out / "variants", "summary.json");
  EXPECT_EQ(written.size(), 6u);
  const Result again = run(args);
  ASSERT_EQ(again.code, 0) << again.output;
  for (const auto& [path, time] : written) EXPECT_EQ(fs::last_write_time(path), time) << path;
  EXPECT_EQ(read_text(out / "calibration.csv"), table);
  fs::remove_all(out);
}

// A fracturing specimen: the disc's tensile strength 2P/(pi D t) at
// ft = 5.5 MPa (the truth) is the target; the fit starts at the scene's
// 4 MPa within 2 to 8 MPa. Measured on this scene (docs/studies.md), the
// peak is continuous in ft with elasticity 0.52, steady for changes of ft
// from 1e-5 to 5% (the peak step moves by one step per 3e-4 of ft, a kink
// in slope, not a jump), so the search, stopping at steps of 1e-6 of the
// range (6 Pa), must land within 1e-4 of ft (550 Pa, a misfit of 5e-5 in
// the peak). The peak rises less than in proportion to ft (elasticity
// between 0 and 1): part of it is the loading rate's overshoot.
TEST(Study, calibrate_recovers_tensile_strength_of_a_fracturing_disc) {
  const std::string scene = kTestDir + "/study_brazilian.toml";
  const fs::path truth = scratch("disc-truth"), out = scratch("disc-calibrate");
  const std::string target = own_target(scene, "--set materials.rock.tensile_strength=5.5e6", truth,
                                        "tensile_strength", "peak_stress", 1e6);
  const auto specimen = read_json(truth / "summary.json")["specimen"];
  ASSERT_TRUE(specimen.contains("stopped_after_peak_at_step")) << specimen.dump();
  const Result r =
      run("calibrate " + scene + target +
          " --free materials.rock.tensile_strength=2e6:8e6 --max-evals 40 -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto s = read_json(out / "calibration_summary.json");
  EXPECT_NEAR(s["parameters"][0]["fitted"].get<double>(), 5.5e6, 1e-4 * 5.5e6) << r.output;
  const double elasticity = s["sensitivity"][0]["elasticity"].get<double>();
  EXPECT_GT(elasticity, 0.0);
  EXPECT_LT(elasticity, 1.0);
  fs::remove_all(truth);
  fs::remove_all(out);
}

// The UCS's pre-peak modulus as a target (what a lab calibration fits
// beside the peaks): the small UCS at E = 33 GPa makes the target, the
// search starts at the scene's 30 GPa within 20-40 GPa. The modulus (the
// slope over 0.2-0.6 of the peak) follows E with elasticity about 1.1
// (dt and the readings move with E), so a search stopping at steps of
// 1e-6 of the range (20 kPa) must land within 1e-3 of E; one that stops
// short, or a modulus that did not follow E, fails.
TEST(Study, calibrate_recovers_young_modulus_from_a_ucs_pre_peak_modulus) {
  const std::string scene = kTestDir + "/ucs_small.toml --set output.vtk=false";
  const fs::path truth = scratch("ucs-modulus-truth"), out = scratch("ucs-modulus-calibrate");
  const std::string target =
      own_target(scene, "--set materials.rock.young=33e9", truth, "modulus", "modulus", 1e9);
  const Result r =
      run("calibrate " + scene + target +
          " --free materials.rock.young=20e9:40e9 --max-evals 40 -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto s = read_json(out / "calibration_summary.json");
  EXPECT_NEAR(s["parameters"][0]["fitted"].get<double>(), 33e9, 1e-3 * 33e9) << r.output;
  EXPECT_EQ(s["targets"][0]["unit"], "GPa");
  EXPECT_GT(s["sensitivity"][0]["elasticity"].get<double>(), 0.5);
  fs::remove_all(truth);
  fs::remove_all(out);
}

// Latin hypercube: 7 samples over two ranges. Each range is cut into 7
// equal bins and each bin of each key holds exactly one sample, within the
// bounds; a second invocation draws the same points (it finds every variant
// already run, and writes the same table).
TEST(Study, latin_hypercube_is_stratified_bounded_and_deterministic) {
  const fs::path out = scratch("latin");
  const std::string args = "sweep " + kScene +
                           " --samples 7 --vary materials.rock.young=3e9:6e9"
                           " --vary insitu.sigma_h=12e6:18e6 --set stages[1].max_steps=10"
                           " -j 1 -q -o " +
                           out.string();
  const Result first = run(args);
  ASSERT_EQ(first.code, 0) << first.output;
  const auto rows = csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 8u);
  const std::pair<std::string, std::pair<double, double>> ranges[] = {
      {"materials.rock.young", {3e9, 6e9}}, {"insitu.sigma_h", {12e6, 18e6}}};
  for (const auto& [key, range] : ranges) {
    const std::size_t c = column(rows[0], key);
    std::vector<long> bins;
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const double v = std::stod(rows[r][c]);
      EXPECT_GE(v, range.first) << key;
      EXPECT_LT(v, range.second) << key;
      bins.push_back(long(std::floor((v - range.first) / (range.second - range.first) * 7)));
    }
    std::sort(bins.begin(), bins.end());
    for (long b = 0; b < 7; ++b) EXPECT_EQ(bins[std::size_t(b)], b) << key;
  }
  const std::string table = read_text(out / "sweep.csv");
  const Result again = run(args);
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("0 run now, 7 taken from earlier runs"), std::string::npos)
      << again.output;
  EXPECT_EQ(read_text(out / "sweep.csv"), table);
  fs::remove_all(out);
}

// sweep.csv is rewritten after every finished variant: a sweep killed
// (SIGKILL) once the table first appears leaves every variant's row, the
// finished ones with their figures and the rest "pending" with none; the
// same command then runs only the pending ones.
TEST(Study, interrupted_sweep_leaves_a_partial_table) {
  const fs::path out = scratch("partial"), log = scratch("partial-log");
  const std::string args = "sweep " + kScene + kGrid + " -o " + out.string();
  const pid_t pid = start(args, log);
  const bool appeared = wait_for(pid, [&] { return fs::exists(out / "sweep.csv"); });
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(appeared) << "the sweep ended without a table: " << read_text(log);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it was killed: " << read_text(log);
  const auto rows = csv(out / "sweep.csv");
  ASSERT_EQ(rows.size(), 5u);
  const std::size_t state = column(rows[0], "status"), vault = column(rows[0], "vault_radial_mm");
  std::size_t done = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r][state] == "completed") {
      ++done;
      EXPECT_FALSE(rows[r][vault].empty()) << rows[r][0];
      EXPECT_TRUE(fs::exists(out / "variants" / rows[r][0] / "variant.json")) << rows[r][0];
    } else {
      EXPECT_EQ(rows[r][state], "pending") << rows[r][0];
      EXPECT_TRUE(rows[r][vault].empty()) << rows[r][0];
    }
  }
  EXPECT_GE(done, 1u);
  EXPECT_LT(done, 4u);
  const Result resumed = run(args);
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find(std::to_string(4 - done) + " run now, " + std::to_string(done) +
                                " taken from earlier runs"),
            std::string::npos)
      << resumed.output;
  fs::remove_all(out);
  fs::remove(log);
}

// A second study into a folder a running sweep holds (once its first run
// has begun) is refused at once (exit 2, naming the holder's PID, nothing
// run). The holder, a sweep of twelve disc runs (about a second each), must
// still be running when both refusals have come back; then it is stopped.
TEST(Study, study_folder_is_locked_against_a_second_study) {
  const fs::path out = scratch("locked"), log = scratch("locked-log");
  const std::string disc = kTestDir + "/study_brazilian.toml";
  const pid_t pid = start("sweep " + disc +
                              " --vary materials.rock.tensile_strength=3e6,3.5e6,4e6,4.5e6,5e6,"
                              "5.5e6,6e6,6.5e6,7e6,7.5e6,8e6,8.5e6 -j 1 -q -o " +
                              out.string(),
                          log);
  const bool started = wait_for(pid, [&] { return fs::exists(out / "variants"); });
  const Result second = run("sweep " + kScene + kGrid + " -o " + out.string());
  const Result third = run("calibrate " + disc +
                           " --target tensile_strength=9 --free materials.rock.tensile_strength="
                           "2e6:8e6 -j 1 -q -o " +
                           out.string());
  const bool held_throughout = waitpid(pid, nullptr, WNOHANG) == 0;
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  ASSERT_TRUE(started) << "the sweep ended before it was seen: " << read_text(log);
  for (const Result& r : {second, third}) {
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("in use by another rockfdem run (PID " + std::to_string(pid) + ")"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("run now"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(out / "calibration.csv"));
  EXPECT_TRUE(held_throughout) << "the sweep ended before the others were refused: "
                               << read_text(log);
  fs::remove_all(out);
  fs::remove(log);
}

// A SIGTERM or SIGINT at any moment of a study stops it with 128 + signal
// (143, 130). The signal is raised by the program itself at a named moment
// (ROCKFDEM_TEST_SIGNAL_AT, interrupt.hpp), so each case lands where it is
// meant to: while the variants' scenes are checked, before a variant, as its
// run installs its handlers (which used to clear the request), in the gap
// between a variant's last check and its record (where the next variant's
// handlers used to drop it and the sweep ran on to exit 0), once
// the last variant is recorded, after the table is written, and as the
// process closes. Variants recorded before the signal are kept: the same
// command then runs only the rest.
TEST(Study, a_signal_at_any_moment_of_a_sweep_stops_it) {
  const fs::path out = scratch("signal-sweep");
  const std::string args = "sweep " + kScene + kGrid + " -o " + out.string();
  struct Case {
    std::string moment;
    int code;
    std::size_t recorded;  // variants with a variant.json afterwards
  };
  const std::vector<Case> cases{
      {"study-start", 143, 0},        {"variant-start", 143, 0}, {"variant-start#3", 130, 2},
      {"variant-run#2", 143, 1},      {"variant-end", 143, 1},   {"variant-end#2", 130, 2},
      {"variant-recorded#4", 143, 4}, {"study-end", 143, 4},     {"command-end", 143, 4}};
  for (const Case& c : cases) {
    fs::remove_all(out);
    const std::string at = c.moment + (c.code == 130 ? ":INT" : "");
    const Result r = run(args, "env ROCKFDEM_TEST_SIGNAL_AT=" + at);
    EXPECT_EQ(r.code, c.code) << at << ": " << r.output;
    EXPECT_TRUE(has(r.output, c.code == 130 ? "signal 2 (SIGINT)" : "signal 15 (SIGTERM)"))
        << at << ": " << r.output;
    std::size_t recorded = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out / "variants", ec))
      recorded += fs::exists(e.path() / "variant.json");
    EXPECT_EQ(recorded, c.recorded) << at << ": " << r.output;
  }
  // The last case left every variant recorded: nothing runs again.
  const Result resumed = run(args);
  ASSERT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_TRUE(has(resumed.output, "0 run now, 4 taken from earlier runs")) << resumed.output;
  fs::remove_all(out);
}

// The same for a calibration: between its evaluations (inside NLopt's
// objective), in the gap after a run, and as it ends.
TEST(Study, a_signal_at_any_moment_of_a_calibration_stops_it) {
  const fs::path out = scratch("signal-calibrate");
  const std::string args = "calibrate " + kScene +
                           " --target vault=20 --free materials.rock.young=2e9:2e10 "
                           "--max-evals 3 -j 1 -q -o " +
                           out.string();
  for (const std::string at :
       {"study-start", "variant-start#2", "variant-end:INT", "study-end", "command-end"}) {
    fs::remove_all(out);
    const Result r = run(args, "env ROCKFDEM_TEST_SIGNAL_AT=" + at);
    const bool sigint = has(at, ":INT");
    EXPECT_EQ(r.code, sigint ? 130 : 143) << at << ": " << r.output;
    EXPECT_TRUE(has(r.output, sigint ? "signal 2 (SIGINT)" : "signal 15 (SIGTERM)"))
        << at << ": " << r.output;
  }
  fs::remove_all(out);
}

// Resume takes every finished status from the variant's folder: completed,
// not_at_equilibrium (an unreachable ratio), unstable (a span fraction of
// 1e-6, passed at the first output), refused (engine.dt = 1 s, above the
// limit) and, with --force-dt, failed. The second invocation runs nothing
// and rewrites no variant's summary.json.
TEST(Study, resume_reruns_no_finished_status) {
  const fs::path out = scratch("resume-statuses"), forced = scratch("resume-failed");
  const std::string mixed = "sweep " + kScene +
                            " --vary stages[1].ratio=1e-5,1e-14"
                            " --vary stages[1].unstable_fraction=0.05,1e-6"
                            " --vary engine.dt=0,1 -j 1 -q -o " +
                            out.string();
  const std::string failing =
      "sweep " + kScene + " --force-dt --vary engine.dt=1 -j 1 -q -o " + forced.string();
  for (const auto& [args, dir, n] : {std::tuple{mixed, out, 8}, std::tuple{failing, forced, 1}}) {
    const Result first = run(args);
    ASSERT_EQ(first.code, 0) << first.output;
    const auto written = write_times(dir / "variants", "variant.json");
    EXPECT_EQ(written.size(), std::size_t(n)) << first.output;
    const Result again = run(args);
    ASSERT_EQ(again.code, 0) << again.output;
    EXPECT_TRUE(has(again.output, "0 run now, " + std::to_string(n) + " taken from earlier runs"))
        << again.output;
    for (const auto& [path, time] : written) EXPECT_EQ(fs::last_write_time(path), time) << path;
  }
  std::set<std::string> statuses;
  for (const fs::path& dir : {out, forced}) {
    const auto rows = csv(dir / "sweep.csv");
    const std::size_t status = column(rows[0], "status");
    for (std::size_t r = 1; r < rows.size(); ++r) statuses.insert(rows[r][status]);
  }
  EXPECT_EQ(statuses, (std::set<std::string>{"completed", "not_at_equilibrium", "unstable",
                                             "refused", "failed"}));
  fs::remove_all(out);
  fs::remove_all(forced);
}

// A variant's record in its place is this program's own small JSON file;
// anything else there (a FIFO, a record nested 100,000 levels deep under its identity, one whose
// result has the wrong types) is not waited on, read whole or dumped: it counts as no record, and
// the same command runs that variant again and ends with exit 0.
TEST(Study, a_forged_variant_record_is_run_again) {
  const fs::path out = scratch("forged-record");
  const std::string args =
      "sweep " + kScene + " --vary materials.rock.young=3e9 -j 1 -q -o " + out.string();
  const Result first = run(args);
  ASSERT_EQ(first.code, 0) << first.output;
  const fs::path record = out / "variants" / "materials.rock.young=3e9" / "variant.json";
  ASSERT_TRUE(fs::exists(record)) << first.output;
  const nlohmann::json written = read_json(record);
  const std::vector<std::pair<std::string, std::function<void()>>> forgeries{
      {"fifo", [&] { ASSERT_EQ(mkfifo(record.c_str(), 0644), 0); }},
      {"deep",
       [&] {
         const std::string deep = std::string(100000, '[') + std::string(100000, ']');
         std::ofstream(record) << "{\"identity\": " << written["identity"].dump()
                               << ", \"result\": {\"figures\": " << deep << "}}";
       }},
      {"types", [&] {
         nlohmann::json j = written;
         j["result"]["status"] = 7;
         std::ofstream(record) << j.dump();
       }}};
  for (const auto& [name, forge] : forgeries) {
    fs::remove(record);
    forge();
    const Result again = run(args, "timeout 120");
    EXPECT_EQ(again.code, 0) << name << ": " << again.output;
    EXPECT_TRUE(has(again.output, "1 run now, 0 taken from earlier runs"))
        << name << ": " << again.output;
    EXPECT_EQ(read_json(record)["result"]["status"], "completed") << name;
  }
  fs::remove_all(out);
}
