// The scene's monitors and extensometers in a run: readings against the
// closed form of an elastic circular opening under hydrostatic stress, and
// the points a run refuses before writing anything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

// Lame: the excavation's radial displacement towards the opening at r [m].
// p = 10 MPa, a = 3 m, G = 5 GPa / (2 x 1.25) = 2 GPa.
double lame_mm(double r) { return 1000 * 10e6 * 9 / (2 * 2e9 * r); }

// extensometer_circular.toml with `extra` appended; returns the scene's path.
fs::path scene_with(const fs::path& dir, const std::string& extra) {
  fs::create_directories(dir);
  const fs::path p = dir / "scene.toml";
  std::ofstream(p) << read_text(kTestDir + "/extensometer_circular.toml") << '\n' << extra;
  return p;
}

}  // namespace

// What is compared: the displacement the excavation causes (the implicit
// stage's open hole plus 200 explicit steps from that equilibrium), along
// each extensometer's axis, towards the opening. The relative readings
// (each point against the deepest anchor, taken as fixed) follow
// u_r(r) - u_r(r_deepest), the absolute ones u_r(r), each within 3% (the
// finite 100 m box adds about 0.5% at these radii, the 0.3 m elements
// about 1%). The monitor 1 m above the crown settles by u_r(4).
TEST(Extensometer, elastic_circular_opening_reads_the_lame_profile) {
  const fs::path out = scratch("extensometer");
  const Result r =
      run("run " + kTestDir + "/extensometer_circular.toml -q -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  const auto expect_profile = [&](const std::string& name, double r0, double length, int n) {
    const nlohmann::json& points = j.at("extensometers").at(name).at("points");
    ASSERT_EQ(points.size(), std::size_t(n + 1)) << name;
    for (int k = 0; k <= n; ++k) {
      const double rk = r0 + length * k / n, rn = r0 + length;
      const double rel = lame_mm(rk) - lame_mm(rn), abs = lame_mm(rk);
      EXPECT_NEAR(points[k].at("absolute_mm").get<double>(), abs, 0.03 * abs) << name << k;
      EXPECT_NEAR(points[k].at("relative_mm").get<double>(), rel, 0.03 * rel + 1e-12) << name << k;
    }
  };
  expect_profile("wall", 3, 6, 3);
  expect_profile("diagonal", 3.5, 5.5, 2);
  const double settle = -j.at("monitors").at("above_crown").at("uy_mm").get<double>();
  EXPECT_NEAR(settle, lame_mm(4), 0.03 * lame_mm(4));
  EXPECT_NEAR(j.at("monitors").at("above_crown").at("ux_mm").get<double>(), 0, 0.01 * settle);
  // history.csv carries the same readings per output.
  const std::string header = read_text(out / "history.csv");
  for (const char* c : {"above_crown_ux_mm", "above_crown_u_mm", "wall_a0_mm", "wall_a2_mm",
                        "wall_a3_abs_mm", "diagonal_a1_mm", "vault_broken_depth_m"})
    EXPECT_NE(header.find(c), std::string::npos) << c;
  EXPECT_EQ(header.find("wall_a3_mm"), std::string::npos);  // the deepest is the reference
  fs::remove_all(out);
}

// Each misplaced or misnamed instrument is refused with exit code 2 before
// any output, naming the key, its index and the point.
TEST(Extensometer, misplaced_or_misnamed_instruments_are_refused) {
  const fs::path dir = scratch("instrument-refusals");
  const struct {
    std::string extra, expect1, expect2;
  } cases[] = {
      {"[[monitor]]\nname = \"centre\"\nx = 0.5\ny = 0.0\n", "monitor[1]",
       "(0.5, 0) m lies inside"},
      {"[[monitor]]\nname = \"far\"\nx = 60.0\ny = 0.0\n", "monitor[1]", "outside the rock domain"},
      {"[[monitor]]\nname = \"above_crown\"\nx = 0.0\ny = 6.0\n", "monitor[1].name",
       "another monitor"},
      {"[[monitor]]\nname = \"two words\"\nx = 0.0\ny = 6.0\n", "monitor[1].name",
       "letters, digits"},
      {"[[monitor]]\nname = \"vault\"\nx = 0.0\ny = 6.0\n", "monitor[1].name", "key point"},
      {"[[monitor]]\nname = \"late\"\nx = 0.0\ny = 6.0\nrelative_to_support = true\n",
       "monitor[1].relative_to_support", "no support"},
      {"[[extensometer]]\nname = \"across\"\nhead = [-5.0, 0.0]\ndirection = [1.0, 0.0]\n"
       "length = 10.0\nanchors = 4\n",
       "extensometer[2]", "anchor 1 at (-2.5, 0) m lies inside"},
      {"[[extensometer]]\nname = \"long\"\nfrom = \"vault\"\nlength = 60.0\n",
       "extensometer[2] \"long\" anchor 3", "lies in no triangle"},
  };
  for (const auto& c : cases) {
    const fs::path scene = scene_with(dir, c.extra);
    const fs::path out = dir / "out";
    const Result r = run("run " + scene.string() + " -q -j 1 -o " + out.string());
    EXPECT_EQ(r.code, 2) << c.extra << r.output;
    EXPECT_NE(r.output.find(c.expect1), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(c.expect2), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "summary.json")) << c.extra;
  }
  fs::remove_all(dir);
}

