// Joints in a user's .msh: a 1D physical group named in msh.joints marks a
// joint, whose mesh edges carry the joint law in the engine; the rest of
// the rock's crack elements keep the rock's. Joint sets and a DFN, which
// need traces meshed in, are refused for a .msh model.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/engine_setup.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using namespace rockfdem::workflows;

namespace {

// A 4 x 4 m box split at y = 0 by three lines: the middle one, (-1, 0) to
// (1, 0), in the 1D group "Fault"; the two beside it plain rock. Returns
// the number of 2-node lines gmsh meshed on the fault.
std::size_t write_faulted_box(const fs::path& file) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("faulted_box");
  namespace geo = gmsh::model::geo;
  const double h = 0.25;
  const int p1 = geo::addPoint(-2, -2, 0, h), p2 = geo::addPoint(2, -2, 0, h),
            p3 = geo::addPoint(2, 0, 0, h), p4 = geo::addPoint(2, 2, 0, h),
            p5 = geo::addPoint(-2, 2, 0, h), p6 = geo::addPoint(-2, 0, 0, h),
            p7 = geo::addPoint(-1, 0, 0, h), p8 = geo::addPoint(1, 0, 0, h);
  const int bottom = geo::addLine(p1, p2), right_low = geo::addLine(p2, p3),
            right_up = geo::addLine(p3, p4), top = geo::addLine(p4, p5),
            left_up = geo::addLine(p5, p6), left_low = geo::addLine(p6, p1),
            mid_left = geo::addLine(p6, p7), fault = geo::addLine(p7, p8),
            mid_right = geo::addLine(p8, p3);
  const int below = geo::addCurveLoop({bottom, right_low, -mid_right, -fault, -mid_left, left_low});
  const int above = geo::addCurveLoop({right_up, top, left_up, mid_left, fault, mid_right});
  const int s_below = geo::addPlaneSurface({below}), s_above = geo::addPlaneSurface({above});
  geo::synchronize();
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {s_below, s_above}), "Rock");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {bottom}), "Bottom");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {right_low, right_up}), "Right");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {top}), "Top");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {left_up, left_low}), "Left");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {fault}), "Fault");
  gmsh::model::mesh::generate(2);
  std::vector<std::size_t> lines, nodes;
  gmsh::model::mesh::getElementsByType(1, lines, nodes, fault);
  gmsh::write(file.string());
  gmsh::finalize();
  return lines.size();
}

const char* const kScene = R"([model]
kind = "msh"
[msh]
file = "box.msh"
zones = { Rock = "rock" }
edges = { Bottom = "bottom", Right = "right", Top = "top", Left = "left" }
joints = ["Fault"]
[materials.rock]
young = 10.0e9
poisson = 0.25
tensile_strength = 2.0e6
cohesion = 4.0e6
fracture_energy_I = 100.0
fracture_energy_II = 500.0
[joints]
cohesion = 0.1e6
friction_angle = 30.0
residual_friction_angle = 25.0
[insitu]
sigma_h = 1.0e6
sigma_v = 1.0e6
)";

fs::path faulted_box_scene(const fs::path& dir, std::size_t* fault_lines) {
  fs::create_directories(dir);
  const std::size_t n = write_faulted_box(dir / "box.msh");
  if (fault_lines) *fault_lines = n;
  std::ofstream(dir / "scene.toml") << kScene;
  return dir / "scene.toml";
}

}  // namespace

