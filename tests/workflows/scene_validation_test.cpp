// Scene files: the schema, defaults, cross-key checks, --set overrides and
// the corpus of malformed scenes (each must be refused naming its key).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using namespace rockfdem::workflows;

namespace {

const std::string kTestDir = ROCKFDEM_TEST_DIR;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Scene, good_scene_fills_defaults) {
  const Scene s = load_scene(kTestDir + "/good_circular.toml");
  EXPECT_EQ(s.mesh.kind, mesh::ModelKind::kTunnel);
  EXPECT_EQ(s.mesh.tunnel.shape, mesh::TunnelShape::kCircular);
  EXPECT_DOUBLE_EQ(s.mesh.tunnel.radius, 3.0);
  EXPECT_EQ(s.mesh.size.algorithm, 6);
  EXPECT_DOUBLE_EQ(s.materials.at("rock").density, 2700.0);
  // The core inherits the rock's properties when not given.
  EXPECT_DOUBLE_EQ(s.materials.at("core").young, 5.0e9);
  EXPECT_EQ(s.materials.count("lining"), 0u);
  ASSERT_EQ(s.insitu.alpha.size(), 1u);
  EXPECT_DOUBLE_EQ(s.insitu.alpha[0], 1.0);
}

TEST(Scene, default_scene_is_the_seed_tunnel) {
  const Scene s = load_default_scene();
  EXPECT_EQ(s.source, "default");
  EXPECT_EQ(s.mesh.tunnel.shape, mesh::TunnelShape::kHorseshoe);
  EXPECT_DOUBLE_EQ(s.mesh.tunnel.span, 11.3);
  EXPECT_DOUBLE_EQ(s.mesh.tunnel.height, 8.8);
  EXPECT_DOUBLE_EQ(s.mesh.tunnel.lining_thickness, 0.2);
  EXPECT_DOUBLE_EQ(s.insitu.sigma_h, 18.2e6);
  EXPECT_DOUBLE_EQ(s.insitu.sigma_v, 11.4e6);
  EXPECT_EQ(s.materials.count("lining"), 1u);
}

TEST(Scene, shipped_scenes_are_valid) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(std::string(ROCKFDEM_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".toml") continue;
    EXPECT_NO_THROW(load_scene(entry.path().string())) << entry.path();
    ++n;
  }
  EXPECT_GE(n, 3);
}

TEST(Scene, override_changes_a_value_and_is_validated) {
  const std::string good = kTestDir + "/good_circular.toml";
  EXPECT_DOUBLE_EQ(load_scene(good, {"tunnel.radius=4.5"}).mesh.tunnel.radius, 4.5);
  // A bare word is taken as a string, so shells need no quoting.
  const Scene rect = load_scene(good, {"tunnel.shape=rectangular", "tunnel.span=6",
                                       "tunnel.height=5"});
  EXPECT_EQ(rect.mesh.tunnel.shape, mesh::TunnelShape::kRectangular);
  const std::string bad = error_of([&] { load_scene(good, {"tunnel.radius=-1"}); });
  EXPECT_NE(bad.find("--set"), std::string::npos) << bad;
  EXPECT_NE(bad.find("tunnel.radius"), std::string::npos) << bad;
  EXPECT_NE(bad.find("> 0"), std::string::npos) << bad;
  const std::string unknown = error_of([&] { load_scene(good, {"tunnel.radios=3"}); });
  EXPECT_NE(unknown.find("tunnel.radios"), std::string::npos) << unknown;
  const std::string malformed = error_of([&] { load_scene(good, {"tunnel.radius"}); });
  EXPECT_NE(malformed.find("section.key=value"), std::string::npos) << malformed;
}

TEST(Scene, error_names_file_line_key_value_and_allowed) {
  const std::string path = kTestDir + "/bad_scenes/negative_radius.toml";
  const std::string msg = error_of([&] { load_scene(path); });
  // "<file>:<line>: key 'tunnel.radius' = -3.0: out of range; allowed: > 0 (m)"
  EXPECT_NE(msg.find(path + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tunnel.radius"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("allowed: > 0 (m)"), std::string::npos) << msg;
  // A choice key lists its choices.
  const std::string choice = error_of(
      [&] { load_scene(kTestDir + "/good_circular.toml", {"engine.mass_scaling=maybe"}); });
  EXPECT_NE(choice.find("'engine.mass_scaling' = \"maybe\""), std::string::npos) << choice;
  EXPECT_NE(choice.find("allowed: one of \"auto\", \"on\", \"off\""), std::string::npos)
      << choice;
}

// Every file in bad_scenes/ starts with "# expect: TEXT"; loading it must
// throw InputError whose message holds TEXT and the file's name.
TEST(Scene, every_malformed_scene_is_refused_naming_its_key) {
  int n = 0;
  for (const auto& entry : fs::directory_iterator(kTestDir + "/bad_scenes")) {
    const std::string path = entry.path().string();
    const std::string text = read_file(path);
    const std::string expect = text.substr(10, text.find('\n') - 10);
    const std::string msg = error_of([&] { load_scene(path); });
    EXPECT_NE(msg.find(expect), std::string::npos) << path << " gave: '" << msg << "'";
    EXPECT_NE(msg.find(entry.path().filename().string()), std::string::npos) << msg;
    ++n;
  }
  EXPECT_GE(n, 30);
}

TEST(Scene, reference_doc_matches_schema) {
  const std::string doc = read_file(std::string(ROCKFDEM_SOURCE_DIR) + "/docs/scene-reference.md");
  EXPECT_EQ(doc, scene_reference_markdown())
      << "regenerate: build/bin/rockfdem --scene-reference > docs/scene-reference.md";
}

TEST(Scene, every_schema_key_has_unit_and_description) {
  for (const KeySpec& k : scene_schema()) {
    EXPECT_FALSE(k.unit.empty()) << k.path;
    EXPECT_FALSE(k.description.empty()) << k.path;
  }
}

// --set reaches into arrays of tables ("stages[2].max_steps"), and an index
// the scene does not have is an error, not a silently ignored key.
TEST(Scene, override_reaches_array_of_tables) {
  const std::string seed = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/tunnel-seed.toml";
  const Scene s = load_scene(seed, {"stages[5].max_steps=123"});
  EXPECT_EQ(s.stages.back().kind, "equilibrium");
  EXPECT_EQ(s.stages.back().max_steps, 123);
  const std::string msg = error_of([&] { load_scene(seed, {"stages[9].max_steps=5"}); });
  EXPECT_NE(msg.find("stages[9]"), std::string::npos) << msg;
}
