// Jointed rock through the workflow: the scene's joint sets and DFN file
// (deterministic, refused with one message naming file, key, value and what
// is allowed), and a run that gives the joints' crack elements their law,
// counts them apart and flags them in the VTK files, bit for bit with any
// thread count.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/plots/plot.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using namespace rockfdem::workflows;
using rockfdem::test::error_of;
using rockfdem::test::has;

namespace {

const std::string kScene = std::string(ROCKFDEM_TEST_DIR) + "/jointed_circular.toml";

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json summary_of(const fs::path& dir) {
  return nlohmann::json::parse(text_of(dir / "summary.json"));
}

bool same_traces(const Scene& a, const Scene& b) {
  return a.mesh.joints.size() == b.mesh.joints.size() &&
         std::memcmp(a.mesh.joints.data(), b.mesh.joints.data(),
                     a.mesh.joints.size() * sizeof(mesh::JointTrace)) == 0;
}

}  // namespace

TEST(JointScene, same_seed_gives_the_same_traces_and_another_seed_others) {
  const Scene a = load_scene(kScene), b = load_scene(kScene);
  const Scene c = load_scene(kScene, {"joints.seed=4"});
  EXPECT_EQ(a.joints.sets.size(), 2u);
  EXPECT_EQ(a.joints.dfn_traces, 3);
  EXPECT_EQ(long(a.mesh.joints.size()), a.joints.set_traces + a.joints.dfn_traces);
  EXPECT_TRUE(same_traces(a, b));
  EXPECT_FALSE(same_traces(a, c));
}

// Each refusal names the file, the key, the value and what is allowed.
TEST(JointScene, bad_joint_input_is_refused_naming_file_key_value_and_allowed) {
  const auto refused = [](std::initializer_list<std::string> sets) {
    return error_of([&] { load_scene(kScene, sets); });
  };
  const std::string residual = refused({"joints.residual_friction_angle=35"});
  EXPECT_TRUE(has(residual, "joints.residual_friction_angle") && has(residual, "35") &&
              has(residual, "allowed"))
      << residual;
  const std::string spacing = refused({"joint_set[0].spacing=0.2"});
  EXPECT_TRUE(has(spacing, "joint_set[0].spacing") && has(spacing, "0.2") &&
              has(spacing, "allowed: >= mesh.size_near"))
      << spacing;
  const std::string missing = refused({"joints.dfn_file=\"nowhere.csv\""});
  EXPECT_TRUE(has(missing, "nowhere.csv") && has(missing, "joints.dfn_file") &&
              has(missing, "allowed"))
      << missing;
  const fs::path bad = rockfdem::test::scratch("bad-dfn");
  fs::create_directories(bad);
  std::ofstream(bad / "dfn.csv") << "x0,y0,x1,y1\n1,2,3,4\n1,2,3,4m\n";
  const std::string value = refused({"joints.dfn_file=\"" + (bad / "dfn.csv").string() + "\""});
  EXPECT_TRUE(has(value, "dfn.csv:3") && has(value, "4m") && has(value, "joints.dfn_file") &&
              has(value, "allowed: four finite numbers"))
      << value;
  fs::remove_all(bad);
  const rockfdem::test::Result r =
      rockfdem::test::run("check " + kScene + " --set joint_set[1].dip=180");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "joint_set[1].dip") && has(r.output, "allowed")) << r.output;
}

