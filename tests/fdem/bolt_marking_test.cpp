// Marking of bolt triangles (bolt_marking.hpp). Generic orientations are
// checked against a brute-force reference written independently here:
// every triangle of the mesh (no grid), the segment clipped against the
// triangle's three half-planes in long double (Cyrus-Beck), "entered" when
// the clipped piece is longer than 1e-9 of the bolt. The touching cases
// (through a vertex, along an edge, long sides on mesh lines) have their
// expected sets worked out by hand in the comments.
#include "rockfdem/fdem/bolt_marking.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>

#include "rockfdem/error.hpp"
#include "rockfdem/fdem/constants.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

namespace rockfdem::fdem {
namespace {

ModelInput grid(double size, int n) {
  RectangleSpec spec;
  spec.width = spec.height = size;
  spec.nx = spec.ny = n;
  return structured_rectangle(spec, benchmark_rock());
}

std::array<Point2, 3> corners(const ModelInput& in, int t) {
  std::array<Point2, 3> v;
  for (int k = 0; k < 3; ++k) v[k] = {in.x[in.triangles[t][k]], in.y[in.triangles[t][k]]};
  return v;
}

/// Length of the part of segment p-q inside the triangle (Cyrus-Beck).
long double clipped_length(const Point2& p, const Point2& q, const std::array<Point2, 3>& v) {
  using L = long double;
  const L area2 = (L(v[1][0]) - v[0][0]) * (L(v[2][1]) - v[0][1]) -
                  (L(v[1][1]) - v[0][1]) * (L(v[2][0]) - v[0][0]);
  const L sign = area2 > 0 ? 1 : -1;
  L lo = 0, hi = 1;
  for (int k = 0; k < 3; ++k) {
    const Point2 &a = v[k], &b = v[(k + 1) % 3];
    // Inside when sign * cross(b - a, x - a) > 0; along the segment f(t) = f0 + t (f1 - f0).
    auto f = [&](const Point2& x) {
      return sign * ((L(b[0]) - a[0]) * (L(x[1]) - a[1]) - (L(b[1]) - a[1]) * (L(x[0]) - a[0]));
    };
    const L f0 = f(p), f1 = f(q);
    if (f0 <= 0 && f1 <= 0) return 0;
    if (f0 < 0) lo = std::max(lo, f0 / (f0 - f1));
    if (f1 < 0) hi = std::min(hi, f0 / (f0 - f1));
  }
  return hi > lo ? (hi - lo) * std::hypot(L(q[0]) - p[0], L(q[1]) - p[1]) : 0;
}

/// Brute-force marking of one bolt (generic position: no vertex on a line).
std::set<int> brute_force(const ModelInput& in, const Bolt& bolt) {
  const double len = std::hypot(bolt.b[0] - bolt.a[0], bolt.b[1] - bolt.a[1]);
  const Point2 u{(bolt.b[0] - bolt.a[0]) / len, (bolt.b[1] - bolt.a[1]) / len};
  const Point2 n{-u[1] * bolt.diameter / 2, u[0] * bolt.diameter / 2};
  const Point2 a1{bolt.a[0] + n[0], bolt.a[1] + n[1]}, b1{bolt.b[0] + n[0], bolt.b[1] + n[1]};
  const Point2 a2{bolt.a[0] - n[0], bolt.a[1] - n[1]}, b2{bolt.b[0] - n[0], bolt.b[1] - n[1]};
  const long double min_len = 1e-9L * len;
  std::set<int> centre;
  std::vector<double> edges;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const auto v = corners(in, int(t));
    if (clipped_length(bolt.a, bolt.b, v) > min_len) {
      centre.insert(int(t));
      for (int k = 0; k < 3; ++k)
        edges.push_back(std::hypot(v[k][0] - v[(k + 1) % 3][0], v[k][1] - v[(k + 1) % 3][1]));
    }
  }
  std::sort(edges.begin(), edges.end());
  if (bolt.diameter < edges[edges.size() / 2]) return centre;  // thin: centre line only
  std::set<int> out = centre;
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const auto v = corners(in, int(t));
    const double cx = (v[0][0] + v[1][0] + v[2][0]) / 3, cy = (v[0][1] + v[1][1] + v[2][1]) / 3;
    const double along = (cx - bolt.a[0]) * u[0] + (cy - bolt.a[1]) * u[1];
    const double across = -(cx - bolt.a[0]) * u[1] + (cy - bolt.a[1]) * u[0];
    const bool inside = along > 0 && along < len && std::fabs(across) < bolt.diameter / 2;
    if (inside || clipped_length(a1, b1, v) > min_len || clipped_length(a2, b2, v) > min_len)
      out.insert(int(t));
  }
  return out;
}

