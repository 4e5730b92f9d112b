// Scene files: the schema, defaults, cross-key checks, --set overrides and
// the corpus of malformed scenes (each must be refused naming its key).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using namespace rockfdem::workflows;
using rockfdem::test::error_of;

namespace {

const std::string kTestDir = ROCKFDEM_TEST_DIR;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every one of `parts` is in `msg`.
void expect_contains(const std::string& msg, std::initializer_list<std::string> parts) {
  for (const std::string& p : parts)
    EXPECT_NE(msg.find(p), std::string::npos) << p << " in: " << msg;
}

}  // namespace

TEST(Scene, good_scene_fills_defaults) {
  const Scene s = load_scene(kTestDir + "/good_circular.toml");
  EXPECT_EQ(s.mesh.kind, mesh::ModelKind::kTunnel);
  EXPECT_EQ(s.mesh.tunnel.shape, mesh::TunnelShape::kCircular);
  EXPECT_DOUBLE_EQ(s.mesh.tunnel.radius, 3.0);
  EXPECT_EQ(s.mesh.size.algorithm, 5);
  EXPECT_DOUBLE_EQ(s.materials.at(mesh::kRock).density, 2700.0);
  // The core inherits the rock's properties when not given.
  EXPECT_DOUBLE_EQ(s.materials.at(mesh::kCore).young, 5.0e9);
  EXPECT_EQ(s.materials.count(mesh::kLining), 0u);
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
  EXPECT_EQ(s.materials.count(mesh::kLining), 1u);
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
  const Scene rect =
      load_scene(good, {"tunnel.shape=rectangular", "tunnel.span=6", "tunnel.height=5"});
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
  EXPECT_NE(choice.find("--set engine.mass_scaling=maybe: not one of the choices"),
            std::string::npos)
      << choice;
  EXPECT_NE(choice.find("allowed: one of \"auto\", \"on\", \"off\""), std::string::npos) << choice;
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
  const std::string seed = rockfdem::test::kSeedScene;
  const Scene s = load_scene(seed, {"stages[9].max_steps=123"});
  EXPECT_EQ(s.stages.back().kind, "equilibrium");
  EXPECT_EQ(s.stages.back().max_steps, 123);
  const std::string msg = error_of([&] { load_scene(seed, {"stages[10].max_steps=5"}); });
  EXPECT_NE(msg.find("stages[10]"), std::string::npos) << msg;
}

// A --set value is cited as the command-line override, never as a line of
// the scene file (its TOML was parsed from the command line), and a choice
// inside a table lists its choices.
TEST(Scene, override_inside_a_table_is_cited_as_set_with_its_choices) {
  const std::string good = kTestDir + "/good_circular.toml";
  const std::string msg = error_of([&] { load_scene(good, {"msh.zones={ rock = \"granite\" }"}); });
  expect_contains(msg, {"key 'msh.zones.rock' = \"granite\"",
                        "allowed: one of \"rock\", \"core\", \"lining\""});
  EXPECT_EQ(msg.find("--set msh.zones={ rock = \"granite\" }: "), 0u) << msg;
}

