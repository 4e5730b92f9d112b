// Jointed rock through the workflow: the scene's joint sets and DFN file
// (deterministic, refused with one message naming file, key, value and what
// is allowed), and a run that gives the joints' crack elements their law,
// counts them apart and flags them in the VTK files, bit for bit with any
// thread count.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "outputs/joint_results.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
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

/// The fields of joint_profile.csv's row `row` (1 = the first after the header).
std::vector<std::string> profile_row(const std::string& csv, int row) {
  std::stringstream in(csv);
  std::string line;
  for (int i = 0; i <= row; ++i) std::getline(in, line);
  std::vector<std::string> f;
  std::stringstream l(line);
  for (std::string x; std::getline(l, x, ',');) f.push_back(x);
  return f;
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
  // Barton-Bandis: JCS > 0 and JRC in [0, 20] (the schema's ranges), both
  // given with it and neither without it.
  const std::string bb = "joints.shear_strength=\"barton_bandis\"";
  const std::string jcs = refused({bb, "joints.jrc=10", "joints.jcs=0"});
  EXPECT_TRUE(has(jcs, "joints.jcs") && has(jcs, "0") && has(jcs, "allowed: > 0")) << jcs;
  const std::string jrc = refused({bb, "joints.jrc=25", "joints.jcs=50e6"});
  EXPECT_TRUE(has(jrc, "joints.jrc") && has(jrc, "25") && has(jrc, "allowed") && has(jrc, "20"))
      << jrc;
  const std::string cap =
      refused({bb, "joints.jrc=10", "joints.jcs=50e6", "joints.friction_angle=80",
               "joints.residual_friction_angle=75"});
  EXPECT_TRUE(has(cap, "joints.residual_friction_angle") && has(cap, "75") &&
              has(cap, "allowed: below 70"))
      << cap;
  const std::string alone = refused({bb, "joints.jrc=10"});
  EXPECT_TRUE(has(alone, "joints.jcs") && has(alone, "allowed")) << alone;
  const std::string without = refused({"joints.jrc=10"});
  EXPECT_TRUE(has(without, "joints.jrc") && has(without, "barton_bandis") &&
              has(without, "allowed"))
      << without;
  const Scene b = load_scene(kScene, {bb, "joints.jrc=8", "joints.jcs=60e6"});
  EXPECT_TRUE(b.joints.barton_bandis);
  EXPECT_EQ(b.joints.jrc, 8);
  EXPECT_EQ(b.joints.jcs, 60e6);
  const rockfdem::test::Result bad_jrc = rockfdem::test::run(
      "check " + kScene + " --set '" + bb + "'" + " --set joints.jrc=-1 --set joints.jcs=50e6");
  EXPECT_EQ(bad_jrc.code, 2) << bad_jrc.output;
  const rockfdem::test::Result r =
      rockfdem::test::run("check " + kScene + " --set joint_set[1].dip=180");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "joint_set[1].dip") && has(r.output, "allowed")) << r.output;
}

// 200 steps: the joints' elements take the joint law (they soften and slide,
// never break), are counted apart, flagged in the VTK file, listed per
// trace in joints.csv and per element in joint_profile.csv; 1 and 2 threads
// give the same bits and the same energy ledger.
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
  // The ledger too, the joints' residual friction included (fixed-block sums).
  EXPECT_GT(s["energy"]["joint_friction"].get<double>(), 0.0);
  EXPECT_EQ(s["energy"], summary_of(two)["energy"]);
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
  const std::string profile = text_of(one / "joint_profile.csv");
  EXPECT_EQ(long(std::count(profile.begin(), profile.end(), '\n')), j["elements"].get<long>() + 1);
  // At each stage's end the same rows (the run ends with its last stage,
  // so that one's are the end's); the first stage's state is another.
  const nlohmann::json& stages = s["fdem"]["stages"];
  ASSERT_GE(stages.size(), 2u);
  std::vector<std::string> at_stage;
  for (const nlohmann::json& st : stages) {
    const fs::path file =
        one / ("joint_profile_stage_" + std::to_string(st["stage"].get<int>()) + ".csv");
    ASSERT_TRUE(fs::exists(file)) << file;
    at_stage.push_back(text_of(file));
    EXPECT_EQ(at_stage.back().substr(0, profile.find('\n')), profile.substr(0, profile.find('\n')));
    EXPECT_EQ(long(std::count(at_stage.back().begin(), at_stage.back().end(), '\n')),
              j["elements"].get<long>() + 1);
  }
  EXPECT_EQ(at_stage.back(), profile);
  EXPECT_NE(at_stage.front(), profile);
  EXPECT_TRUE(has(text_of(one / "fdem_0001.vtu"), "Name=\"joint\""));
  EXPECT_TRUE(has(text_of(one / "report.md"), "joint crack elements"));
  fs::remove_all(one);
  fs::remove_all(two);
}

