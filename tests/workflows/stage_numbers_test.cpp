// One stage numbering in every file (docs/workflow.md, "Monitors and
// results"): grout_trigger.toml lists insitu, remove_core, equilibrium,
// bolts and grout as stages[0..4]; its run must number them so in
// history.csv's and bolts.csv's `stage` column, in summary.json's
// `history_stages` and `fdem.stages[].stage`, and in report.md's stage table.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

// The first column of a CSV file's rows, as integers.
std::set<int> first_column(const fs::path& csv, const std::string& name) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  std::vector<std::string> cols;
  for (std::string c; std::getline(header, c, ',');) cols.push_back(c);
  const std::size_t at = std::size_t(std::find(cols.begin(), cols.end(), name) - cols.begin());
  EXPECT_LT(at, cols.size()) << csv << " has no column " << name;
  std::set<int> out;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<std::string> values;
    for (std::string v; std::getline(row, v, ',');) values.push_back(v);
    out.insert(std::stoi(values.at(at)));
  }
  return out;
}

}  // namespace

TEST(StageNumbers, history_summary_report_and_bolts_number_stages_as_the_scene_lists_them) {
  const fs::path out = scratch("stage-numbers");
  const Result r = run("run " + kTestDir + "/grout_trigger.toml -q -j 1 -o " + out.string() +
                       " --set stages[4].trigger_steps=20");
  ASSERT_TRUE(r.code == 0 || r.code == 4) << r.output;  // 4: not at equilibrium
  const std::vector<std::string> kinds = {"insitu", "remove_core", "equilibrium", "bolts", "grout"};
  const nlohmann::json j = read_json(out / "summary.json");
  EXPECT_EQ(j.at("format_version").get<int>(), 3);
  EXPECT_EQ(j.at("history_stages").get<std::vector<std::string>>(), kinds);
  int n = 0;
  for (const nlohmann::json& st : j.at("fdem").at("stages")) {
    ++n;
    const int number = st.at("stage").get<int>();
    EXPECT_EQ(number, n) << st.at("kind");
    EXPECT_EQ(st.at("kind").get<std::string>(), kinds.at(std::size_t(number)));
  }
  EXPECT_EQ(n, 4);
  // Rows come from the stages that stepped: the hand-off (0), the
  // equilibrium stage's 8 steps (2) and the grout stage (4).
  EXPECT_EQ(first_column(out / "history.csv", "stage"), (std::set<int>{0, 2, 4}));
  // The bolts go in at stage 3 and are first read by the grout stage.
  EXPECT_EQ(first_column(out / "bolts.csv", "stage"), (std::set<int>{4}));
  const std::string md = read_text(out / "report.md");
  for (std::size_t i = 1; i < kinds.size(); ++i) {
    const std::string row = "| " + std::to_string(i) + " | " + kinds[i] + " |";
    EXPECT_NE(md.find(row), std::string::npos) << row << "\n" << md;
  }
  EXPECT_NE(md.find("| 0 | insitu: hand-off step"), std::string::npos) << md;
  fs::remove_all(out);
}
