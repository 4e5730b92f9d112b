// The excavation boundary found in the mesh, and the key points on it (see
// rockfdem/mesh/opening.hpp for the rules per shape).
#include "rockfdem/mesh/opening.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh {
namespace {

// Rock triangle edges, oriented as the counter-clockwise triangle runs them
// (rock on the left), whose reverse no rock triangle has.
// The undirected edges are counted in a sorted array (an edge of two rock
// triangles appears twice), not a map: a 420k-triangle mesh has 630k edges,
// and the monitors, the lining and the broken zone each ask.
std::vector<std::array<int, 2>> rock_boundary_edges(const Mesh& m) {
  const auto key = [&](std::size_t t, int k) {
    const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
    return std::pair<int, int>{std::min(a, b), std::max(a, b)};
  };
  // (edge, 3 t + k): one run of equal edges per undirected edge.
  std::vector<std::pair<std::pair<int, int>, std::size_t>> sorted;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == kRock)
      for (int k = 0; k < 3; ++k) sorted.push_back({key(t, k), 3 * t + k});
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> lone(3 * m.n_triangles(), 0);
  for (std::size_t i = 0, j = 0; i < sorted.size(); i = j) {
    while (j < sorted.size() && sorted[j].first == sorted[i].first) ++j;
    if (j - i == 1) lone[sorted[i].second] = 1;
  }
  // In the triangles' order, as the boundary's edge order (and its sums) had it.
  std::vector<std::array<int, 2>> out;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k)
      if (lone[3 * t + k]) out.push_back({m.triangles[t][k], m.triangles[t][(k + 1) % 3]});
  return out;
}

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// Edges grouped into connected loops (union-find on their vertices).
std::map<int, std::vector<std::array<int, 2>>> loops(const Mesh& m,
                                                     const std::vector<std::array<int, 2>>& edges) {
  std::vector<int> parent(m.n_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : edges) parent[find_root(parent, a)] = find_root(parent, b);
  std::map<int, std::vector<std::array<int, 2>>> out;
  for (const auto& e : edges) out[find_root(parent, e[0])].push_back(e);
  return out;
}

// Area and centroid of what a closed loop encloses (Green's theorem); the
// sign of the area is the loop's sense.
void measure(const Mesh& m, OpeningBoundary& b) {
  double twice = 0, sx = 0, sy = 0;
  b.xmin = b.ymin = std::numeric_limits<double>::infinity();
  b.xmax = b.ymax = -std::numeric_limits<double>::infinity();
  for (const auto& [p, q] : b.edges) {
    const double cross = m.x[p] * m.y[q] - m.x[q] * m.y[p];
    twice += cross;
    sx += (m.x[p] + m.x[q]) * cross;
    sy += (m.y[p] + m.y[q]) * cross;
    b.xmin = std::min(b.xmin, m.x[p]), b.xmax = std::max(b.xmax, m.x[p]);
    b.ymin = std::min(b.ymin, m.y[p]), b.ymax = std::max(b.ymax, m.y[p]);
  }
  b.area = twice / 2;
  b.cx = twice != 0 ? sx / (3 * twice) : 0;
  b.cy = twice != 0 ? sy / (3 * twice) : 0;
}

// Parameters t where the line (ox, oy) + t (dx, dy) crosses the boundary.
std::vector<double> line_hits(const Mesh& m, const OpeningBoundary& b, double ox, double oy,
                              double dx, double dy) {
  std::vector<double> hits;
  for (const auto& [p, q] : b.edges) {
    const double ex = m.x[q] - m.x[p], ey = m.y[q] - m.y[p];
    const double den = dx * ey - dy * ex;
    if (den == 0) continue;  // parallel: its end points are hit by the neighbours
    const double wx = m.x[p] - ox, wy = m.y[p] - oy;
    const double s = (wx * dy - wy * dx) / den;  // along the edge
    if (s < 0 || s > 1) continue;
    hits.push_back((wx * ey - wy * ex) / den);
  }
  return hits;
}

