// The rock locator (outputs/rock_locator.hpp) against the scan in triangle
// order it replaces: the same triangle, the lowest-numbered rock one, for
// every vertex, edge midpoint and centroid of a jittered grid (points on
// shared edges and corners lie in several triangles), -1 in the core and
// outside the mesh.
#include "outputs/rock_locator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rw = rockfdem::workflows;
namespace rm = rockfdem::mesh;

namespace {

constexpr int kCells = 24;

// kCells x kCells squares on [-3, 3]^2, split in two counter-clockwise
// triangles, vertices jittered by up to a fifth of a cell; the middle 6 x 6
// cells are core.
rm::Mesh jittered_grid() {
  rm::Mesh m;
  const double h = 6.0 / kCells;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const bool edge = i == 0 || j == 0 || i == kCells || j == kCells;
      const double jx = edge ? 0 : 0.2 * h * std::sin(12.9898 * i + 78.233 * j);
      const double jy = edge ? 0 : 0.2 * h * std::cos(39.3468 * i + 11.135 * j);
      m.x.push_back(-3 + i * h + jx);
      m.y.push_back(-3 + j * h + jy);
    }
  const auto id = [](int i, int j) { return j * (kCells + 1) + i; };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const bool core = std::abs(2 * i + 1 - kCells) < 6 && std::abs(2 * j + 1 - kCells) < 6;
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      m.zone.insert(m.zone.end(), 2, core ? rm::kCore : rm::kRock);
    }
  m.fracture.assign(m.triangles.size(), 1);
  return m;
}

int scan(const rm::Mesh& m, double x, double y) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != rm::kRock) continue;
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      inside = (m.x[b] - m.x[a]) * (y - m.y[a]) - (m.y[b] - m.y[a]) * (x - m.x[a]) >= 0;
    }
    if (inside) return int(t);
  }
  return -1;
}

}  // namespace

TEST(RockLocator, finds_the_triangle_a_scan_in_triangle_order_finds) {
  const rm::Mesh m = jittered_grid();
  const rw::RockLocator rock(m);
  std::vector<std::array<double, 2>> points;
  for (std::size_t v = 0; v < m.x.size(); ++v) points.push_back({m.x[v], m.y[v]});
  for (const auto& tri : m.triangles) {
    points.push_back({(m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3,
                      (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3});
    for (int k = 0; k < 3; ++k)
      points.push_back(
          {(m.x[tri[k]] + m.x[tri[(k + 1) % 3]]) / 2, (m.y[tri[k]] + m.y[tri[(k + 1) % 3]]) / 2});
  }
  points.push_back({3.5, 0.0});
  points.push_back({-3.0, -3.5});
  int found = 0, none = 0;
  for (const auto& [x, y] : points) {
    const int t = rock.at(x, y);
    ASSERT_EQ(t, scan(m, x, y)) << "at (" << x << ", " << y << ")";
    (t >= 0 ? found : none) += 1;
  }
  // Both answers occur: rock points, and core centroids and points outside.
  EXPECT_GT(found, 1000);
  EXPECT_GT(none, 2 * 36);
}