/// No vertex within 1e-9 of the centre line or long sides: the brute force
/// compares only generic positions.
bool generic(const ModelInput& in, const Bolt& bolt) {
  const double len = std::hypot(bolt.b[0] - bolt.a[0], bolt.b[1] - bolt.a[1]);
  for (std::size_t v = 0; v < in.x.size(); ++v) {
    const double d = ((bolt.b[0] - bolt.a[0]) * (in.y[v] - bolt.a[1]) -
                      (bolt.b[1] - bolt.a[1]) * (in.x[v] - bolt.a[0])) /
                     len;
    for (double off : {0.0, bolt.diameter / 2, -bolt.diameter / 2})
      if (std::fabs(d - off) < 1e-9) return false;
  }
  return true;
}

std::set<int> as_set(const std::vector<int>& v) { return {v.begin(), v.end()}; }

/// Every marked triangle reaches every other one through shared edges.
bool edge_connected(const ModelInput& in, const std::vector<int>& tris) {
  std::map<std::pair<int, int>, std::vector<int>> by_edge;
  for (std::size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      int a = in.triangles[tris[i]][k], b = in.triangles[tris[i]][(k + 1) % 3];
      by_edge[{std::min(a, b), std::max(a, b)}].push_back(int(i));
    }
  std::vector<int> parent(tris.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = int(i);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& [edge, users] : by_edge)
    for (std::size_t k = 1; k < users.size(); ++k) parent[find(users[k])] = find(users[0]);
  for (std::size_t i = 0; i < tris.size(); ++i)
    if (find(int(i)) != find(0)) return false;
  return true;
}

/// Positions along the axis increase head to end.
bool ordered_along_axis(const ModelInput& in, const Bolt& bolt, const std::vector<int>& tris) {
  double prev = -1e300;
  for (int t : tris) {
    const auto v = corners(in, t);
    const double cx = (v[0][0] + v[1][0] + v[2][0]) / 3, cy = (v[0][1] + v[1][1] + v[2][1]) / 3;
    const double along =
        (cx - bolt.a[0]) * (bolt.b[0] - bolt.a[0]) + (cy - bolt.a[1]) * (bolt.b[1] - bolt.a[1]);
    if (along < prev) return false;
    prev = along;
  }
  return true;
}

// Horizontal, vertical and 30-degree bolts, thin (d = 0.05 < h = 0.5) and
// wide (d = 1.3 = 2.6 h), on a 10 x 10-cell mesh: exactly the brute force.
TEST(BoltMarking, generic_orientations_match_brute_force) {
  const ModelInput in = grid(5.0, 10);
  const double c30 = std::cos(kPi / 6), s30 = std::sin(kPi / 6);
  std::vector<Bolt> bolts;
  for (double d : {0.05, 1.3}) {
    bolts.push_back({{0.3, 2.37}, {4.1, 2.37}, d});                      // horizontal
    bolts.push_back({{1.83, 0.2}, {1.83, 4.6}, d});                      // vertical
    bolts.push_back(bolt_from_head({0.41, 0.33}, {c30, s30}, 4.5, d));   // 30 degrees
    bolts.push_back(bolt_from_head({4.47, 0.61}, {-s30, c30}, 4.0, d));  // 120 degrees
  }
  const BoltMarks marks = mark_bolts(in, bolts);
  for (std::size_t b = 0; b < bolts.size(); ++b) {
    ASSERT_TRUE(generic(in, bolts[b])) << "bolt " << b;
    const std::set<int> expected = brute_force(in, bolts[b]);
    EXPECT_EQ(as_set(marks.triangles[b]), expected) << "bolt " << b;
    EXPECT_EQ(marks.triangles[b].size(), expected.size()) << "bolt " << b << " has duplicates";
    EXPECT_TRUE(ordered_along_axis(in, bolts[b], marks.triangles[b])) << "bolt " << b;
    EXPECT_TRUE(edge_connected(in, marks.triangles[b])) << "bolt " << b;
  }
  // A wide bolt marks more than its thin twin; owners follow the first bolt.
  EXPECT_GT(marks.triangles[4].size(), marks.triangles[0].size());
  for (int t : marks.triangles[0]) EXPECT_EQ(marks.owner[t], 0);
}

