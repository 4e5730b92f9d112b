// The locality order (locality.hpp): the Hilbert index is a curve through
// every cell, the order is a permutation that leaves the mesh as it was
// (same triangles with the same corners, areas, zones, fracture flags and
// adjacency), build_mesh hands out meshes already in it, and it puts
// neighbouring triangles close together in the numbering.
#include "rockfdem/mesh/locality.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <set>
#include <vector>

#include "mesh_checks.hpp"
#include "rockfdem/mesh/build.hpp"

namespace rockfdem::mesh {
namespace {

using namespace checks;

// Order 4: 256 cells, each visited once (the indices are 0..255), and
// cells with consecutive indices share a side, which is what makes a run
// of consecutive triangles one compact patch.
TEST(Locality, hilbert_index_walks_every_cell_once_through_side_neighbours) {
  constexpr int kOrder = 4, kN = 1 << kOrder;
  std::vector<std::array<int, 2>> cell_at(kN * kN, {-1, -1});
  for (int x = 0; x < kN; ++x)
    for (int y = 0; y < kN; ++y) {
      const std::uint64_t d = hilbert_index(x, y, kOrder);
      ASSERT_LT(d, std::uint64_t(kN * kN));
      ASSERT_EQ(cell_at[d][0], -1) << "index " << d << " given twice";
      cell_at[d] = {x, y};
    }
  for (int d = 1; d < kN * kN; ++d)
    EXPECT_EQ(
        std::abs(cell_at[d][0] - cell_at[d - 1][0]) + std::abs(cell_at[d][1] - cell_at[d - 1][1]),
        1)
        << "step " << d;
  EXPECT_EQ(hilbert_index(0, 0, 1), 0u);
  EXPECT_EQ(hilbert_index(0, 1, 1), 1u);
  EXPECT_EQ(hilbert_index(1, 1, 1), 2u);
  EXPECT_EQ(hilbert_index(1, 0, 1), 3u);
}

// A circular tunnel with a lining ring and a fracture zone, meshed once.
const Mesh& tunnel() {
  static const Mesh m = [] {
    MeshSpec s;
    s.tunnel.shape = TunnelShape::kCircular;
    s.tunnel.radius = 2;
    s.tunnel.lining_thickness = 0.2;
    s.tunnel.fracture_zone = 1.5;
    s.domain = {30, 30, 0, 0};
    s.size.size_near = 0.2, s.size.size_far = 2.5;
    return build_mesh(s);
  }();
  return m;
}

/// A fixed scramble of 0..n-1 (Fisher-Yates on a 64-bit LCG, so the same
/// on every standard library).
std::vector<int> scramble(std::size_t n) {
  std::vector<int> p(n);
  std::iota(p.begin(), p.end(), 0);
  std::uint64_t s = 12345;
  for (std::size_t i = n; i > 1; --i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(p[i - 1], p[(s >> 33) % i]);
  }
  return p;
}

std::vector<int> identity(std::size_t n) {
  std::vector<int> p(n);
  std::iota(p.begin(), p.end(), 0);
  return p;
}

TEST(Locality, build_mesh_hands_out_a_tunnel_in_locality_order) {
  const Mesh& m = tunnel();
  ASSERT_GT(m.n_triangles(), 1000u);
  EXPECT_EQ(locality_order(m), identity(m.n_triangles()));
}

// Scrambled, then put back in locality order: exactly the mesh build_mesh
// gave (the order depends on the geometry, not on the numbering it finds).
TEST(Locality, order_is_a_permutation_that_restores_the_same_mesh) {
  const Mesh& m = tunnel();
  const Mesh s = with_triangle_order(m, scramble(m.n_triangles()));
  const std::vector<int> order = locality_order(s);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, identity(m.n_triangles()));
  const Mesh r = with_triangle_order(s, order);
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.zone, m.zone);
  EXPECT_EQ(r.fracture, m.fracture);
  EXPECT_EQ(r.x, m.x);
  EXPECT_EQ(r.y, m.y);
}

// Each triangle keeps its corners (so its signed area to the bit), its
// zone and fracture flag; the tagged edges stay; and two triangles share an
// edge after the renumbering exactly when they shared it before.
TEST(Locality, renumbered_mesh_keeps_areas_zones_edges_and_adjacency) {
  const Mesh s = with_triangle_order(tunnel(), scramble(tunnel().n_triangles()));
  const std::vector<int> order = locality_order(s);
  const Mesh r = with_triangle_order(s, order);
  for (std::size_t t = 0; t < r.n_triangles(); ++t) {
    ASSERT_EQ(signed_area(r, t), signed_area(s, order[t])) << "triangle " << t;
    ASSERT_EQ(r.zone[t], s.zone[order[t]]);
    ASSERT_EQ(r.fracture[t], s.fracture[order[t]]);
  }
  EXPECT_NEAR(zone_area(r, 0), zone_area(s, 0), 1e-9 * zone_area(s, 0));
  ASSERT_EQ(r.edges.size(), s.edges.size());
  for (std::size_t e = 0; e < r.edges.size(); ++e) {
    EXPECT_EQ(r.edges[e].a, s.edges[e].a);
    EXPECT_EQ(r.edges[e].b, s.edges[e].b);
    EXPECT_EQ(r.edges[e].tag, s.edges[e].tag);
  }
  auto before = edge_triangles(s), after = edge_triangles(r);
  ASSERT_EQ(before.size(), after.size());
  for (const auto& [edge, tris] : after) {
    std::set<std::size_t> mapped;
    for (std::size_t t : tris) mapped.insert(std::size_t(order[t]));
    const auto it = before.find(edge);
    ASSERT_NE(it, before.end());
    EXPECT_EQ(mapped, std::set<std::size_t>(it->second.begin(), it->second.end()));
  }
}

/// Median over interior edges of |t1 - t2|, the id distance between the
/// two triangles that share the edge.
long median_neighbour_distance(const Mesh& m) {
  std::vector<long> d;
  for (const auto& [edge, tris] : edge_triangles(m))
    if (tris.size() == 2) d.push_back(std::labs(long(tris[0]) - long(tris[1])));
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return d[d.size() / 2];
}

// On a Hilbert curve half of a cell's side neighbours lie within a few
// steps along it, whatever the grid's size; a scrambled numbering puts
// them a third of the mesh apart on average.
TEST(Locality, neighbouring_triangles_get_close_ids) {
  const Mesh& m = tunnel();
  const long ordered = median_neighbour_distance(m);
  const long scrambled =
      median_neighbour_distance(with_triangle_order(m, scramble(m.n_triangles())));
  std::printf("median id distance of edge neighbours: %ld ordered, %ld scrambled (%zu triangles)\n",
              ordered, scrambled, m.n_triangles());
  EXPECT_LE(ordered, 4);
  EXPECT_GT(scrambled, long(m.n_triangles() / 10));
}

}  // namespace
}  // namespace rockfdem::mesh
