// The excavation boundary found in the mesh and the key points on it, per
// shape, against the exact outline: on straight walls and at geometry points
// (crown, invert, springing, corners) the meshed boundary is exact, so those
// points are exact to rounding; on an arc between mesh vertices the chord
// lies inside the arc by at most the sagitta h^2 / (8 R) (h: chord length,
// below 1.3 x size_near).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/mesh/opening.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh {
namespace {

constexpr double kExact = 1e-9;

MeshSpec tunnel(TunnelShape shape, double near) {
  MeshSpec s;
  s.tunnel.shape = shape;
  s.tunnel.lining_thickness = 0.2;
  s.tunnel.fracture_zone = 2;
  s.domain = {60, 60, 0, 0};
  s.size.size_near = near, s.size.size_far = 4;
  return s;
}

double sagitta(double near, double radius) {
  const double h = 1.3 * near;
  return h * h / (8 * radius);
}

std::map<std::string, KeyPoint> key_points(const Mesh& m, const TunnelSpec* shape) {
  const std::optional<OpeningBoundary> b = find_opening(m);
  EXPECT_TRUE(b.has_value());
  std::map<std::string, KeyPoint> out;
  if (!b) return out;
  for (const KeyPoint& p : opening_key_points(m, *b, shape)) out[p.name] = p;
  EXPECT_EQ(out.size(), 6u);
  return out;
}

void expect_point(const KeyPoint& p, double x, double y, double tol) {
  EXPECT_NEAR(p.x, x, tol) << p.name;
  EXPECT_NEAR(p.y, y, tol) << p.name;
}

void expect_inward(const KeyPoint& p, double ix, double iy) {
  EXPECT_NEAR(p.inward_x, ix, 1e-12) << p.name;
  EXPECT_NEAR(p.inward_y, iy, 1e-12) << p.name;
}

// The seed tunnel: horseshoe 11.3 x 8.8, arch centre at 4.4 - 5.65 = -1.25
// (the springline), floor at -4.4: the walls' monitors go midway, at
// y = -2.825 (they were at -0.83, on the arch, before).
TEST(KeyPoints, seed_horseshoe_walls_are_midway_between_springline_and_floor) {
  MeshSpec s = tunnel(TunnelShape::kHorseshoe, 0.35);
  s.tunnel.span = 11.3, s.tunnel.height = 8.8, s.tunnel.fracture_zone = 4;
  s.domain = {80, 80, 0, 0};
  const Mesh m = build_mesh(s);
  const auto k = key_points(m, &s.tunnel);
  expect_point(k.at("left_wall"), -5.65, -2.825, kExact);
  expect_point(k.at("right_wall"), 5.65, -2.825, kExact);
  expect_point(k.at("vault"), 0, 4.4, kExact);
  expect_point(k.at("invert"), 0, -4.4, kExact);
  const double d = 5.65 * std::sqrt(0.5), sag = sagitta(0.35, 5.65);
  // On the arch: along the 45-degree ray, at most a sagitta short of it.
  expect_point(k.at("left_shoulder"), -d, -1.25 + d, sag);
  expect_point(k.at("right_shoulder"), d, -1.25 + d, sag);
  expect_inward(k.at("left_wall"), 1, 0);
  expect_inward(k.at("right_wall"), -1, 0);
  expect_inward(k.at("vault"), 0, -1);
  expect_inward(k.at("invert"), 0, 1);
  expect_inward(k.at("right_shoulder"), -std::sqrt(0.5), -std::sqrt(0.5));
}

TEST(KeyPoints, circular_points_are_at_the_compass_points) {
  MeshSpec s = tunnel(TunnelShape::kCircular, 0.25);
  s.tunnel.radius = 3;
  const Mesh m = build_mesh(s);
  const auto k = key_points(m, &s.tunnel);
  expect_point(k.at("vault"), 0, 3, kExact);
  expect_point(k.at("invert"), 0, -3, kExact);
  expect_point(k.at("left_wall"), -3, 0, kExact);
  expect_point(k.at("right_wall"), 3, 0, kExact);
  const double d = 3 * std::sqrt(0.5), sag = sagitta(0.25, 3);
  expect_point(k.at("left_shoulder"), -d, d, sag);
  expect_point(k.at("right_shoulder"), d, d, sag);
  expect_inward(k.at("left_shoulder"), std::sqrt(0.5), -std::sqrt(0.5));
  expect_inward(k.at("left_wall"), 1, 0);
}

// Arched: rise 2 on span 8, height 6: springing at 3 - 2 = 1, floor at -3,
// walls midway at -1; the shoulders are the springing points (-4, 1), (4, 1).
TEST(KeyPoints, arched_shoulders_at_the_springing_walls_midway_below) {
  MeshSpec s = tunnel(TunnelShape::kArched, 0.25);
  s.tunnel.span = 8, s.tunnel.height = 6, s.tunnel.rise = 2;
  const Mesh m = build_mesh(s);
  const auto k = key_points(m, &s.tunnel);
  expect_point(k.at("left_shoulder"), -4, 1, 1e-7);
  expect_point(k.at("right_shoulder"), 4, 1, 1e-7);
  expect_point(k.at("left_wall"), -4, -1, kExact);
  expect_point(k.at("right_wall"), 4, -1, kExact);
  expect_point(k.at("vault"), 0, 3, kExact);
  expect_point(k.at("invert"), 0, -3, kExact);
}

TEST(KeyPoints, rectangular_shoulders_at_the_top_corners_walls_at_mid_height) {
  MeshSpec s = tunnel(TunnelShape::kRectangular, 0.25);
  s.tunnel.span = 6, s.tunnel.height = 4;
  const Mesh m = build_mesh(s);
  const auto k = key_points(m, &s.tunnel);
  expect_point(k.at("left_shoulder"), -3, 2, 1e-7);
  expect_point(k.at("right_shoulder"), 3, 2, 1e-7);
  expect_point(k.at("left_wall"), -3, 0, kExact);
  expect_point(k.at("right_wall"), 3, 0, kExact);
  const double r = std::hypot(3, 2);
  expect_inward(k.at("right_shoulder"), -3 / r, -2 / r);
}

// The boundary itself: the area it encloses is the core-plus-lining area
// (the polygon through the meshed boundary), its centroid on the axis.
TEST(KeyPoints, opening_area_is_the_meshed_core_and_lining) {
  MeshSpec s = tunnel(TunnelShape::kHorseshoe, 0.3);
  s.tunnel.span = 8, s.tunnel.height = 7;
  const Mesh m = build_mesh(s);
  double inside = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] != kRock) inside += signed_area(m, t);
  const std::optional<OpeningBoundary> b = find_opening(m);
  ASSERT_TRUE(b);
  EXPECT_NEAR(b->area, inside, 1e-9 * inside);
  EXPECT_NEAR(b->cx, 0, 1e-9);
  EXPECT_LT(b->area, opening_area(s.tunnel));
}