// Thin bolt (d = 0.01) on a 4 x 4 unit mesh along y = 2x from (0.25, 0.5) to
// (1.75, 3.5), through the vertex (1, 2). Its centre line enters cell (0,0)'s
// upper triangle (1), both triangles of cell (0,1) (8, 9) and of cell (1,2)
// (18, 19), and cell (1,3)'s lower triangle (26, where it ends). At (1, 2)
// cells (0,1) and (1,2) touch only at the vertex: the rule adds the triangle
// on the left there, cell (0,2)'s lower one (16), which shares an edge with
// both, so the chain stays joined by crack elements.
TEST(BoltMarking, thin_bolt_through_a_vertex) {
  const ModelInput in = grid(4.0, 4);
  const Bolt bolt{{0.25, 0.5}, {1.75, 3.5}, 0.01};
  const BoltMarks marks = mark_bolts(in, {bolt});
  EXPECT_EQ(as_set(marks.triangles[0]), (std::set<int>{1, 8, 9, 16, 18, 19, 26}));
  EXPECT_TRUE(edge_connected(in, marks.triangles[0]));
  // The centre line alone enters 16 nowhere and touches 17 nowhere.
  const auto v16 = corners(in, 16);
  EXPECT_FALSE(segment_enters_triangle(bolt.a, bolt.b, v16[0], v16[1], v16[2]));
  // A segment from the vertex outward enters only the triangles it points into.
  const auto v18 = corners(in, 18), v9 = corners(in, 9);
  EXPECT_TRUE(segment_enters_triangle({1, 2}, {1.5, 3}, v18[0], v18[1], v18[2]));
  EXPECT_FALSE(segment_enters_triangle({1, 2}, {1.5, 3}, v9[0], v9[1], v9[2]));
}

// Along an edge: a thin bolt on the mesh line y = 2 from x = 0.5 to 3.5
// enters no triangle; the triangles above the four edges it runs along (16,
// 18, 20, 22) and those around the inner vertices (1,2), (2,2), (3,2) on its
// left (19, 21) are marked: row 2 without 17 (touches only (0,2), outside
// the bolt) and 23 (touches only (4,2), beyond its end).
// A wide bolt (d = 1, one cell) whose long sides run along y = 2 and y = 3
// marks the same row: long sides on mesh lines touch, the centre line y = 2.5
// enters 16, 18-21, 22, and 17, 23 only touch its ends.
TEST(BoltMarking, bolt_along_an_edge_and_long_sides_on_mesh_lines) {
  const ModelInput in = grid(4.0, 4);
  const BoltMarks thin = mark_bolts(in, {Bolt{{0.5, 2}, {3.5, 2}, 0.01}});
  EXPECT_EQ(as_set(thin.triangles[0]), (std::set<int>{16, 18, 19, 20, 21, 22}));
  EXPECT_TRUE(edge_connected(in, thin.triangles[0]));
  const BoltMarks row = mark_bolts(in, {Bolt{{0.5, 2.5}, {3.5, 2.5}, 1.0}});
  EXPECT_EQ(as_set(row.triangles[0]), (std::set<int>{16, 18, 19, 20, 21, 22}));
  // Reversed direction: the left side is now below y = 2 (row 1).
  const BoltMarks reversed = mark_bolts(in, {Bolt{{3.5, 2}, {0.5, 2}, 0.01}});
  for (int t : reversed.triangles[0]) EXPECT_LT(t, 16) << t;
  EXPECT_EQ(reversed.triangles[0].size(), 6u);
}

