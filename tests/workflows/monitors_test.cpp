// Tunnel monitors placed on the excavation boundary found in the mesh and
// tied to engine nodes: the seed horseshoe's walls midway between
// springline and floor, a circular tunnel's points at the compass points, a
// user's .msh with its opening away from the origin, and the error for a
// .msh without an opening. Built from monitors.cpp, mesh/ and fdem/ only
// (no deal.II), so it compiles in seconds.
#include "outputs/monitors.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace rockfdem::workflows {
namespace {

// An elastic engine on the mesh: monitors need only its nodes.
fdem::Engine engine_on(const mesh::Mesh& m) {
  fdem::ModelInput in;
  in.x = m.x, in.y = m.y, in.triangles = m.triangles;
  in.material.assign(m.n_triangles(), 0);
  in.materials = {fdem::Material{}};
  in.threads = 1;
  return fdem::Engine(in);
}

std::map<std::string, Monitor> by_name(const std::vector<Monitor>& monitors) {
  std::map<std::string, Monitor> out;
  for (const Monitor& mon : monitors) out[mon.name] = mon;
  EXPECT_EQ(out.size(), 6u);
  return out;
}

// The followed node sits at the vertex it reports, on a rock triangle.
void expect_tied(const fdem::Engine& e, const mesh::Mesh& m, const Monitor& mon) {
  ASSERT_GE(mon.node, 0) << mon.name;
  const int v = e.node_vertex()[mon.node];
  EXPECT_EQ(m.x[v], mon.node_x) << mon.name;
  EXPECT_EQ(m.y[v], mon.node_y) << mon.name;
}

mesh::MeshSpec seed_tunnel() {
  mesh::MeshSpec s;
  s.tunnel.shape = mesh::TunnelShape::kHorseshoe;
  s.tunnel.span = 11.3, s.tunnel.height = 8.8;
  s.tunnel.lining_thickness = 0.2, s.tunnel.fracture_zone = 4;
  s.domain = {80, 80, 0, 0};
  s.size.size_near = 0.35, s.size.size_far = 5, s.size.grading_distance = 25;
  return s;
}

// Springline at the arch centre 4.4 - 5.65 = -1.25, floor at -4.4: the
// walls' nodes within half an element of y = -2.825 on the walls x = +-5.65.
TEST(TunnelMonitors, seed_horseshoe_walls_are_mid_wall) {
  const mesh::MeshSpec s = seed_tunnel();
  const mesh::Mesh m = mesh::build_mesh(s);
  const fdem::Engine e = engine_on(m);
  const auto mon = by_name(tunnel_monitors(s, m, e));
  const double half = s.size.size_near / 2;
  for (const char* wall : {"left_wall", "right_wall"}) {
    const Monitor& w = mon.at(wall);
    expect_tied(e, m, w);
    EXPECT_NEAR(w.node_y, -2.825, half) << wall;
    EXPECT_NEAR(std::abs(w.node_x), 5.65, 1e-9) << wall;
    EXPECT_NEAR(w.y, -2.825, 1e-9) << wall;
  }
  EXPECT_EQ(mon.at("left_wall").inward_x, 1.0);
  EXPECT_EQ(mon.at("right_wall").inward_x, -1.0);
  EXPECT_NEAR(mon.at("vault").node_y, 4.4, 1e-9);
  EXPECT_NEAR(mon.at("vault").node_x, 0, half);
  EXPECT_EQ(mon.at("vault").inward_y, -1.0);
  EXPECT_NEAR(mon.at("invert").node_y, -4.4, 1e-9);
  // A displacement straight into the opening at the vault: full convergence.
  EXPECT_DOUBLE_EQ(radial_convergence(mon.at("vault"), {0, -0.01}), 0.01);
}

TEST(TunnelMonitors, circular_points_are_at_the_compass_points) {
  mesh::MeshSpec s;
  s.tunnel.shape = mesh::TunnelShape::kCircular;
  s.tunnel.radius = 3, s.tunnel.fracture_zone = 1;
  s.domain = {30, 30, 0, 0};
  s.size.size_near = 0.25, s.size.size_far = 3;
  const mesh::Mesh m = mesh::build_mesh(s);
  const fdem::Engine e = engine_on(m);
  const auto mon = by_name(tunnel_monitors(s, m, e));
  // Crown, invert and the walls are geometry points of the circle: exact.
  const std::map<std::string, std::pair<double, double>> compass{
      {"vault", {0, 3}}, {"invert", {0, -3}}, {"left_wall", {-3, 0}}, {"right_wall", {3, 0}}};
  for (const auto& [name, at] : compass) {
    expect_tied(e, m, mon.at(name));
    EXPECT_NEAR(mon.at(name).node_x, at.first, 1e-9) << name;
    EXPECT_NEAR(mon.at(name).node_y, at.second, 1e-9) << name;
    // Inward is radial: minus the point over the radius.
    EXPECT_NEAR(mon.at(name).inward_x, -at.first / 3, 1e-12) << name;
    EXPECT_NEAR(mon.at(name).inward_y, -at.second / 3, 1e-12) << name;
  }
  // Shoulders: the nearest boundary vertex to 45 degrees, within half an element.
  const double d = 3 * std::sqrt(0.5);
  EXPECT_NEAR(mon.at("right_shoulder").node_x, d, 0.125 + 0.01);
  EXPECT_NEAR(mon.at("right_shoulder").node_y, d, 0.125 + 0.01);
  EXPECT_NEAR(std::hypot(mon.at("left_shoulder").node_x, mon.at("left_shoulder").node_y), 3, 1e-9);
}

std::string temp_msh(const std::string& what) {
  return ::testing::TempDir() + "monitors_" + what + "_" + std::to_string(::getpid()) + ".msh";
}

// A user's mesh: a circular opening of radius 2 centred at (7, -3), written
// by the msh writer and read back. The default tunnel's points (vault at
// (0, 4.4)) are nowhere near it; its own are.
TEST(TunnelMonitors, user_msh_gets_points_on_its_own_opening) {
  mesh::MeshSpec built;
  built.tunnel.shape = mesh::TunnelShape::kCircular;
  built.tunnel.radius = 2;
  built.domain = {30, 30, 0, 0};
  built.size.size_near = 0.2, built.size.size_far = 2;
  mesh::Mesh made = mesh::build_mesh(built);
  for (double& x : made.x) x += 7;
  for (double& y : made.y) y -= 3;
  mesh::MeshSpec s;
  s.kind = mesh::ModelKind::kMshFile;
  s.msh.path = temp_msh("user");
  mesh::write_msh(made, s.msh.path);
  const mesh::Mesh m = mesh::read_msh(s.msh);
  std::remove(s.msh.path.c_str());
  const fdem::Engine e = engine_on(m);
  const auto mon = by_name(tunnel_monitors(s, m, e));
  expect_tied(e, m, mon.at("vault"));
  EXPECT_NEAR(mon.at("vault").node_x, 7, 1e-9);
  EXPECT_NEAR(mon.at("vault").node_y, -1, 1e-9);
  EXPECT_NEAR(mon.at("invert").node_y, -5, 1e-9);
  EXPECT_NEAR(mon.at("left_wall").node_x, 5, 1e-9);
  EXPECT_NEAR(mon.at("right_wall").node_x, 9, 1e-9);
  EXPECT_NEAR(mon.at("right_wall").node_y, -3, 1e-9);
  for (const auto& [name, a] : mon)
    EXPECT_NEAR(std::hypot(a.node_x - 7, a.node_y + 3), 2, 1e-9) << name;
}

TEST(TunnelMonitors, msh_without_an_opening_is_an_input_error_naming_the_file) {
  mesh::MeshSpec block;
  block.kind = mesh::ModelKind::kUcs;
  block.size.size_near = 0.01;
  mesh::MeshSpec s;
  s.kind = mesh::ModelKind::kMshFile;
  s.msh.path = temp_msh("solid");
  mesh::write_msh(mesh::build_mesh(block), s.msh.path);
  const mesh::Mesh m = mesh::read_msh(s.msh);
  std::remove(s.msh.path.c_str());
  const fdem::Engine e = engine_on(m);
  try {
    tunnel_monitors(s, m, e);
    FAIL() << "no InputError";
  } catch (const InputError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find(s.msh.path), std::string::npos) << what;
    EXPECT_NE(what.find("no excavation boundary was found"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace rockfdem::workflows
