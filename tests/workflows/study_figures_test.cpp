// What a sweep's table takes from each tunnel run's summary.json
// (study/study_figures.hpp): the support and damage columns from a
// constructed summary, and their absence where the summary has none.
#include "study/study_figures.hpp"

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace study = rockfdem::workflows::study;

namespace {

nlohmann::json tunnel_summary() {
  nlohmann::json bolts = nlohmann::json::array();
  bolts.push_back({{"max_tension_kN_per_bar", 76.7}, {"broken", false}});
  bolts.push_back({{"max_tension_kN_per_bar", 80.8}, {"broken", true}});
  bolts.push_back({{"max_tension_kN_per_bar", 12.0}, {"broken", true}});
  return {{"monitors", {{"vault", {{"radial_mm", 48.6}, {"explicit_share", 0.57}}}}},
          {"broken_zone",
           {{"depth_m", 5.99},
            {"along_rays",
             {{"vault", {{"depth_m", 0.5}, {"broken_or_grouted_depth_m", 3.1}}},
              {"left_wall", {{"depth_m", 0.0}, {"broken_or_grouted_depth_m", 0.84}}},
              {"invert", {{"depth_m", 3.5}, {"broken_or_grouted_depth_m", 4.4}}}}}}},
          {"lining", {{"min_safety_factor", 0.56}}},
          {"bolts", {{"each", bolts}}},
          {"support", {{"verdict", "overstressed"}}},
          {"broken", {{"mode_I", 15}, {"mode_II", 1918}, {"mixed", 67}}}};
}

}  // namespace

// Each support column is the summary's figure: the largest bolt tension
// of all bars, the count of bars with broken steel.
TEST(StudyFigures, a_tunnel_runs_support_and_damage_become_columns) {
  const nlohmann::json f = study::key_figures(tunnel_summary());
  EXPECT_DOUBLE_EQ(f.at("vault_explicit_share").get<double>(), 0.57);
  EXPECT_DOUBLE_EQ(f.at("broken_depth_m").get<double>(), 5.99);
  // The least ray's zone broken at some time, not its depth broken now.
  EXPECT_DOUBLE_EQ(f.at("damaged_depth_least_ray_m").get<double>(), 0.84);
  EXPECT_DOUBLE_EQ(f.at("lining_min_safety_factor").get<double>(), 0.56);
  EXPECT_DOUBLE_EQ(f.at("max_bolt_tension_kN_per_bar").get<double>(), 80.8);
  EXPECT_EQ(f.at("bolts_with_broken_steel").get<long>(), 2);
  EXPECT_EQ(f.at("support_verdict").get<std::string>(), "overstressed");
  EXPECT_DOUBLE_EQ(f.at("vault_radial_mm").get<double>(), 48.6);
}

// An unsupported, unlined run: no support columns rather than zeros.
TEST(StudyFigures, a_run_without_support_has_no_support_columns) {
  nlohmann::json s = tunnel_summary();
  for (const char* k : {"lining", "bolts", "support"}) s.erase(k);
  const nlohmann::json f = study::key_figures(s);
  for (const char* c : {"lining_min_safety_factor", "max_bolt_tension_kN_per_bar",
                        "bolts_with_broken_steel", "support_verdict"})
    EXPECT_FALSE(f.contains(c)) << c;
  EXPECT_TRUE(f.contains("broken_depth_m"));
}

// calibrate --help names every target calibrate accepts, for a tunnel and
// for a specimen, and its example is a specimen that reaches its peak.
TEST(StudyFigures, calibrate_help_lists_every_target_name) {
  namespace test = rockfdem::test;
  const test::Result r = test::run("calibrate --help");
  ASSERT_EQ(r.code, 0) << r.output;
  // Boost wraps long option texts, within words too: search without spaces.
  std::string help;
  for (const char c : r.output)
    if (c != '\n' && c != ' ') help.push_back(c);
  for (const char* scene :
       {"/scenes/tunnel-seed.toml", "/scenes/brazilian-disc.toml", "/scenes/ucs-33k.toml"}) {
    const rockfdem::workflows::Scene s =
        rockfdem::workflows::load_scene(std::string(ROCKFDEM_SOURCE_DIR) + scene);
    for (const study::TargetName& t : study::target_names(s)) {
      const std::string suffix = "_since_support";
      const bool composed =
          t.name.size() > suffix.size() &&
          t.name.compare(t.name.size() - suffix.size(), suffix.size(), suffix) == 0;
      const std::string base = composed ? t.name.substr(0, t.name.size() - suffix.size()) : t.name;
      EXPECT_NE(help.find(base), std::string::npos) << t.name << " in\n" << r.output;
    }
  }
  EXPECT_NE(help.find("with_since_support"), std::string::npos) << r.output;
  EXPECT_NE(help.find("calibratescenes/brazilian-disc.toml--targettensile_strength="),
            std::string::npos)
      << r.output;
}

// The shoulders as monitoring reads them: each one's survey_mm (horizontal
// convergence) becomes its column, and their mean the pair's.
TEST(StudyFigures, the_shoulders_horizontal_convergence_becomes_columns) {
  nlohmann::json s = tunnel_summary();
  s["monitors"]["left_shoulder"] = {{"radial_mm", 247.0}, {"survey_mm", 215.9}};
  s["monitors"]["right_shoulder"] = {{"radial_mm", 234.1}, {"survey_mm", 193.1}};
  const nlohmann::json f = study::key_figures(s);
  EXPECT_DOUBLE_EQ(f.at("left_shoulder_horizontal_mm").get<double>(), 215.9);
  EXPECT_DOUBLE_EQ(f.at("right_shoulder_horizontal_mm").get<double>(), 193.1);
  EXPECT_DOUBLE_EQ(f.at("shoulders_horizontal_mm").get<double>(), (215.9 + 193.1) / 2);
  EXPECT_DOUBLE_EQ(f.at("shoulders_radial_mm").get<double>(), (247.0 + 234.1) / 2);
}