// Numbers in messages are the shortest text that reads back (8.8, not
// 8.8000000000000007), and a check between two keys names the one the user
// changed with --set: the seed tunnel widened to 200 m blames the span.
TEST(Scene, cross_key_errors_name_the_changed_key_with_short_numbers) {
  const std::string seed = rockfdem::test::kSeedScene;
  expect_contains(error_of([&] { load_scene(seed, {"tunnel.span=200"}); }),
                  {"--set tunnel.span=200: ", "tunnel.height = 8.8 m", "allowed: at most 17.6 m"});
  expect_contains(error_of([&] { load_scene(seed, {"tunnel.height=5"}); }),
                  {"--set tunnel.height=5: ", "span/2", "allowed: at least 5.65 m"});
  // From the file, the key the check is about is named, with its value as written.
  std::string text = read_file(seed);
  text.replace(text.find("span = 11.3"), 11, "span = 20.0");
  const std::string file = error_of([&] { parse_scene(text, "wide.toml", "."); });
  EXPECT_NE(file.find("key 'tunnel.height' = 8.8:"), std::string::npos) << file;
  EXPECT_EQ(file.find("00000"), std::string::npos) << file;
  expect_contains(error_of([&] { load_scene(seed, {"mesh.size_near=9"}); }),
                  {"--set mesh.size_near=9: must be at most mesh.size_far = 5 m"});
  // The fracture zone pushes the opening out of the domain: it is named,
  // and round numbers print plainly (40, not 4e+01).
  expect_contains(error_of([&] { load_scene(seed, {"tunnel.fracture_zone=40"}); }),
                  {"--set tunnel.fracture_zone=40: ", "fracture zone 40 m", "(width 80 m)"});
  // A curved invert leaves the walls a length and the lining a core.
  expect_contains(
      error_of([&] { load_scene(seed, {"tunnel.invert_rise=3.5"}); }),
      {"--set tunnel.invert_rise=3.5: ", "arch's rise (5.65 m)", "allowed: at most 3.15 m"});
  expect_contains(error_of([&] { load_scene(seed, {"tunnel.invert_rise=0.1"}); }),
                  {"--set tunnel.invert_rise=0.1: ", "lining thickness 0.2 m"});
  expect_contains(
      error_of([&] {
        load_scene(seed, {"tunnel.shape=circular", "tunnel.radius=5", "tunnel.invert_rise=1"});
      }),
      {"tunnel.invert_rise", "horseshoe and arched openings only"});
  // The ring's floor part: where there is a floor and a ring, thinner than
  // a curved invert's rise, with a material only where it can act.
  expect_contains(
      error_of([&] {
        load_scene(seed, {"tunnel.shape=circular", "tunnel.radius=5", "tunnel.invert_rise=0"});
      }),
      {"key 'tunnel.invert_thickness' = 1", "horseshoe or arched", "allowed here: "});
  expect_contains(error_of([&] {
                    load_scene(seed, {"tunnel.invert_rise=1", "tunnel.invert_thickness=1"});
                  }),
                  {"tunnel.invert_thickness", "below tunnel.invert_rise (1 m)"});
  expect_contains(error_of([&] {
                    load_scene(seed, {"tunnel.invert_rise=0", "tunnel.invert_thickness=4"});
                  }),
                  {"tunnel.invert_thickness", "leaves no wall"});
  expect_contains(error_of([&] {
                    load_scene(seed, {"materials.invert.young=3e10", "insitu.lining_active=true"});
                  }),
                  {"insitu.lining_active", "materials.lining alone"});
  expect_contains(error_of([&] {
                    load_scene(seed, {"tunnel.lining_thickness=0", "tunnel.invert_thickness=0"});
                  }),
                  {"materials.invert", "tunnel.lining_thickness > 0"});
}

// Gravity and the in-situ gradient are one choice (scene_build.cpp,
// relate_gravity): the gradient left out is rho g, one given must be rho g,
// and the sides need their rollers.
TEST(Scene, gravity_takes_the_in_situ_gradient_from_the_rock_density) {
  const std::string seed = rockfdem::test::kSeedScene;
  // A round density for round figures in the messages.
  const std::string rho = "materials.rock.density=2500", g = "engine.gravity=9.81";
  const Scene s = load_scene(seed, {rho, g});
  EXPECT_DOUBLE_EQ(s.insitu.unit_weight, 2500.0 * 9.81);
  EXPECT_EQ(load_scene(seed, {}).insitu.unit_weight, 0.0);
  EXPECT_DOUBLE_EQ(load_scene(seed, {rho, g, "insitu.unit_weight=24525"}).insitu.unit_weight,
                   24525.0);
  expect_contains(error_of([&] {
                    load_scene(seed, {rho, g, "insitu.unit_weight=27000"});
                  }),
                  {"--set insitu.unit_weight=27000: ", "= 24525 N/m^3"});
  expect_contains(error_of([&] {
                    load_scene(seed, {rho, g, "insitu.rollers=false"});
                  }),
                  {"--set insitu.rollers=false: ", "gravity needs the rollers"});
  expect_contains(error_of([&] {
                    load_scene(seed, {rho, g, "insitu.angle=10"});
                  }),
                  {"--set insitu.angle=10: ", "angle 0"});
}

