// Material points and the broken zone along rays, on real meshes: a
// monitor's displacement interpolated in its triangle is exact for a linear
// displacement field, and the broken depth along a key point's ray reaches
// the radius out to which crack elements were broken, ignoring broken
// elements away from the ray. Built from workflows/ sources with mesh/ and
// fdem/ only (no deal.II).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "outputs/broken_zone.hpp"
#include "outputs/material_point.hpp"
#include "outputs/monitors.hpp"
#include "rockfdem/mesh/build.hpp"

namespace rockfdem::workflows {
namespace {

mesh::MeshSpec circular(double fracture_zone) {
  mesh::MeshSpec s;
  s.tunnel.shape = mesh::TunnelShape::kCircular;
  s.tunnel.radius = 3, s.tunnel.fracture_zone = fracture_zone;
  s.domain = {30, 30, 0, 0};
  s.size.size_near = 0.25, s.size.size_far = 3;
  return s;
}

// A weak rock (a crack breaks after microns of opening or slip) with crack
// elements in the fracture zone, at rest and unstressed.
fdem::Engine weak_engine(const mesh::Mesh& m) {
  fdem::ModelInput in;
  in.x = m.x, in.y = m.y, in.triangles = m.triangles;
  in.material.assign(m.n_triangles(), 0);
  fdem::Material rock;
  rock.tensile_strength = 1e3, rock.cohesion = 1e3, rock.gf_I = 1e-3, rock.gf_II = 1e-3;
  in.materials = {rock};
  in.fracture = m.fracture;
  in.threads = 1;
  return fdem::Engine(in);
}

// Displacement u = A x + b of the node's mesh vertex.
std::array<double, 2> linear(const fdem::Engine& e, const mesh::Mesh& m, int node) {
  const int v = e.node_vertex()[node];
  return {1e-3 + 2e-3 * m.x[v] - 5e-4 * m.y[v], -2e-3 + 7e-4 * m.x[v] + 3e-3 * m.y[v]};
}

TEST(MaterialPoint, interpolation_is_exact_for_a_linear_displacement_field) {
  const mesh::Mesh m = mesh::build_mesh(circular(2));
  const fdem::Engine e = weak_engine(m);
  const NodeDisplacement u = [&](int node) { return linear(e, m, node); };
  // Points inside triangles (not at vertices), in the fracture zone (own
  // nodes per triangle) and beyond it (shared nodes).
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{
           {3.37, 0.41}, {-2.9, 2.2}, {0.13, -4.61}, {9.3, -7.7}, {-13.1, 12.9}}) {
    const std::optional<MaterialPoint> p = locate(m, e, x, y);
    ASSERT_TRUE(p) << x << ", " << y;
    EXPECT_EQ(p->zone, mesh::kRock);
    const std::array<double, 2> got = interpolate(*p, u);
    const double ux = 1e-3 + 2e-3 * x - 5e-4 * y, uy = -2e-3 + 7e-4 * x + 3e-3 * y;
    EXPECT_NEAR(got[0], ux, 1e-15) << x << ", " << y;
    EXPECT_NEAR(got[1], uy, 1e-15) << x << ", " << y;
    // A point not at a vertex weighs more than one node.
    EXPECT_LT(*std::max_element(p->weights.begin(), p->weights.end()), 1.0 - 1e-6);
  }
}

TEST(MaterialPoint, opening_points_are_core_and_outside_points_are_nowhere) {
  const mesh::Mesh m = mesh::build_mesh(circular(2));
  const fdem::Engine e = weak_engine(m);
  EXPECT_EQ(locate(m, e, 0.5, 0.2)->zone, mesh::kCore);
  // On the opening's boundary (the crown vertex): the rock's triangle.
  EXPECT_EQ(locate(m, e, 0, 3)->zone, mesh::kRock);
  EXPECT_FALSE(locate(m, e, 15.5, 0));
}

// Shifts every node of the rock triangles whose centroid satisfies `in` by
// (sx, sy): crack elements between shifted and unshifted triangles open or
// slip by the shift, those inside the block stay closed.
template <class In>
void shift_block(fdem::Engine& e, const mesh::Mesh& m, In in, double sx, double sy) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    const auto& v = m.triangles[t];
    const double cx = (m.x[v[0]] + m.x[v[1]] + m.x[v[2]]) / 3;
    const double cy = (m.y[v[0]] + m.y[v[1]] + m.y[v[2]]) / 3;
    if (!in(cx, cy)) continue;
    for (int node : e.triangle_nodes(t))
      e.set_node_state(node, e.positions()[2 * node] + sx, e.positions()[2 * node + 1] + sy, 0, 0);
  }
}