// The farthest boundary point along the ray from (ox, oy) in direction
// (dx, dy), which need not be of unit length; `inward` points back at the origin.
KeyPoint farthest_on_ray(const Mesh& m, const OpeningBoundary& b, const std::string& name,
                         double ox, double oy, double dx, double dy) {
  const double len = std::hypot(dx, dy);
  dx /= len, dy /= len;
  double best = -1;
  for (double t : line_hits(m, b, ox, oy, dx, dy)) best = std::max(best, t);
  if (best < 0) best = 0;  // the origin on the boundary itself: no ray leaves it
  return {name, ox + best * dx, oy + best * dy, -dx, -dy};
}

struct Centres {
  double axis_x, axis_y;          ///< the vertical axis (and its point for vault/invert)
  double wall_y;                  ///< height of the wall points
  double shoulder_x, shoulder_y;  ///< origin of the shoulder rays
  double left_dx, left_dy;        ///< direction of the left shoulder ray (mirrored for the right)
};

Centres shape_centres(const OpeningBoundary& b, const TunnelSpec& t) {
  const double xc = (b.xmin + b.xmax) / 2, yc = (b.ymin + b.ymax) / 2;
  const double half_width = (b.xmax - b.xmin) / 2;
  const double diagonal = std::sqrt(0.5);
  switch (t.shape) {
    case TunnelShape::kCircular:
      return {xc, yc, yc, xc, yc, -diagonal, diagonal};
    case TunnelShape::kHorseshoe: {
      const double springline = b.ymax - half_width;  // semicircular arch of radius span/2
      return {xc,        yc,      (springline + b.ymin + t.invert_rise) / 2, xc, springline,
              -diagonal, diagonal};
    }
    case TunnelShape::kArched: {
      const double radius = (t.span * t.span / 4 + t.rise * t.rise) / (2 * t.rise);
      const double springing = b.ymax - t.rise, centre = b.ymax - radius;
      return {xc,
              yc,
              (springing + b.ymin + t.invert_rise) / 2,
              xc,
              centre,
              -half_width,
              springing - centre};
    }
    case TunnelShape::kRectangular:
      return {xc, yc, yc, xc, yc, -half_width, b.ymax - yc};
  }
  return {xc, yc, yc, xc, yc, -diagonal, diagonal};
}

}  // namespace

std::optional<OpeningBoundary> find_opening(const Mesh& m) {
  std::optional<OpeningBoundary> best;
  for (auto& [root, edges] : loops(m, rock_boundary_edges(m))) {
    OpeningBoundary b;
    b.edges = std::move(edges);
    measure(m, b);
    // Openings run clockwise (negative area); the outer boundary counter-clockwise.
    if (b.area < 0 && (!best || -b.area > best->area)) {
      b.area = -b.area;
      best = std::move(b);
    }
  }
  return best;
}

std::vector<KeyPoint> opening_key_points(const Mesh& m, const OpeningBoundary& b,
                                         const TunnelSpec* shape) {
  const double diagonal = std::sqrt(0.5);
  const Centres c =
      shape ? shape_centres(b, *shape) : Centres{b.cx, b.cy, b.cy, b.cx, b.cy, -diagonal, diagonal};
  return {
      farthest_on_ray(m, b, "vault", c.axis_x, c.axis_y, 0, 1),
      farthest_on_ray(m, b, "left_shoulder", c.shoulder_x, c.shoulder_y, c.left_dx, c.left_dy),
      farthest_on_ray(m, b, "right_shoulder", c.shoulder_x, c.shoulder_y, -c.left_dx, c.left_dy),
      farthest_on_ray(m, b, "left_wall", c.axis_x, c.wall_y, -1, 0),
      farthest_on_ray(m, b, "right_wall", c.axis_x, c.wall_y, 1, 0),
      farthest_on_ray(m, b, "invert", c.axis_x, c.axis_y, 0, -1)};
}

bool boundary_matches(const Mesh& m, const OpeningBoundary& b, const TunnelSpec& t,
                      double tolerance) {
  Outline o;
  try {
    o = tunnel_outline(t);
  } catch (const InputError&) {
    return false;  // a spec that builds no outline matches no mesh
  }
  for (const auto& [p, q] : b.edges)
    if (distance_to_outline(o, m.x[p], m.y[p]) > tolerance) return false;
  return !b.edges.empty();
}

}  // namespace rockfdem::mesh