// 200 steps: the joints' elements take the joint law (they soften and slide,
// never break), are counted apart, flagged in the VTK file and listed per
// trace in joints.csv; 1 and 2 threads give the same bits.
TEST(JointScene, a_run_counts_joint_elements_apart_with_the_same_bits_on_1_and_2_threads) {
  const fs::path one = rockfdem::test::scratch("joints-1"),
                 two = rockfdem::test::scratch("joints-2");
  for (const auto& [dir, threads] : {std::pair{one, 1}, std::pair{two, 2}}) {
    const rockfdem::test::Result r =
        rockfdem::test::run("run " + kScene + " -q -j " + std::to_string(threads) +
                            " --set output.plots=false -o " + dir.string());
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const nlohmann::json s = summary_of(one);
  EXPECT_EQ(s["state_hash"], summary_of(two)["state_hash"]);
  const nlohmann::json& j = s["joints"];
  EXPECT_EQ(j["traces"]["from_file"], 3);
  EXPECT_GT(j["elements"].get<long>(), 50);
  EXPECT_GT(j["yielding"].get<long>() + j["residual"].get<long>(), 0);
  // Joint elements never break: every broken element is the rock's.
  EXPECT_EQ(s["broken_zone"]["broken_rock_cracks"].get<long>(),
            s["broken"]["mode_I"].get<long>() + s["broken"]["mode_II"].get<long>() +
                s["broken"]["mixed"].get<long>());
  const std::string csv = text_of(one / "joints.csv");
  EXPECT_EQ(long(std::count(csv.begin(), csv.end(), '\n')), j["traces"]["meshed"].get<long>() + 1);
  EXPECT_TRUE(has(text_of(one / "fdem_0001.vtu"), "Name=\"joint\""));
  EXPECT_TRUE(has(text_of(one / "report.md"), "joint crack elements"));
  fs::remove_all(one);
  fs::remove_all(two);
}

// The joints in the pictures: `rockfdem mesh` draws the traces as meshed
// in purple in preview.png (a scene without joints has none of it), and a
// run's final_mesh.png and displacement.png draw the joint elements by
// state, in colours the rock's cracks do not take: intact lavender,
// sliding purple, opened cyan, the states summary.json counts.
TEST(JointScene, pictures_draw_the_joints_by_state_and_the_preview_their_traces) {
  if (std::string(ROCKFDEM_XVFB_RUN).empty()) GTEST_SKIP() << "xvfb-run is not installed";
  const std::string xvfb =
      std::string(ROCKFDEM_XVFB_RUN) + " -n " + std::to_string(100 + getpid() % 800) + " -a ";
  const fs::path jointed = rockfdem::test::scratch("joints-pictures"),
                 plain = rockfdem::test::scratch("joints-pictures-plain");
  const std::string plots = " -q -j 1 --set output.plots=true --set output.vtk=false -o ";
  rockfdem::test::Result r = rockfdem::test::run("mesh " + kScene + plots + jointed.string(), xvfb);
  ASSERT_EQ(r.code, 0) << r.output;
  r = rockfdem::test::run(
      "mesh " + std::string(ROCKFDEM_TEST_DIR) + "/good_circular.toml" + plots + plain.string(),
      xvfb);
  ASSERT_EQ(r.code, 0) << r.output;
  const std::array<int, 3> purple{115, 0, 179}, lavender{158, 133, 209}, cyan{0, 191, 217};
  using rockfdem::plots::read_png_pixels;
  // Over 50 m of traces in the window, 2 px wide at about 30 px/m.
  EXPECT_GT(read_png_pixels((jointed / "preview.png").string()).count(purple), 1000);
  EXPECT_LT(read_png_pixels((plain / "preview.png").string()).count(purple), 20);
  r = rockfdem::test::run("run " + kScene + plots + jointed.string() + " --force", xvfb);
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = summary_of(jointed)["joints"];
  for (const char* png : {"final_mesh.png", "displacement.png"}) {
    const rockfdem::plots::PngPixels p = read_png_pixels((jointed / png).string());
    // Each state drawn where the summary counts elements in it (an
    // element's 0.2-0.4 m is 10 px or more); the legend's strokes alone
    // are about 150 px each.
    const long sliding = j["yielding"].get<long>() + j["residual"].get<long>();
    EXPECT_GT(p.count(purple), sliding > 0 ? 300 : 0) << png;
    EXPECT_GT(p.count(lavender) + p.count(purple) + p.count(cyan), 1000) << png;
  }
  fs::remove_all(jointed);
  fs::remove_all(plain);
}
