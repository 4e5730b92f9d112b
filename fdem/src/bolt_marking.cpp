// Marking of bolt triangles (seed eq. 3, rule in bolt_marking.hpp).
//
// The exact test per (segment, triangle) classifies the triangle's vertices
// by the side of the segment's line they lie on, with a small tolerance so
// that "on the line" is decided once per vertex and consistently for both
// triangles sharing it. The line passes through the open triangle only if
// vertices lie strictly on both sides; then the chord it cuts is an open
// interval of the line's parameter, and the segment enters the triangle when
// that interval overlaps [0, 1] by more than the tolerance.
#include "rockfdem/fdem/bolt_marking.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "rockfdem/error.hpp"

namespace rockfdem::fdem {
namespace {

constexpr double kRelTol = 1e-12;

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

struct Box {
  double x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
};

/// The three segments of a bolt (long sides and centre line) and its frame.
struct BoltGeometry {
  Point2 a, b;  // axis
  Point2 u, n;  // unit axis and normal
  double length, half_width;
  std::array<std::array<Point2, 2>, 3> segments;
  Box box;
};

BoltGeometry bolt_geometry(const Bolt& bolt, std::size_t index) {
  BoltGeometry g;
  g.a = bolt.a;
  g.b = bolt.b;
  g.length = std::hypot(bolt.b[0] - bolt.a[0], bolt.b[1] - bolt.a[1]);
  if (!(g.length > 0) || !(bolt.diameter > 0))
    throw InputError("fdem bolts: bolt " + std::to_string(index) + " has length " +
                     std::to_string(g.length) + " m and diameter " + std::to_string(bolt.diameter) +
                     " m; both must be positive");
  g.u = {(bolt.b[0] - bolt.a[0]) / g.length, (bolt.b[1] - bolt.a[1]) / g.length};
  g.n = {-g.u[1], g.u[0]};
  g.half_width = 0.5 * bolt.diameter;
  const double ox = g.half_width * g.n[0], oy = g.half_width * g.n[1];
  g.segments[0] = {g.a, g.b};
  g.segments[1] = {Point2{g.a[0] + ox, g.a[1] + oy}, Point2{g.b[0] + ox, g.b[1] + oy}};
  g.segments[2] = {Point2{g.a[0] - ox, g.a[1] - oy}, Point2{g.b[0] - ox, g.b[1] - oy}};
  g.box = {std::min(g.a[0], g.b[0]) - std::fabs(ox), std::min(g.a[1], g.b[1]) - std::fabs(oy),
           std::max(g.a[0], g.b[0]) + std::fabs(ox), std::max(g.a[1], g.b[1]) + std::fabs(oy)};
  return g;
}

/// Rule (2): centroid strictly inside the bolt rectangle.
bool centroid_inside(const BoltGeometry& g, const Point2& c) {
  const double dx = c[0] - g.a[0], dy = c[1] - g.a[1];
  const double along = dx * g.u[0] + dy * g.u[1];
  const double across = dx * g.n[0] + dy * g.n[1];
  const double tol = kRelTol * g.length;
  return along > tol && along < g.length - tol && std::fabs(across) < g.half_width - tol;
}

/// Uniform grid of triangle bounding boxes (CSR), about one triangle per cell.
struct CellGrid {
  Box box{};
  double cell = 1;
  int nx = 1, ny = 1;
  std::vector<int> start, items;

