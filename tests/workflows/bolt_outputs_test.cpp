// Bolt outputs of a tunnel run as a script reads them (docs/output-formats.md,
// "Bolts"): history.csv's bolt_NN_max_axial_kN is the largest-magnitude
// station of that step's bolts.csv profile, the summary's force per bolt is
// the final one and lies on its bolt_NN.csv profile, every force is a bar's
// (within the steel's ultimate force, fu pi d^2 / 4), and each frame after
// installation has its bolts_NNNN.vtp in bolts.pvd.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

using Table = std::vector<std::map<std::string, double>>;

// A CSV of numbers as rows of name -> value.
Table read_csv(const fs::path& p) {
  std::istringstream in(read_text(p));
  std::string header, line;
  std::getline(in, header);
  std::vector<std::string> names;
  std::istringstream h(header);
  for (std::string n; std::getline(h, n, ',');) names.push_back(n);
  Table rows;
  while (std::getline(in, line)) {
    std::istringstream v(line);
    std::map<std::string, double> row;
    std::string value;
    for (std::size_t k = 0; k < names.size() && std::getline(v, value, ','); ++k)
      row[names[k]] = std::stod(value);
    rows.push_back(row);
  }
  return rows;
}

// The signed force of largest magnitude among `rows` (first of equals).
double largest(const Table& rows) {
  double best = 0;
  for (const auto& r : rows)
    if (std::abs(r.at("axial_force_kN")) > std::abs(best)) best = r.at("axial_force_kN");
  return best;
}

bool near(double a, double b, double rel) { return std::abs(a - b) <= rel * std::abs(b) + 1e-9; }

}  // namespace

// restart_support: 8 bolts of 25 mm, 2 m, installed at the hand-off, 1200
// steps with grouting. bolts.csv holds 6 figures: history agrees to 1e-5.
TEST(BoltOutputs, history_profiles_summary_and_frames_agree) {
  const fs::path out = scratch("bolt-outputs");
  const Result r = run("run " + kTestDir + "/restart_support.toml -q -j 1 -o " + out.string() +
                       " --set output.plots=false");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(out / "summary.json");
  const Table history = read_csv(out / "history.csv");
  const Table profiles = read_csv(out / "bolts.csv");
  const double fu_bar = 500e6 * M_PI * 0.025 * 0.025 / 4 / 1e3;  // [kN], default steel
  std::map<long, std::map<int, Table>> by_step;
  for (const auto& p : profiles) {
    by_step[long(p.at("step"))][int(p.at("bolt"))].push_back(p);
    EXPECT_LE(std::abs(p.at("axial_force_kN")), fu_bar) << "a bar cannot carry more";
  }
  ASSERT_EQ(history.size(), by_step.size() + 1) << "every row after the hand-off's has profiles";
  for (const auto& row : history) {
    for (int b = 0; b < 8; ++b) {
      const double h = row.at("bolt_0" + std::to_string(b) + "_max_axial_kN");
      const auto step = by_step.find(long(row.at("step")));
      if (step == by_step.end()) {
        EXPECT_EQ(h, 0.0) << "not installed yet";
        continue;
      }
      EXPECT_TRUE(near(h, largest(step->second.at(b)), 1e-5)) << h << " step " << step->first;
    }
  }
  ASSERT_EQ(j["bolts"]["each"].size(), 8u);
  bool any_tension = false, any_compression = false;
  for (int b = 0; b < 8; ++b) {
    const nlohmann::json& e = j["bolts"]["each"][b];
    EXPECT_EQ(e["name"], "bolt_0" + std::to_string(b));
    EXPECT_FALSE(e.contains("peak_force_N")) << "the strip-based figure is gone";
    const double kn = e["max_axial_force_kN_per_bar"].get<double>();
    const Table final_profile = read_csv(out / e["file"].get<std::string>());
    EXPECT_TRUE(near(kn, largest(final_profile), 1e-5)) << e;
    EXPECT_TRUE(near(kn, history.back().at(e["name"].get<std::string>() + "_max_axial_kN"), 1e-9));
    int worst = 0;
    for (const auto& s : final_profile) worst = std::max(worst, int(s.at("state")));
    EXPECT_EQ(e["yielded"].get<bool>(), worst >= 1);
    EXPECT_EQ(e["broken"].get<bool>(), worst == 2);
    // Tension and compression apart, from the same profile; the tension's
    // stress over the default steel (fy 400, fu 500 MPa, restart_support.toml).
    double tension = 0, compression = 0, stress = 0;
    for (const auto& s : final_profile) {
      if (s.at("axial_force_kN") > tension)
        tension = s.at("axial_force_kN"), stress = s.at("steel_stress_MPa");
      compression = std::max(compression, -s.at("axial_force_kN"));
    }
    EXPECT_TRUE(near(e["max_tension_kN_per_bar"].get<double>(), tension, 1e-5)) << e;
    EXPECT_TRUE(near(e["max_compression_kN_per_bar"].get<double>(), compression, 1e-5)) << e;
    EXPECT_TRUE(near(kn, kn > 0 ? tension : -compression, 1e-5)) << e;
    EXPECT_TRUE(near(e["tension_over_yield"].get<double>(), stress / 400, 1e-5)) << e;
    EXPECT_TRUE(near(e["tension_over_ultimate"].get<double>(), stress / 500, 1e-5)) << e;
    EXPECT_EQ(e["first_broken_station_m"].is_null(), worst < 2) << e;
    any_tension |= kn > 1;
    any_compression |= kn < -1;
  }
  EXPECT_TRUE(any_tension || any_compression) << "the bolts carry load";
  // Frames: fdem_0000 is the hand-off, before the bolts; each later one has its bolts.
  const std::string pvd = read_text(out / "bolts.pvd");
  for (int f = 1; fs::exists(out / ("fdem_000" + std::to_string(f) + ".vtu")); ++f) {
    const std::string name = "bolts_000" + std::to_string(f) + ".vtp";
    EXPECT_TRUE(fs::exists(out / name)) << name;
    EXPECT_NE(pvd.find(name), std::string::npos) << name;
  }
  EXPECT_FALSE(fs::exists(out / "bolts_0000.vtp"));
  fs::remove_all(out);
}