// The blocks below pushed and one step taken (cracks along their edges
// broken), with the key points' rays.
struct BrokenBlocks {
  mesh::MeshSpec spec = circular(3);
  mesh::Mesh m = mesh::build_mesh(spec);
  fdem::Engine e = weak_engine(m);
  std::vector<Ray> rays;
  std::map<std::string, int> index;
  explicit BrokenBlocks(bool off_ray_block) {
    const double d = 0.01;
    shift_block(
        e, m, [](double x, double y) { return x > 0 && x < 1 && y > 3 && y < 4.5; }, d, 0);
    shift_block(
        e, m, [](double x, double y) { return y > 0 && y < 1 && x > 3 && x < 5.5; }, 0, d);
    // Farther up than the crown's block, but 1.8 m off its ray.
    if (off_ray_block)
      shift_block(
          e, m, [](double x, double y) { return x > 1.8 && x < 2.6 && y > 3.8 && y < 5.2; }, d, 0);
    e.step();
    for (const Monitor& k : tunnel_monitors(spec, m, e)) {
      index[k.name] = int(rays.size());
      rays.push_back({k.x, k.y, -k.inward_x, -k.inward_y});
    }
  }
};

// Above the crown, a block right of the vertical ray x = 0 is pushed 10 mm
// sideways up to 1.5 m above the opening: the cracks along the ray and
// across its top break out to 1.5 m. Right of the right wall, a block up to
// 2.5 m deep is pushed up, and a third block, up to 2.2 m above the crown
// but 1.8 m to its side. The crown's ray meets broken cracks to 1.5 m (not
// the third block's 2.2 m), the right wall's to 2.5 m, the other key
// points' none.
TEST(BrokenDepth, each_key_points_ray_reaches_the_radius_broken_along_it) {
  BrokenBlocks b(true);
  const mesh::MeshSpec& s = b.spec;
  const mesh::Mesh& m = b.m;
  fdem::Engine& e = b.e;
  const std::vector<Ray>& rays = b.rays;
  const std::map<std::string, int>& index = b.index;
  ASSERT_GT(e.broken_counts().total(), 20);
  // Resolved to one element: the farthest element within half an element
  // of the ray has its midpoint up to an element short of the block's edge.
  const double h = s.size.size_near;
  const std::vector<double> depth = broken_depth_along_rays(e, m, rays, h / 2, {});
  EXPECT_NEAR(depth[index.at("vault")], 1.5, h);
  EXPECT_NEAR(depth[index.at("right_wall")], 2.5, h);
  EXPECT_EQ(depth[index.at("left_wall")], 0.0);
  EXPECT_EQ(depth[index.at("invert")], 0.0);
  // Without the ray's half-width both shoulders would count blocks ahead of them.
  EXPECT_EQ(depth[index.at("left_shoulder")], 0.0);
  EXPECT_EQ(depth[index.at("right_shoulder")], 0.0);
  // Over the whole boundary the third block's far corner is the deepest.
  const BrokenZone z = broken_zone(e, m, h, {});
  EXPECT_NEAR(z.depth, std::hypot(2.6, 5.2) - 3, h);
}

// Grouting re-joins the broken cracks of the right wall's block: the
// broken depth along its ray drops to 0 while the depth of the zone broken
// at some time, grouted since, stays at the block's 2.5 m; elsewhere
// (crown) the two agree.
TEST(BrokenDepth, grouted_cracks_count_in_the_zone_broken_at_some_time) {
  BrokenBlocks b(false);
  const mesh::Mesh& m = b.m;
  fdem::Engine& e = b.e;
  std::vector<char> grouted(e.n_cracks(), 0);
  const std::vector<int>& vertex = e.node_vertex();
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto n = e.crack_nodes(c);
    const bool right = m.x[vertex[n[0]]] > 2.9 && m.y[vertex[n[0]]] < 1.5;
    if (right && e.crack_state(c) == fdem::CrackState::kBroken) {
      e.rejoin_crack(c, 0);
      grouted[c] = 1;
    }
  }
  ASSERT_GT(std::count(grouted.begin(), grouted.end(), 1), 10);
  const std::vector<Ray>& rays = b.rays;
  const std::map<std::string, int>& index = b.index;
  const double h = b.spec.size.size_near;
  const std::vector<double> now = broken_depth_along_rays(e, m, rays, h / 2, {});
  const std::vector<double> ever = broken_depth_along_rays(e, m, rays, h / 2, {}, grouted);
  EXPECT_EQ(now[index.at("right_wall")], 0.0);
  EXPECT_NEAR(ever[index.at("right_wall")], 2.5, h);
  EXPECT_NEAR(now[index.at("vault")], 1.5, h);
  EXPECT_EQ(ever[index.at("vault")], now[index.at("vault")]);
  EXPECT_EQ(ever[index.at("invert")], 0.0);
}

}  // namespace
}  // namespace rockfdem::workflows