  int cx(double x) const { return std::clamp(int((x - box.x0) / cell), 0, nx - 1); }
  int cy(double y) const { return std::clamp(int((y - box.y0) / cell), 0, ny - 1); }
};

CellGrid build_grid(const std::vector<Box>& boxes) {
  CellGrid grid;
  grid.box = boxes.front();
  double size_sum = 0;
  for (const Box& b : boxes) {
    grid.box = {std::min(grid.box.x0, b.x0), std::min(grid.box.y0, b.y0),
                std::max(grid.box.x1, b.x1), std::max(grid.box.y1, b.y1)};
    size_sum += std::max(b.x1 - b.x0, b.y1 - b.y0);
  }
  const double w = grid.box.x1 - grid.box.x0, h = grid.box.y1 - grid.box.y0;
  // Cells of about two triangle sizes, but never more cells than triangles.
  grid.cell = std::max(2.0 * size_sum / boxes.size(), std::sqrt(w * h / boxes.size()));
  grid.cell = std::max(grid.cell, 1e-12 * std::max(w, h) + 1e-300);
  grid.nx = std::max(1, int(std::ceil(w / grid.cell)));
  grid.ny = std::max(1, int(std::ceil(h / grid.cell)));
  const std::size_t n_cells = std::size_t(grid.nx) * grid.ny;
  grid.start.assign(n_cells + 1, 0);
  auto for_cells = [&](const Box& b, auto&& f) {
    for (int j = grid.cy(b.y0); j <= grid.cy(b.y1); ++j)
      for (int i = grid.cx(b.x0); i <= grid.cx(b.x1); ++i) f(std::size_t(j) * grid.nx + i);
  };
  for (const Box& b : boxes) for_cells(b, [&](std::size_t c) { ++grid.start[c + 1]; });
  std::partial_sum(grid.start.begin(), grid.start.end(), grid.start.begin());
  grid.items.resize(grid.start.back());
  std::vector<int> fill(grid.start.begin(), grid.start.end() - 1);
  for (std::size_t t = 0; t < boxes.size(); ++t)
    for_cells(boxes[t], [&](std::size_t c) { grid.items[fill[c]++] = int(t); });
  return grid;
}

/// Distance from point p to the segment a-b.
double distance_to_segment(const Point2& p, const BoltGeometry& g) {
  const double dx = p[0] - g.a[0], dy = p[1] - g.a[1];
  const double along = std::clamp(dx * g.u[0] + dy * g.u[1], 0.0, g.length);
  return std::hypot(dx - along * g.u[0], dy - along * g.u[1]);
}

/// Where a triangle's vertices lie relative to the line through p and q:
/// signed distance o (left positive), side snapped to -1/0/+1 with the
/// tolerance, and the parameter t of each vertex's projection along p->q.
struct LineSides {
  bool valid = false;
  std::array<double, 3> o{}, t{};
  std::array<int, 3> side{};
  bool any_left = false, any_right = false;
  double t_tol = 0;  ///< parameter tolerance
};

LineSides line_sides(const Point2& p, const Point2& q, const std::array<Point2, 3>& v) {
  LineSides ls;
  const double len2 = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]);
  const double len = std::sqrt(len2);
  if (!(len > 0)) return ls;
  double size = 0;
  for (int k = 0; k < 3; ++k)
    size = std::max(size, std::hypot(v[k][0] - v[(k + 1) % 3][0], v[k][1] - v[(k + 1) % 3][1]));
  const double tol = kRelTol * std::max(len, size);
  for (int k = 0; k < 3; ++k) {
    ls.o[k] = cross(p, q, v[k]) / len;
    ls.t[k] = ((v[k][0] - p[0]) * (q[0] - p[0]) + (v[k][1] - p[1]) * (q[1] - p[1])) / len2;
    ls.side[k] = ls.o[k] > tol ? 1 : (ls.o[k] < -tol ? -1 : 0);
    ls.any_left = ls.any_left || ls.side[k] > 0;
    ls.any_right = ls.any_right || ls.side[k] < 0;
  }
  ls.t_tol = kRelTol * std::max(1.0, size / len);
  ls.valid = true;
  return ls;
}

/// The centre line's connectivity rules: the triangle lies on the line's
/// left and touches it at a vertex strictly between the ends, or along an
/// edge overlapping the segment.
bool left_of_touching_centre_line(const Point2& p, const Point2& q,
                                  const std::array<Point2, 3>& v) {
  const LineSides ls = line_sides(p, q, v);
  if (!ls.valid || !ls.any_left || ls.any_right) return false;
  double t_lo = 1e300, t_hi = -1e300;
  int on_line = 0;
  for (int k = 0; k < 3; ++k) {
    if (ls.side[k] != 0) continue;
    ++on_line;
    t_lo = std::min(t_lo, ls.t[k]);
    t_hi = std::max(t_hi, ls.t[k]);
    if (ls.t[k] > ls.t_tol && ls.t[k] < 1.0 - ls.t_tol) return true;  // vertex fan
  }
  return on_line == 2 && std::min(t_hi, 1.0) - std::max(t_lo, 0.0) > ls.t_tol;  // edge
}

}  // namespace

bool segment_enters_triangle(const Point2& p, const Point2& q, const Point2& v0, const Point2& v1,
                             const Point2& v2) {
  const LineSides ls = line_sides(p, q, {v0, v1, v2});
  if (!ls.valid || !(ls.any_left && ls.any_right)) return false;  // line misses the interior
  // The chord: crossings of edges with strictly opposite ends, and vertices
  // on the line; as parameters along p->q.
  double t_lo = 1e300, t_hi = -1e300;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    double t = 0;
    if (ls.side[k] == 0) {
      t = ls.t[k];
    } else if (ls.side[k] * ls.side[j] < 0) {
      const double s = ls.o[k] / (ls.o[k] - ls.o[j]);
      t = ls.t[k] + s * (ls.t[j] - ls.t[k]);
    } else {
      continue;
    }
    t_lo = std::min(t_lo, t);
    t_hi = std::max(t_hi, t);
  }
  return std::min(t_hi, 1.0) - std::max(t_lo, 0.0) > ls.t_tol;
}

Bolt bolt_from_head(const Point2& head, const Point2& direction, double length, double diameter) {
  const double norm = std::hypot(direction[0], direction[1]);
  if (!(norm > 0) || !(length > 0))
    throw InputError(
        "fdem bolts: a bolt from its head needs a non-zero direction and a positive "
        "length (got length " +
        std::to_string(length) + " m)");
  const Point2 u{direction[0] / norm, direction[1] / norm};
  return {head, {head[0] + length * u[0], head[1] + length * u[1]}, diameter};
}