// A bolt shorter than a triangle marks the triangle holding it; one that
// ends exactly on an edge does not mark the triangle beyond.
TEST(BoltMarking, end_points_inside_and_on_edges) {
  const ModelInput in = grid(4.0, 4);
  const BoltMarks inside = mark_bolts(in, {Bolt{{0.6, 0.2}, {0.8, 0.3}, 0.01}});
  EXPECT_EQ(as_set(inside.triangles[0]), (std::set<int>{0}));  // cell (0,0), below y = x
  const BoltMarks on_edge = mark_bolts(in, {Bolt{{0.3, 0.7}, {1.0, 0.7}, 0.01}});
  EXPECT_EQ(as_set(on_edge.triangles[0]), (std::set<int>{0, 1}));  // stops on x = 1
}

TEST(BoltMarking, zero_length_bolt_is_refused) {
  EXPECT_THROW(mark_bolts(grid(1, 2), {Bolt{{0, 0}, {0, 0}, 0.1}}), InputError);
}

// 100 bolts (a fan of 3 m bolts) on a 200k-triangle mesh, the size where
// an accidental O(N) per bolt would show (the time is printed for
// docs/benchmarks.md, "Bolt marking"; never asserted). Every marked
// triangle lies on its bolt: a long side of the bolt crosses it, so its
// centroid lies within sqrt(5)/3 h (2/3 of a half-cell triangle's longest
// median) plus d / 2 of the axis segment; each bolt marks at least one triangle per
// cell it crosses (L / h), and its triangles run head to end.
TEST(BoltMarking, hundred_bolts_on_200k_triangles_mark_only_their_corridor) {
  RectangleSpec spec;
  spec.width = spec.height = 40;
  spec.nx = spec.ny = 317;  // 200,978 triangles
  const double h = 40.0 / 317, length = 3.0, d = 0.025;
  const ModelInput in = structured_rectangle(spec, benchmark_rock());
  std::vector<Bolt> bolts;  // radial, heads on a 5 m circle about (20, 20), 3.6 deg apart
  for (int i = 0; i < 100; ++i) {
    const Point2 dir{std::cos(i * 3.6 * kPi / 180), std::sin(i * 3.6 * kPi / 180)};
    bolts.push_back(bolt_from_head({20 + 5 * dir[0], 20 + 5 * dir[1]}, dir, length, d));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const BoltMarks marks = mark_bolts(in, bolts);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("marking: %zu bolts, %zu triangles, %.1f ms\n", bolts.size(), in.triangles.size(),
              1e3 * s);
  ASSERT_EQ(marks.triangles.size(), bolts.size());
  for (std::size_t b = 0; b < bolts.size(); ++b) {
    const Bolt& bolt = bolts[b];
    const double ux = (bolt.b[0] - bolt.a[0]) / length, uy = (bolt.b[1] - bolt.a[1]) / length;
    EXPECT_GE(marks.triangles[b].size(), std::size_t(length / h)) << "bolt " << b;
    double last = -1;
    for (int t : marks.triangles[b]) {
      const auto& v = in.triangles[t];
      const double cx = (in.x[v[0]] + in.x[v[1]] + in.x[v[2]]) / 3 - bolt.a[0];
      const double cy = (in.y[v[0]] + in.y[v[1]] + in.y[v[2]]) / 3 - bolt.a[1];
      const double along = cx * ux + cy * uy;
      const double off = std::hypot(cx - std::clamp(along, 0.0, length) * ux,
                                    cy - std::clamp(along, 0.0, length) * uy);
      EXPECT_LE(off, h * std::sqrt(5.0) / 3 + d / 2) << "bolt " << b << ", triangle " << t;
      EXPECT_GE(along, last) << "bolt " << b << ", triangle " << t;
      last = along;
    }
  }
}

}  // namespace
}  // namespace rockfdem::fdem