// A jointed run restarts bit for bit: checkpoints every 50 steps (at the
// output steps) with 1 thread; the older kept one, restarted with 2
// threads, gives the uninterrupted run's state hash, energy ledger (the
// joints' residual friction included) and joint_profile.csv.
TEST(JointScene, a_jointed_run_restarts_bit_for_bit) {
  const fs::path ref = rockfdem::test::scratch("joints-ref"),
                 again = rockfdem::test::scratch("joints-restart");
  // Output (and so checkpoints) every 50 steps; the restart repeats the --set.
  const std::string kSets =
      " --set output.every_steps=50 --set output.plots=false --set output.vtk=false";
  rockfdem::test::Result r = rockfdem::test::run(
      "run " + kScene + " -q -j 1 --checkpoint-every 50" + kSets + " -o " + ref.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const auto kept = rockfdem::test::checkpoints(ref);
  ASSERT_FALSE(kept.empty());
  r = rockfdem::test::run("run " + kScene + " -q -j 2" + kSets + " --restart " +
                          kept.front().string() + " -o " + again.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json a = summary_of(ref), b = summary_of(again);
  EXPECT_GT(b["restarted_from"]["step"].get<long>(), 0);
  EXPECT_LT(b["restarted_from"]["step"].get<long>(), a["steps"].get<long>());
  EXPECT_EQ(b["state_hash"], a["state_hash"]);
  EXPECT_GT(a["energy"]["joint_friction"].get<double>(), 0.0);
  EXPECT_EQ(b["energy"], a["energy"]);
  EXPECT_EQ(text_of(again / "joint_profile.csv"), text_of(ref / "joint_profile.csv"));
  // Every stage's profile, those ended before the checkpoint carried over.
  for (const nlohmann::json& st : a["fdem"]["stages"]) {
    const std::string name =
        "joint_profile_stage_" + std::to_string(st["stage"].get<int>()) + ".csv";
    ASSERT_TRUE(fs::exists(again / name)) << name;
    EXPECT_EQ(text_of(again / name), text_of(ref / name)) << name;
  }
  fs::remove_all(ref);
  fs::remove_all(again);
}

// joint_profile.csv on a constructed case: two triangles joined along a
// horizontal joint of length h (one trace), the upper triangle moved by an
// imposed slip and opening; the row reports them in mm (printed to 6
// digits: 1e-5 relative), the same whichever way the trace runs, with the
// state the motion gives.
TEST(JointScene, joint_profile_reports_an_imposed_slip_and_opening) {
  const double h = 0.2;
  mesh::Mesh m;
  m.x = {0, h, h / 2, h / 2};
  m.y = {0, 0, -h, h};
  m.triangles = {{0, 2, 1}, {0, 1, 3}};
  m.zone = {mesh::kRock, mesh::kRock};
  m.fracture = {1, 1};
  m.joint_edges = {{0, 1, 0}};
  fdem::ModelInput in;
  in.x = m.x;
  in.y = m.y;
  in.triangles = m.triangles;
  in.material = {0, 0};
  in.fracture = m.fracture;
  fdem::Material joint;
  joint.crack_law = fdem::CrackLaw::kJoint;
  joint.tensile_strength = 0;
  joint.cohesion = 0.5e6;
  joint.friction_deg = 35;
  joint.residual_friction_deg = 25;
  in.materials = {joint};
  fdem::Engine e(in);
  // The upper triangle moved by (u, v) from the mesh, the lower at rest in it.
  const auto move = [&](double u, double v) {
    for (int t = 0; t < 2; ++t)
      for (int node : e.triangle_nodes(t)) {
        const int w = e.node_vertex()[node];
        e.set_node_state(node, in.x[w] + t * u, in.y[w] + t * v, 0, 0);
      }
  };
  const auto near = [](const std::string& f, double x) {
    return std::fabs(std::stod(f) - x) <= 1e-5 * std::fabs(x) + 1e-9;
  };
  for (const mesh::JointTrace t : {mesh::JointTrace{0, 0, h, 0}, mesh::JointTrace{h, 0, 0, 0}}) {
    // Slid 2.5 mm and pressed 0.01 mm down: closed (aperture 0), intact
    // (no step taken: no damage).
    move(2.5e-3, -1e-5);
    std::vector<std::string> f = profile_row(workflows::joint_profile_csv(e, m, {t}), 1);
    ASSERT_EQ(f.size(), 12u);
    EXPECT_EQ(f[0], "1");
    EXPECT_TRUE(near(f[2], h / 2)) << f[2];  // distance_m of the midpoint
    EXPECT_TRUE(near(f[6], 2.5)) << f[6];    // slip_mm
    EXPECT_TRUE(near(f[7], -0.01)) << f[7];  // opening_mm
    EXPECT_TRUE(near(f[8], 0)) << f[8];      // aperture_mm
    EXPECT_EQ(f[11], "intact");
    // Slid to -1.5 mm and lifted 0.4 mm: open.
    move(-1.5e-3, 4e-4);
    f = profile_row(workflows::joint_profile_csv(e, m, {t}), 1);
    EXPECT_TRUE(near(f[6], -1.5)) << f[6];
    EXPECT_TRUE(near(f[7], 0.4)) << f[7];
    EXPECT_TRUE(near(f[8], 0.4)) << f[8];
    EXPECT_EQ(f[11], "open");
  }
  // Closed again and slid far past the softening range (one step raises
  // the damage to 1): sliding.
  move(20e-3, -1e-5);
  e.step();
  move(20e-3, -1e-5);
  const std::vector<std::string> f =
      profile_row(workflows::joint_profile_csv(e, m, {mesh::JointTrace{0, 0, h, 0}}), 1);
  EXPECT_TRUE(near(f[6], 20)) << f[6];
  EXPECT_TRUE(near(f[10], 1)) << f[10];
  EXPECT_EQ(f[11], "sliding");
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

namespace {

/// Column `name` of a CSV text's data row `row` (1 = the first after the header).
std::string cell(const std::string& csv, int row, const std::string& name) {
  const std::vector<std::string> header = profile_row(csv, 0), values = profile_row(csv, row);
  for (std::size_t k = 0; k < header.size() && k < values.size(); ++k)
    if (header[k] == name) return values[k];
  return "";
}

/// The shipped jointed scene `name` run to its own end: its status, the
/// vault's inward displacement [mm], the largest slip and opening [mm] of
/// the joint elements above the crown (within 4 m of the axis, up to 5 m
/// above the 4.4 m crown), and the share of rock crack elements broken.
struct Crown {
  std::string status;
  double vault = 0, joint_slip = 0, joint_opening = 0, broken_share = 0;
};

Crown crown_of(const std::string& name) {
  const fs::path dir = rockfdem::test::scratch(name);
  const rockfdem::test::Result r = rockfdem::test::run(
      "run " + std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/" + name +
      ".toml -q -j 2 --set output.vtk=false --set output.plots=false -o " + dir.string());
  Crown c;
  const nlohmann::json s = summary_of(dir);
  c.status = s["status"].get<std::string>();
  if (c.status == "completed") {
    EXPECT_EQ(r.code, 0) << r.output;
  }
  c.vault = s["monitors"]["vault"]["radial_mm"].get<double>();
  long broken = 0;
  for (const auto& [mode, n] : s["broken"].items()) broken += n.get<long>();
  c.broken_share = double(broken) / s["counts"]["crack_elements"].get<double>();
  const std::string profile = text_of(dir / "joint_profile.csv");
  const auto n = long(std::count(profile.begin(), profile.end(), '\n')) - 1;
  for (int k = 1; k <= n; ++k) {
    const double x = std::stod(cell(profile, k, "x_m")), y = std::stod(cell(profile, k, "y_m"));
    if (std::fabs(x) > 4 || y < 4.3 || y > 9.4) continue;
    c.joint_slip = std::max(c.joint_slip, std::fabs(std::stod(cell(profile, k, "slip_mm"))));
    c.joint_opening = std::max(c.joint_opening, std::stod(cell(profile, k, "opening_mm")));
  }
  fs::remove_all(dir);
  return c;
}

}  // namespace

// The shipped jointed seed tunnel in a hard basalt mass, unsupported and
// bolted (arch, walls and floor), each run to its own end
// (docs/benchmarks.md, "The jointed seed tunnel"): the intact rock stays
// nearly whole (under 5% of all crack elements broken); the unsupported
// crown wedge loosens, its joints opening, and the bolts hold it: the
// bolted run completes. The unsupported wedge is at limit equilibrium:
// over seven realisations (dt_safety 0.785-0.815) it came to rest twice,
// crept to the step cap twice and flowed three times, so its status is
// not asserted; the bounds hold over every pairing of those realisations.
// Measured, bolted against unsupported: vault 6.39-6.41 against 7.48-14.14
// mm (ratio 0.86 at worst, 0.70 in the shipped run), the crown joints'
// largest opening 0.97-3.23 against 4.90-14.05 mm (0.66 at worst, 0.41).
TEST(JointScene, bolts_hold_the_jointed_crown_the_unsupported_tunnel_loosens) {
  const Crown open = crown_of("tunnel-jointed"), bolted = crown_of("tunnel-jointed-bolted");
  EXPECT_EQ(bolted.status, "completed");
  EXPECT_LT(bolted.vault, 0.9 * open.vault) << bolted.vault << " mm against " << open.vault;
  EXPECT_LT(bolted.joint_opening, 0.75 * open.joint_opening)
      << bolted.joint_opening << " mm against " << open.joint_opening;
  EXPECT_GT(open.joint_opening, 3.0);  // the wedge's joints open: a block loosening
  EXPECT_LT(open.broken_share, 0.05);
  EXPECT_LT(bolted.broken_share, 0.05);
}