namespace {

using Triangle2 = std::array<Point2, 3>;

/// Candidate triangles near bolt g from the grid: bounding boxes overlap
/// and the cell lies within reach of the axis.
std::vector<int> candidates(const CellGrid& grid, const std::vector<Box>& boxes,
                            const BoltGeometry& g, std::vector<std::size_t>& stamp,
                            std::size_t tag) {
  std::vector<int> out;
  const double reach = g.half_width + 0.5 * std::sqrt(2.0) * grid.cell;
  for (int j = grid.cy(g.box.y0); j <= grid.cy(g.box.y1); ++j)
    for (int i = grid.cx(g.box.x0); i <= grid.cx(g.box.x1); ++i) {
      const Point2 centre{grid.box.x0 + (i + 0.5) * grid.cell, grid.box.y0 + (j + 0.5) * grid.cell};
      if (distance_to_segment(centre, g) > reach * (1 + 1e-9)) continue;
      const std::size_t cell = std::size_t(j) * grid.nx + i;
      for (int k = grid.start[cell]; k < grid.start[cell + 1]; ++k) {
        const int t = grid.items[k];
        if (stamp[t] == tag || !boxes[t].overlaps(g.box)) continue;
        stamp[t] = tag;
        out.push_back(t);
      }
    }
  std::sort(out.begin(), out.end());
  return out;
}

double median_edge(const std::vector<Triangle2>& tris) {
  std::vector<double> edges;
  for (const auto& v : tris)
    for (int k = 0; k < 3; ++k)
      edges.push_back(std::hypot(v[k][0] - v[(k + 1) % 3][0], v[k][1] - v[(k + 1) % 3][1]));
  if (edges.empty()) return 0;
  std::nth_element(edges.begin(), edges.begin() + edges.size() / 2, edges.end());
  return edges[edges.size() / 2];
}

/// The marked triangles of one bolt, ordered along its axis.
std::vector<int> mark_one(const BoltGeometry& g, const std::vector<int>& cands,
                          const std::vector<Triangle2>& geo) {
  const auto& centre = g.segments[0];
  std::vector<char> hit(cands.size(), 0);
  std::vector<Triangle2> entered;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const Triangle2& v = geo[i];
    hit[i] = segment_enters_triangle(centre[0], centre[1], v[0], v[1], v[2]) ||
             left_of_touching_centre_line(centre[0], centre[1], v);
    if (hit[i]) entered.push_back(v);
  }
  const bool wide = 2 * g.half_width >= median_edge(entered);
  std::vector<std::pair<double, int>> found;
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const Triangle2& v = geo[i];
    const Point2 c{(v[0][0] + v[1][0] + v[2][0]) / 3, (v[0][1] + v[1][1] + v[2][1]) / 3};
    bool marked = hit[i];
    if (wide && !marked) {
      marked = centroid_inside(g, c);
      for (int s = 1; s < 3 && !marked; ++s)
        marked = segment_enters_triangle(g.segments[s][0], g.segments[s][1], v[0], v[1], v[2]);
    }
    if (marked) found.push_back({(c[0] - g.a[0]) * g.u[0] + (c[1] - g.a[1]) * g.u[1], cands[i]});
  }
  std::sort(found.begin(), found.end());
  std::vector<int> out;
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

}  // namespace

BoltMarks mark_bolts(const std::vector<double>& x, const std::vector<double>& y,
                     const std::vector<std::array<int, 3>>& triangles,
                     const std::vector<Bolt>& bolts) {
  BoltMarks marks;
  marks.triangles.resize(bolts.size());
  marks.owner.assign(triangles.size(), -1);
  if (triangles.empty() || bolts.empty()) return marks;
  std::vector<Box> boxes(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    boxes[t] = {
        std::min({x[tri[0]], x[tri[1]], x[tri[2]]}), std::min({y[tri[0]], y[tri[1]], y[tri[2]]}),
        std::max({x[tri[0]], x[tri[1]], x[tri[2]]}), std::max({y[tri[0]], y[tri[1]], y[tri[2]]})};
  }
  const CellGrid grid = build_grid(boxes);
  std::vector<std::size_t> stamp(triangles.size(), 0);  // last bolt (+1) that listed t
  for (std::size_t b = 0; b < bolts.size(); ++b) {
    const BoltGeometry g = bolt_geometry(bolts[b], b);
    const std::vector<int> cands = candidates(grid, boxes, g, stamp, b + 1);
    std::vector<Triangle2> geo(cands.size());
    for (std::size_t i = 0; i < cands.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        const int v = triangles[cands[i]][k];
        geo[i][k] = {x[v], y[v]};
      }
    marks.triangles[b] = mark_one(g, cands, geo);
    for (int t : marks.triangles[b])
      if (marks.owner[t] < 0) marks.owner[t] = int(b);
  }
  return marks;
}

BoltMarks mark_bolts(const ModelInput& input, const std::vector<Bolt>& bolts) {
  return mark_bolts(input.x, input.y, input.triangles, bolts);
}

}  // namespace rockfdem::fdem
