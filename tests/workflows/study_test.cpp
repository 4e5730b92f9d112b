// `rockfdem sweep` and `rockfdem calibrate` on a small elastic circular
// tunnel (study_elastic.toml: 1.1k triangles, no fracture, the implicit
// stage excavates fully, so the key points move as 1/E).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "cli_runner.hpp"

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
  const double soft = u.at("materials.rock.young=3e9_insitu.sigma_h=12e6");
  const double stiff = u.at("materials.rock.young=6e9_insitu.sigma_h=12e6");
  EXPECT_NEAR(soft / stiff, 2.0, 1e-9);

  std::map<fs::path, fs::file_time_type> written;
  for (const auto& e : fs::recursive_directory_iterator(out / "variants"))
    if (e.path().filename() == "summary.json") written[e.path()] = fs::last_write_time(e.path());
  const std::string table = read_text(out / "sweep.csv");
  const Result again = run("sweep " + kScene + kGrid + " -o " + out.string());
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
          << " --target left_wall=" << monitors["left_wall"]["radial_mm"].get<double>();
  const Result r =
      run("calibrate " + kScene + targets.str() +
          " --free materials.rock.young=2e9:2e10 --max-evals 40 -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto s = read_json(out / "calibration_summary.json");
  EXPECT_NEAR(s["parameters"][0]["fitted"].get<double>(), 7e9, 0.01 * 7e9) << r.output;
  for (const auto& e : s["sensitivity"]) EXPECT_NEAR(e["elasticity"].get<double>(), -1.0, 0.02);
  EXPECT_GT(csv(out / "calibration.csv").size(), 3u);
  EXPECT_EQ(run("check " + (out / "best_scene.toml").string()).code, 0);
  fs::remove_all(truth);
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
      {"run --vary materials.rock.young=1e9,2e9", "--vary belongs to `rockfdem sweep`"}};
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