// The reference's default stage list is the one the reader builds: a
// tunnel with a ring and bolts and no [[stages]] gets lining, bolts,
// remove_core, equilibrium; a ring active in the implicit stage is not
// installed again. A specimen's one stage is load_platens, for engine.steps.
TEST(Scene, default_stage_list_is_the_documented_one) {
  std::string text = read_file(rockfdem::test::kSeedScene);
  text = text.substr(0, text.find("[[stages]]"));
  // The implicit stage solves the ring with one material: no floor part of its own.
  const auto invert = text.find("\n[materials.invert]");
  text.erase(invert, text.find("\n[insitu]") - invert);
  const auto kinds = [](const Scene& s) {
    std::string out;
    for (const StageSpec& st : s.stages) out += (out.empty() ? "" : ", ") + st.kind;
    return out;
  };
  EXPECT_EQ(kinds(parse_scene(text, "seed", ".")), "lining, bolts, remove_core, equilibrium");
  EXPECT_EQ(kinds(parse_scene(text, "seed", ".", {"insitu.lining_active=true"})),
            "bolts, remove_core, equilibrium");
  const KeySpec* kind = find_key("stages[].kind");
  ASSERT_NE(kind, nullptr);
  EXPECT_NE(kind->description.find("Without [[stages]]: insitu, lining (if the model has a ring "
                                   "not already active in the implicit stage), bolts (if the "
                                   "scene has any), remove_core, equilibrium; UCS and "
                                   "Brazilian specimens (which take no [[stages]]): "
                                   "load_platens."),
            std::string::npos)
      << kind->description;
  for (const char* scene : {"ucs-33k", "brazilian-disc"}) {
    const Scene s = load_scene(std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/" + scene + ".toml");
    EXPECT_EQ(kinds(s), "load_platens") << scene;
    EXPECT_EQ(s.stages.front().max_steps, s.engine.steps) << scene;
    EXPECT_EQ(s.stages.front().every_steps, s.output.every_steps) << scene;
  }
}

// Each section of the reference appears once (the bolt tables did twice).
TEST(Scene, reference_lists_each_section_once) {
  const std::string md = scene_reference_markdown();
  std::set<std::string> seen;
  for (std::size_t at = md.find("\n## ["); at != std::string::npos;
       at = md.find("\n## [", at + 1)) {
    const std::string header = md.substr(at + 1, md.find('\n', at + 1) - at - 1);
    EXPECT_TRUE(seen.insert(header).second) << header << " twice";
  }
  EXPECT_GE(seen.size(), 20u);
}

// The documented range is the checked one: the implicit stage needs
// compression, so 0 is refused for a tunnel and documented as such; a
// specimen (which has no in-situ stress) needs neither key. A specimen has
// no default element size: the reference says so and the reader asks for it.
TEST(Scene, documented_defaults_and_ranges_are_the_checked_ones) {
  for (const char* key : {"insitu.sigma_h", "insitu.sigma_v"}) {
    const KeySpec* k = find_key(key);
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(describe_allowed(*k), "> 0 (Pa)") << key;
    expect_contains(
        error_of([&] { load_scene(kTestDir + "/good_circular.toml", {std::string(key) + "=0"}); }),
        {key, "> 0 (Pa)"});
  }
  EXPECT_NO_THROW(load_scene(kTestDir + "/ucs_small.toml"));
  const std::string ucs =
      "[model]\nkind = \"ucs\"\n[materials.rock]\nyoung = 1e10\n"
      "poisson = 0.2\ntensile_strength = 1e6\ncohesion = 2e6\n"
      "fracture_energy_I = 10\nfracture_energy_II = 50\n";
  expect_contains(error_of([&] { parse_scene(ucs, "ucs.toml", "."); }),
                  {"missing key 'mesh.size_near'", "at most 0.025 m"});
  EXPECT_NO_THROW(parse_scene(ucs, "ucs.toml", ".", {"mesh.size_near=0.004"}));
  const KeySpec* near = find_key("mesh.size_near");
  ASSERT_NE(near, nullptr);
  EXPECT_EQ(near->default_doc, "0.5 (tunnels); specimens: required");
}

// Scene text is bounded before toml++ parses it: its parser recurses per
// dotted part and per nesting level, so a 200 KB header [a.a.a...] of 50,000
// parts overflowed the stack (SIGSEGV), and a 200-deep array in
// insitu.alpha came back as a 707-line message.
namespace {

std::string bounded_error(const std::string& text, const std::vector<std::string>& sets = {}) {
  return error_of([&] { parse_scene(text, "bounded.toml", ".", sets); });
}

std::string dotted(std::size_t n_parts) {
  std::string key = "a";
  for (std::size_t i = 1; i < n_parts; ++i) key += ".a";
  return key;
}

}  // namespace

TEST(SceneBounds, header_of_50000_dotted_parts_is_refused_before_parsing) {
  const std::string msg = bounded_error("# line 1\n[" + dotted(50000) + "]\nx = 1\n");
  expect_contains(msg, {"bounded.toml:2:", "more than 16 dotted parts", "at most 16"});
  EXPECT_LT(msg.size(), 300u) << msg;
}

TEST(SceneBounds, dotted_keys_past_16_parts_are_refused_where_they_are) {
  expect_contains(bounded_error("[model]\nkind = \"tunnel\"\n" + dotted(17) + " = 1\n"),
                  {"bounded.toml:3:", "more than 16 dotted parts"});
  expect_contains(bounded_error("x = { " + dotted(20) + " = 1 }\n"),
                  {"bounded.toml:1:", "more than 16 dotted parts"});
  // 16 parts pass the bound (and are then an unknown key).
  expect_contains(bounded_error("[" + dotted(16) + "]\n"), {"unknown key"});
  // Dots in values, strings and comments are no key parts.
  std::string good = read_file(kTestDir + "/good_circular.toml");
  good.replace(good.find("kind = \"tunnel\""), 15,
               "kind = \"tunnel\"  # " + dotted(40) + "\ntitle = '" + dotted(40) + "'");
  EXPECT_EQ(bounded_error(good), "");
}

TEST(SceneBounds, deep_nesting_is_refused_in_one_short_line) {
  const std::string deep = std::string(200, '[') + "1.0" + std::string(200, ']');
  const std::string msg = bounded_error("[insitu]\nalpha = " + deep + "\n");
  expect_contains(msg, {"bounded.toml:2:", "nest more than 32 levels", "at most 32"});
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_LT(msg.size(), 300u) << msg;
  // The same through --set.
  const std::string set =
      bounded_error(read_file(kTestDir + "/good_circular.toml"), {"insitu.alpha=" + deep});
  expect_contains(set, {"--set insitu.alpha=", "nest more than 32 levels"});
  EXPECT_LT(set.size(), 900u) << set;
  // Brackets inside strings do not count.
  expect_contains(bounded_error("[tunnel]\nshape = \"" + deep + "\"\n"),
                  {"tunnel.shape", "not one of the choices"});
}

TEST(SceneBounds, long_keys_and_large_scenes_are_refused) {
  expect_contains(bounded_error("[model]\n" + std::string(300, 'k') + " = 1\n"),
                  {"bounded.toml:2:", "longer than 256 characters", "at most 256"});
  expect_contains(bounded_error("[model]\n\"" + std::string(300, 'q') + "\" = 1\n"),
                  {"bounded.toml:2:", "longer than 256 characters"});
  std::string big = read_file(kTestDir + "/good_circular.toml");
  while (big.size() <= (1u << 20)) big += "# " + std::string(1000, 'x') + "\n";
  expect_contains(bounded_error(big), {"bounded.toml", "bytes; allowed: at most 1048576 bytes"});
}

// Keys and values from a scene are echoed with their control characters
// escaped: an ESC sequence in a key must not clear the user's terminal, a
// NUL must not cut the message short.
TEST(SceneBounds, control_characters_in_echoed_keys_and_values_are_escaped) {
  const std::string key = bounded_error("[tunnel]\n\"x\\u001b[2Jy\" = 1\n");
  expect_contains(key, {"bounded.toml:2", "x\\x1b[2Jy", "unknown key"});
  EXPECT_EQ(key.find('\x1b'), std::string::npos) << key;
  const std::string value =
      bounded_error("[tunnel]\nshape = \"c\\u001b]0;pwned\\u0007\\u0000z\"\n");
  expect_contains(value, {"tunnel.shape", "c\\x1b]0;pwned\\x07\\x00z\"", "not one of the choices"});
  EXPECT_EQ(value.find('\x1b'), std::string::npos) << value;
  EXPECT_EQ(value.find('\x07'), std::string::npos) << value;
  // A C1 control (U+009B, a CSI on some terminals) too.
  const std::string c1 = bounded_error("[tunnel]\nshape = \"\\u009b2J\"\n");
  expect_contains(c1, {"\\u009b2J"});
  EXPECT_EQ(c1.find("\xc2\x9b"), std::string::npos) << c1;
}

// A scene path that is a device (or a FIFO) is refused before anything is
// read: reading /dev/zero first never ended.
TEST(Scene, device_path_is_refused_unread) {
  try {
    load_scene("/dev/zero");
    FAIL() << "no InputError";
  } catch (const rockfdem::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}