// The fault's lines become joint edges, one trace from (-1, 0) to (1, 0):
// as many as gmsh meshed on the curve, their lengths adding up to the
// trace's 2 m within 0.1% (a straight line: round-off). In the engine the
// crack elements on them take the joint law: the upper half of the box
// slid 20 mm along y = 0 in one step, every fault element slides at its
// residual friction (damage 1) without breaking, as a joint does, while
// the rock's elements on the same line beside it break in shear.
TEST(MshJoints, a_joint_group_gives_its_edges_the_joint_law) {
  const fs::path dir = rockfdem::test::scratch("msh-joints");
  std::size_t fault_lines = 0;
  const Scene scene = load_scene(faulted_box_scene(dir, &fault_lines).string());
  ASSERT_GT(fault_lines, 4u);
  mesh::MeshReport report;
  const mesh::Mesh m = mesh::build_mesh(scene.mesh, &report);
  ASSERT_EQ(m.joint_edges.size(), fault_lines);
  ASSERT_EQ(report.joint_traces.size(), 1u);
  const mesh::JointTrace& t = report.joint_traces[0];
  EXPECT_NEAR(std::fabs(t.x1 - t.x0), 2.0, 1e-12);
  EXPECT_NEAR(t.y0, 0.0, 1e-12);
  EXPECT_NEAR(t.y1, 0.0, 1e-12);
  double length = 0;
  for (const mesh::JointEdge& e : m.joint_edges) {
    EXPECT_EQ(e.trace, 0);
    length += std::hypot(m.x[e.b] - m.x[e.a], m.y[e.b] - m.y[e.a]);
  }
  EXPECT_NEAR(length, 2.0, 2.0 * 1e-3);
  EXPECT_EQ(report.joints.kept, 1);

  // The engine as a run sets it up, from a hand-off at rest.
  insitu::InsituField rest;
  rest.alpha = 1;
  rest.stress.assign(m.n_triangles(), {});
  rest.active.assign(m.n_triangles(), 1);
  rest.ux.assign(m.n_vertices(), 0);
  rest.uy.assign(m.n_vertices(), 0);
  fdem::Engine e = setup_engine(scene, m, rest, 1, false).engine;
  e.step();  // the first step sets the cracks' pre-stress from the state at rest
  const std::vector<int>& vertex = e.node_vertex();
  for (std::size_t tri = 0; tri < e.n_triangles(); ++tri) {
    const auto nodes = e.triangle_nodes(tri);
    double cy = 0;
    for (int node : nodes) cy += m.y[std::size_t(vertex[node])] / 3;
    const double slide = cy > 0 ? 20e-3 : 0.0;
    for (int node : nodes) {
      const auto w = std::size_t(vertex[node]);
      e.set_node_state(node, m.x[w] + slide, m.y[w], 0, 0);
    }
  }
  e.step();
  std::size_t joints = 0, rock_on_line = 0;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto n = e.crack_nodes(c);
    const auto a = std::size_t(vertex[n[0]]), b = std::size_t(vertex[n[1]]);
    if (std::fabs(m.y[a]) > 1e-12 || std::fabs(m.y[b]) > 1e-12) continue;
    const bool on_fault = std::fabs(m.x[a]) <= 1 + 1e-12 && std::fabs(m.x[b]) <= 1 + 1e-12;
    if (on_fault) {
      ++joints;
      EXPECT_EQ(e.crack_damage(c), 1.0) << "fault element " << c;
      EXPECT_NE(e.crack_state(c), fdem::CrackState::kBroken) << "fault element " << c;
    } else {
      ++rock_on_line;
      EXPECT_EQ(e.crack_state(c), fdem::CrackState::kBroken) << "rock element " << c;
    }
  }
  EXPECT_EQ(joints, fault_lines);
  EXPECT_GT(rock_on_line, 4u);
  fs::remove_all(dir);
}

// Joints the scene would mesh in (sets, a DFN file) cannot enter a user's
// mesh, and a joint material without joint lines acts nowhere: refused,
// naming the file and key. A group that is not in the file is refused
// naming it and the file's groups.
TEST(MshJoints, sets_a_dfn_and_missing_groups_are_refused) {
  const fs::path dir = rockfdem::test::scratch("msh-joints-refused");
  const std::string scene = faulted_box_scene(dir, nullptr).string();
  const auto refused = [&](const std::string& text) {
    return rockfdem::test::error_of([&] { parse_scene(text, "scene.toml", dir.string()); });
  };
  std::string why = refused(std::string(kScene) + "[[joint_set]]\ndip = 60.0\nspacing = 1.0\n");
  EXPECT_TRUE(rockfdem::test::has(why, "scene.toml")) << why;
  EXPECT_TRUE(rockfdem::test::has(why, "'joint_set'")) << why;
  EXPECT_TRUE(rockfdem::test::has(why, "msh.joints")) << why;
  std::string text = kScene;
  text.replace(text.find("[joints]\n"), 9, "[joints]\ndfn_file = \"dfn.csv\"\n");
  why = refused(text);
  EXPECT_TRUE(rockfdem::test::has(why, "'joints.dfn_file'")) << why;
  text = kScene;
  text.replace(text.find("joints = [\"Fault\"]"), 18, "");
  why = refused(text);
  EXPECT_TRUE(rockfdem::test::has(why, "'joints'")) << why;
  EXPECT_TRUE(rockfdem::test::has(why, "no joint lines")) << why;
  const Scene wrong = load_scene(scene, {"msh.joints=[\"Faults\"]"});
  try {
    mesh::build_mesh(wrong.mesh);
    ADD_FAILURE() << "a missing joint group was read";
  } catch (const InputError& e) {
    EXPECT_TRUE(rockfdem::test::has(e.what(), "joint physical group 'Faults'")) << e.what();
    EXPECT_TRUE(rockfdem::test::has(e.what(), "'Fault'")) << e.what();
  }
  fs::remove_all(dir);
}