// A monitor read relative to the support reads 0 until the lining stage
// installs the ring and from then on the in-situ-based reading minus its
// value at installation: the last row of the soften stage (the lining
// stage takes no step), to the 10 digits history.csv prints. An
// extensometer read relative to the support likewise, both its reading
// against the deepest anchor and its head's axial displacement.
TEST(Monitor, relative_to_support_starts_at_the_lining_installation) {
  const fs::path out = scratch("relative-monitor");
  const Result r = run("run " + kTestDir + "/relative_monitor.toml -q -j 1 -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream csv(out / "history.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> cols;
  for (std::stringstream h(line); std::getline(h, line, ',');) cols.push_back(line);
  const auto col = [&](const std::string& name) {
    return std::size_t(std::find(cols.begin(), cols.end(), name) - cols.begin());
  };
  const nlohmann::json j = read_json(out / "summary.json");
  const std::vector<std::string> stages = j.at("history_stages");
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    for (std::stringstream s(line); std::getline(s, line, ',');) row.push_back(std::stod(line));
    rows.push_back(row);
  }
  double at_install = std::nan(""), ext_at_install = at_install, head_at_install = at_install;
  int before = 0, after = 0;
  for (const auto& row : rows) {
    const std::string stage = stages.at(std::size_t(row[col("stage")]));
    const double abs = row[col("from_insitu_uy_mm")], rel = row[col("from_lining_uy_mm")];
    // The extensometers' readings: the head against the deepest anchor, and
    // the head's own axial displacement.
    const double ext_abs = row[col("ext_insitu_a0_mm")], ext_rel = row[col("ext_lining_a0_mm")];
    const double head_abs = row[col("ext_insitu_a0_abs_mm")];
    const double head_rel = row[col("ext_lining_a0_abs_mm")];
    if (stage == "insitu" || stage == "soften") {
      EXPECT_EQ(rel, 0.0) << stage;
      EXPECT_EQ(ext_rel, 0.0) << stage;
      EXPECT_EQ(head_rel, 0.0) << stage;
      at_install = abs;
      ext_at_install = ext_abs;
      head_at_install = head_abs;
      ++before;
    } else {
      EXPECT_NEAR(rel, abs - at_install, 1e-9 * std::abs(abs)) << stage;
      EXPECT_NEAR(ext_rel, ext_abs - ext_at_install, 2e-9 * std::abs(ext_abs) + 1e-12) << stage;
      EXPECT_NEAR(head_rel, head_abs - head_at_install, 2e-9 * std::abs(head_abs)) << stage;
      ++after;
    }
  }
  EXPECT_EQ(before, 4);  // the hand-off and 3 soften outputs
  EXPECT_EQ(after, 3);
  // The core's removal moves the crown after installation: a reading to check.
  EXPECT_GT(std::abs(rows.back()[col("from_lining_uy_mm")]), 0.01);
  EXPECT_EQ(j.at("monitors").at("from_lining").at("from"), "support");
  EXPECT_GT(std::abs(rows.back()[col("ext_lining_a0_abs_mm")]), 0.01);
  EXPECT_EQ(j.at("extensometers").at("ext_lining").at("read_from"), "support");
  EXPECT_EQ(j.at("extensometers").at("ext_insitu").at("read_from"), "in-situ state");
  // report.md lists both, with what they read from and the summary's figures.
  const std::string md = read_text(out / "report.md");
  const nlohmann::json& head = j.at("extensometers").at("ext_lining").at("points").at(0);
  char row[200];
  std::snprintf(row, sizeof row, "| ext_lining | vault | support | 6.00 | %.2f | %.2f |",
                head.at("relative_mm").get<double>(), head.at("absolute_mm").get<double>());
  EXPECT_NE(md.find(row), std::string::npos) << row << "\n" << md;
  EXPECT_NE(md.find("| from_lining | 0.00 | 4.00 | support |"), std::string::npos) << md;
  fs::remove_all(out);
}

// The support reference is run state: a run restarted from a checkpoint
// taken after the lining's installation writes the same history.csv,
// relative readings included, as the run that went through.
TEST(Monitor, restart_after_the_support_keeps_the_relative_readings) {
  const fs::path ref = scratch("relative-ref"), out = scratch("relative-restart");
  const std::string scene = kTestDir + "/relative_monitor.toml";
  ASSERT_EQ(run("run " + scene + " -q -j 1 --checkpoint-every 100 -o " + ref.string()).code, 0);
  std::vector<fs::path> kept;
  for (const auto& e : fs::directory_iterator(ref / "checkpoints")) kept.push_back(e.path());
  std::sort(kept.begin(), kept.end());
  ASSERT_FALSE(kept.empty());
  // checkpoint_<step>: the older kept one is in the equilibrium stage.
  const std::string stem = kept.front().stem().string();
  ASSERT_GT(std::stol(stem.substr(stem.find('_') + 1)), 301) << stem;
  const Result r =
      run("run " + scene + " -q -j 1 --restart " + kept.front().string() + " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_text(out / "history.csv"), read_text(ref / "history.csv"));
  fs::remove_all(ref);
  fs::remove_all(out);
}
