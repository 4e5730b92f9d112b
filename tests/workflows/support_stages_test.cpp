// The support stages' scene keys as a user sets them (docs/support.md):
// bolts.install_stress reaches the engine. The physics of each option is
// pinned in the engine's tests (BoltInstall.*); here a run with "current"
// must report the bolts stage's clipped points (only that option counts
// them) and end in another state than the same run with "free".
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

const std::string kScene = kTestDir + "/restart_support.toml";

// The run's summary.json, or fails the test with the output.
nlohmann::json run_summary(const std::string& name, const std::string& sets) {
  const fs::path out = scratch(name);
  const Result r =
      run("run " + kScene + " -q -j 1 -o " + out.string() + " --set output.vtk=false " + sets);
  EXPECT_EQ(r.code, 0) << r.output;
  nlohmann::json j = read_json(out / "summary.json");
  fs::remove_all(out);
  return j;
}

const nlohmann::json& stage_changes(const nlohmann::json& summary, const std::string& kind) {
  for (const nlohmann::json& s : summary.at("fdem").at("stages"))
    if (s.at("kind") == kind) return s.at("changes");
  throw std::runtime_error("no stage " + kind);
}

}  // namespace

TEST(SupportStages, bolts_install_stress_reaches_the_engine) {
  const nlohmann::json free = run_summary("install-free", "");
  const nlohmann::json kept = run_summary("install-current", "--set bolts.install_stress=current");
  const nlohmann::json& f = stage_changes(free, "bolts");
  const nlohmann::json& k = stage_changes(kept, "bolts");
  EXPECT_FALSE(f.contains("clipped_points")) << f;
  ASSERT_TRUE(k.contains("clipped_points")) << k;
  EXPECT_GE(k.at("clipped_points").get<long>(), 0);
  EXPECT_EQ(k.at("bolt_triangles"), f.at("bolt_triangles"));
  EXPECT_NE(kept.at("state_hash"), free.at("state_hash"));
  std::printf("free: state %s; current: state %s, %ld crack points clipped\n",
              free.at("state_hash").get<std::string>().c_str(),
              kept.at("state_hash").get<std::string>().c_str(), k.at("clipped_points").get<long>());
}