TEST(KeyPoints, a_specimen_has_no_opening) {
  MeshSpec s;
  s.kind = ModelKind::kUcs;
  s.size.size_near = 0.01;
  EXPECT_FALSE(find_opening(build_mesh(s)).has_value());
}

// A user's mesh: a circular opening of radius 2 moved to (7, -3), written
// and read back as a .msh, once with its core and once as a bare hole. The
// shape-free rules put every point on its own opening: centroid (7, -3),
// vault (7, -1), walls (5, -3) and (9, -3), shoulders 45 degrees out.
Mesh moved_circle(bool keep_core) {
  MeshSpec s = tunnel(TunnelShape::kCircular, 0.2);
  s.tunnel.radius = 2, s.tunnel.lining_thickness = 0;
  s.domain = {30, 30, 0, 0};
  Mesh m = build_mesh(s);
  for (double& x : m.x) x += 7;
  for (double& y : m.y) y -= 3;
  if (!keep_core) {
    Mesh rock = m;
    rock.triangles.clear(), rock.zone.clear(), rock.fracture.clear();
    for (std::size_t t = 0; t < m.n_triangles(); ++t)
      if (m.zone[t] == kRock) {
        rock.triangles.push_back(m.triangles[t]);
        rock.zone.push_back(kRock);
        rock.fracture.push_back(m.fracture[t]);
      }
    rock.edges.clear();
    for (const TaggedEdge& e : m.edges)
      if (e.tag != kExcavation) rock.edges.push_back(e);
    // Drop the core's own vertices: a .msh keeps only used nodes anyway.
    m = rock;
  }
  const std::string path = ::testing::TempDir() + "key_points_" + std::to_string(::getpid()) +
                           (keep_core ? "_core" : "_hole") + ".msh";
  write_msh(m, path);
  Mesh r = read_msh({path, {}, {}, "", {}});
  std::remove(path.c_str());
  return r;
}

TEST(KeyPoints, user_msh_gets_points_on_its_own_opening) {
  for (const bool keep_core : {true, false}) {
    SCOPED_TRACE(keep_core ? "with core" : "bare hole");
    const Mesh m = moved_circle(keep_core);
    const std::optional<OpeningBoundary> b = find_opening(m);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->cx, 7, 1e-9);
    EXPECT_NEAR(b->cy, -3, 1e-9);
    const auto k = key_points(m, nullptr);
    const double sag = sagitta(0.2, 2), d = 2 * std::sqrt(0.5);
    expect_point(k.at("vault"), 7, -1, 1e-9);
    expect_point(k.at("invert"), 7, -5, 1e-9);
    expect_point(k.at("left_wall"), 5, -3, 1e-9);
    expect_point(k.at("right_wall"), 9, -3, 1e-9);
    expect_point(k.at("left_shoulder"), 7 - d, -3 + d, sag);
    expect_point(k.at("right_shoulder"), 7 + d, -3 + d, sag);
  }
}

TEST(KeyPoints, boundary_matches_only_the_outline_it_was_built_from) {
  MeshSpec s = tunnel(TunnelShape::kCircular, 0.25);
  s.tunnel.radius = 3;
  const Mesh m = build_mesh(s);
  const std::optional<OpeningBoundary> b = find_opening(m);
  ASSERT_TRUE(b);
  EXPECT_TRUE(boundary_matches(m, *b, s.tunnel, 1e-6));
  TunnelSpec other = s.tunnel;
  other.radius = 3.1;
  EXPECT_FALSE(boundary_matches(m, *b, other, 1e-6));
  EXPECT_FALSE(boundary_matches(m, *b, TunnelSpec{}, 1e-6));  // the default horseshoe
  other.radius = 0;                                           // builds no outline
  EXPECT_FALSE(boundary_matches(m, *b, other, 1e-6));
}

}  // namespace
}  // namespace rockfdem::mesh
