// The fracture zone's mesh must be isotropic and unstructured: crack
// elements lie on mesh edges, and a lattice-like mesh lets cracks run only
// along its straight lattice lines. First the measuring function against a
// lattice whose figures are known in closed form, then the default tunnel
// mesh against stated bounds, and the old default (algorithm 6,
// Frontal-Delaunay) shown to fail them.
//
// Survey of the algorithms (prints the table of docs/meshing.md):
//   build/tests/mesh/rockfdem_mesh_tests --gtest_also_run_disabled_tests
//       --gtest_filter='FractureZoneMesh.DISABLED_survey*'   (one line)
#include "rockfdem/mesh/edge_orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/constants.hpp"

namespace rockfdem::mesh {
namespace {

// An equilateral lattice of n x n points (side 1), edges at 0, 60 and 120
// degrees to the x axis, split into 2 (n-1)^2 counter-clockwise triangles.
Mesh hexagonal_lattice(int n) {
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.x.push_back(i + 0.5 * j);
      m.y.push_back(j * std::sqrt(3.0) / 2);
    }
  const auto id = [n](int i, int j) { return j * n + i; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  m.zone.assign(m.triangles.size(), kRock);
  m.fracture.assign(m.triangles.size(), 1);
  return m;
}

// 12 x 12 points: 11 x 12 edges at 0 and at 60 degrees, 11 x 11 at 120
// degrees; the rims (left out: no crack joins two band triangles there)
// take 22 of the 0- and 22 of the 60-degree edges, leaving 110, 110, 121.
constexpr double kShare0 = 110.0 / 341, kShare120 = 121.0 / 341;

// A centre far off along -x: the radial direction is the x axis everywhere
// (to 1e-5 rad), so the length lies in the bins centred on 0, 60 and 120
// degrees (bins 0, 4, 8 of 12): max deviation 12 x 121/341 - 1.
// exp(i 6 phi) = 1 for all three angles (hexatic order 1); exp(i 2 phi)
// takes the three cube roots of unity with weights 110, 110, 121, so the
// bias is |121 - 110| / 341. Interior nodes all have 6 neighbours.
TEST(EdgeOrientation, equilateral_lattice_matches_closed_forms) {
  const Mesh m = hexagonal_lattice(12);
  const EdgeOrientation e = measure_edge_orientation(m, m.fracture, -1e6, 5);
  ASSERT_EQ(e.histogram.size(), 12u);
  for (int k = 0; k < 12; ++k)
    EXPECT_NEAR(e.histogram[k],
                k == 8       ? kShare120
                : k % 4 == 0 ? kShare0
                             : 0.0,
                1e-9)
        << "bin " << k;
  EXPECT_NEAR(e.max_deviation, 12 * kShare120 - 1, 1e-9);
  EXPECT_NEAR(e.hexatic_order, 1.0, 1e-9);
  EXPECT_NEAR(e.directional_bias, 11.0 / 341, 1e-9);
  EXPECT_DOUBLE_EQ(e.valence6_fraction, 1.0);
  EXPECT_EQ(e.n_interior_nodes, 10u * 10u);
  // Interior edges only: 3 (n-1)^2 + 2 (n-1) edges in all, less the 4 (n-1) on the rim.
  EXPECT_EQ(e.n_edges, 3u * 121u + 2u * 11u - 4u * 11u);
  EXPECT_NEAR(e.min_angle_deg, 60.0, 1e-9);
  EXPECT_NEAR(e.min_altitude, std::sqrt(3.0) / 2, 1e-12);
}

// Turning the reference direction by 90 degrees (centre far off along -y)
// moves the peaks to 90, 150 and 30 degrees: bins 6, 10, 2.
TEST(EdgeOrientation, angles_are_taken_against_the_radial_direction) {
  const Mesh m = hexagonal_lattice(12);
  const EdgeOrientation e = measure_edge_orientation(m, m.fracture, 5, -1e6);
  for (int k = 0; k < 12; ++k)
    EXPECT_NEAR(e.histogram[k],
                k == 2       ? kShare120
                : k % 4 == 2 ? kShare0
                             : 0.0,
                1e-9)
        << "bin " << k;
}

TEST(EdgeOrientation, only_band_triangles_count) {
  Mesh m = hexagonal_lattice(6);
  m.fracture.assign(m.n_triangles(), 0);
  const EdgeOrientation e = measure_edge_orientation(m, m.fracture, 0, 0);
  EXPECT_EQ(e.n_edges, 0u);
  EXPECT_EQ(e.n_interior_nodes, 0u);
  EXPECT_THROW(measure_edge_orientation(m, std::vector<std::uint8_t>(3, 1), 0, 0),
               std::invalid_argument);
}

// The seed scene's tunnel (scenes/tunnel-seed.toml): horseshoe 11.3 x 8.8 m,
// 0.2 m lining, 4 m fracture zone, near 0.35 m, far 5 m over 25 m, in an
// 80 m square. Angles are taken against the radial direction from the arch
// centre (0, 4.4 - 5.65).
MeshSpec seed_tunnel(int algorithm) {
  MeshSpec s;
  s.tunnel.shape = TunnelShape::kHorseshoe;
  s.tunnel.span = 11.3, s.tunnel.height = 8.8;
  s.tunnel.lining_thickness = 0.2, s.tunnel.fracture_zone = 4;
  s.domain = {80, 80, 0, 0};
  s.size.size_near = 0.35, s.size.size_far = 5, s.size.grading_distance = 25;
  if (algorithm > 0) s.size.algorithm = algorithm;
  return s;
}
constexpr double kArchCentreY = 4.4 - 5.65;

EdgeOrientation fracture_zone_figures(const MeshSpec& s) {
  const Mesh m = build_mesh(s);
  const double cy = s.tunnel.shape == TunnelShape::kCircular ? 0 : kArchCentreY;
  return measure_edge_orientation(m, m.fracture, 0, cy);
}

// Bounds. The fracture zone holds about 5400-6000 interior edges; if they
// were independent, a bin's share would scatter by sqrt(11/6000) = 4.3%
// and the largest of 12 bins by about 2.5 sigma = 0.11. Measured: Delaunay
// 0.11 (horseshoe) and 0.12 (circular), MeshAdapt 0.12 and 0.11, Frontal-
// Delaunay 0.21 and 0.30 (its lattice peaks at 30, 90, 150 degrees). So:
// at most 0.16 off flat. Valence 6: a Delaunay mesh has 45-50%, the
// Frontal-Delaunay lattice 89-91%: at most 65%.
constexpr double kMaxDeviation = 0.16;
constexpr double kMaxValence6 = 0.65;

TEST(FractureZoneMesh, default_tunnel_is_isotropic_and_unstructured) {
  const MeshSpec s = seed_tunnel(0);  // the MeshSizeSpec default algorithm
  const EdgeOrientation e = fracture_zone_figures(s);
  EXPECT_GT(e.n_edges, 4000u);
  EXPECT_LT(e.max_deviation, kMaxDeviation);
  EXPECT_LT(e.valence6_fraction, kMaxValence6);
  // Quality kept: no sliver shrinks the stable time step. Measured 32.9
  // degrees and 0.44 x size_near (Frontal-Delaunay: 38.8, 0.50).
  EXPECT_GT(e.min_angle_deg, 28.0);
  EXPECT_GT(e.min_altitude, 0.4 * s.size.size_near);
}

// The same check fails on the old default: the test can tell a lattice.
TEST(FractureZoneMesh, frontal_delaunay_lattice_fails_the_bounds) {
  const EdgeOrientation e = fracture_zone_figures(seed_tunnel(6));
  EXPECT_GT(e.max_deviation, kMaxDeviation);
  EXPECT_GT(e.valence6_fraction, kMaxValence6);
}

TEST(FractureZoneMesh, default_tunnel_mesh_repeats_bit_for_bit) {
  const Mesh a = build_mesh(seed_tunnel(0)), b = build_mesh(seed_tunnel(0));
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.fracture, b.fracture);
}

// Not a check: prints the figures of docs/meshing.md for the three
// triangle algorithms, seed horseshoe and a circular opening of radius 5.
TEST(FractureZoneMesh, DISABLED_survey_of_algorithms) {
  std::printf("%-10s %4s %8s %8s %8s %8s %8s %9s %8s %8s\n", "shape", "alg", "tris", "edges",
              "maxdev", "val6", "hexatic", "minang", "minalt/h", "all_alt/h");
  for (const bool circular : {false, true})
    for (const int algorithm : {6, 5, 1}) {
      MeshSpec s = seed_tunnel(algorithm);
      if (circular) s.tunnel.shape = TunnelShape::kCircular, s.tunnel.radius = 5;
      MeshReport r;
      const Mesh m = build_mesh(s, &r);
      const EdgeOrientation e =
          measure_edge_orientation(m, m.fracture, 0, circular ? 0 : kArchCentreY);
      const double h = s.size.size_near;
      std::printf("%-10s %4d %8zu %8zu %8.3f %8.3f %8.3f %9.1f %8.3f %8.3f\n",
                  circular ? "circular" : "horseshoe", algorithm, r.n_triangles, e.n_edges,
                  e.max_deviation, e.valence6_fraction, e.hexatic_order, e.min_angle_deg,
                  e.min_altitude / h, r.min_altitude / h);
      std::printf("  histogram x 12:");
      for (double v : e.histogram) std::printf(" %.2f", 12 * v);
      std::printf("\n");
    }
}

}  // namespace
}  // namespace rockfdem::mesh
