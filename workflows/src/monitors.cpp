#include "monitors.hpp"

#include <cmath>
#include <limits>

#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {
namespace {

// Points on the outline: crown, shoulders at 45 degrees of the arch (the
// wall top for flat-roofed shapes), walls at mid-height, invert.
std::vector<Monitor> monitor_points(const mesh::TunnelSpec& t) {
  const mesh::HalfExtent h = mesh::opening_half_extent(t);
  const double hx = h.hx, hy = h.hy;
  double shoulder_x = hx, shoulder_y = hy;
  if (t.shape == mesh::TunnelShape::kCircular || t.shape == mesh::TunnelShape::kHorseshoe) {
    const double r = t.shape == mesh::TunnelShape::kCircular ? t.radius : t.span / 2;
    const double cy = hy - r;
    shoulder_x = r * std::sqrt(0.5);
    shoulder_y = cy + r * std::sqrt(0.5);
  } else if (t.shape == mesh::TunnelShape::kArched) {
    shoulder_y = hy - t.rise;  // the springing line
  }
  const double wall_y = t.shape == mesh::TunnelShape::kCircular ? 0.0 : (shoulder_y - hy) / 2;
  return {{"vault", 0, hy},
          {"left_shoulder", -shoulder_x, shoulder_y},
          {"right_shoulder", shoulder_x, shoulder_y},
          {"left_wall", -hx, wall_y},
          {"right_wall", hx, wall_y},
          {"invert", 0, -hy}};
}

}  // namespace

std::vector<Monitor> tunnel_monitors(const mesh::TunnelSpec& t, const mesh::Mesh& m,
                                     const fdem::Engine& e) {
  std::vector<Monitor> monitors = monitor_points(t);
  const std::vector<int>& vertex = e.node_vertex();
  std::vector<double> best(monitors.size(), std::numeric_limits<double>::max());
  // Only nodes of rock triangles: the core goes, the lining is support.
  for (std::size_t tri = 0; tri < e.n_triangles(); ++tri) {
    if (m.zone[tri] != mesh::kRock) continue;
    for (int node : e.triangle_nodes(tri)) {
      const int v = vertex[node];
      for (std::size_t k = 0; k < monitors.size(); ++k) {
        const double d = std::hypot(m.x[v] - monitors[k].x, m.y[v] - monitors[k].y);
        if (d < best[k] || (d == best[k] && node < monitors[k].node)) {
          best[k] = d;
          monitors[k].node = node;
        }
      }
    }
  }
  return monitors;
}

std::array<double, 2> monitor_displacement(const fdem::Engine& e, const Monitor& mon,
                                           const std::vector<double>& implicit_ux,
                                           const std::vector<double>& implicit_uy) {
  std::array<double, 2> u = e.displacement(mon.node);
  const int v = e.node_vertex()[mon.node];
  if (!implicit_ux.empty()) {
    u[0] += implicit_ux[v];
    u[1] += implicit_uy[v];
  }
  return u;
}

}  // namespace rockfdem::workflows
