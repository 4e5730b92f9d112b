#include "outputs/picture_outlines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "outputs/broken_zone.hpp"
#include "rockfdem/mesh/opening.hpp"

namespace rockfdem::workflows {
namespace {

using Segment = std::array<double, 4>;

// One engine node per mesh vertex of a rock triangle: where the opening's
// boundary vertices move with the rock.
std::vector<int> rock_node_of_vertex(const fdem::Engine& e, const mesh::Mesh& m) {
  std::vector<int> node(m.n_vertices(), -1);
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    const auto n = e.triangle_nodes(t);
    for (int k = 0; k < 3; ++k)
      if (node[m.triangles[t][k]] < 0) node[m.triangles[t][k]] = n[k];
  }
  return node;
}

std::string factor_text(double k) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", k);
  return s;
}

}  // namespace

plots::PictureLines fracture_zone_lines(const mesh::Mesh& m, double dash) {
  return {"fracture zone edge", {0.15, 0.15, 0.15}, 2, dashed(fracture_zone_edge(m), dash)};
}

double outline_magnification(double u_max, double span) {
  if (!(u_max > 0) || !(span > 0)) return 1;
  const double k = 0.1 * span / u_max;
  if (k <= 1) return 1;
  const double p = std::pow(10.0, std::floor(std::log10(k)));
  const double f = k / p;
  return (f >= 5 ? 5 : f >= 2 ? 2 : 1) * p;
}

std::optional<plots::PictureLines> deformed_opening(const fdem::Engine& e, const mesh::Mesh& m,
                                                    const NodeDisplacement& u) {
  const std::optional<mesh::OpeningBoundary> b = mesh::find_opening(m);
  if (!b) return std::nullopt;
  const std::vector<int> node = rock_node_of_vertex(e, m);
  const auto moved = [&](int v) { return node[v] < 0 ? std::array<double, 2>{0, 0} : u(node[v]); };
  double u_max = 0;
  for (const auto& edge : b->edges) {
    const auto d = moved(edge[0]);
    u_max = std::max(u_max, std::hypot(d[0], d[1]));
  }
  if (!(u_max > 0)) return std::nullopt;
  const double k = outline_magnification(u_max, b->xmax - b->xmin);
  plots::PictureLines out{"opening deformed x" + factor_text(k), {0.85, 0.0, 0.85}, 3, {}};
  for (const auto& edge : b->edges) {
    const auto d0 = moved(edge[0]), d1 = moved(edge[1]);
    out.segments.push_back({m.x[edge[0]] + k * d0[0], m.y[edge[0]] + k * d0[1],
                            m.x[edge[1]] + k * d1[0], m.y[edge[1]] + k * d1[1]});
  }
  return out;
}

std::vector<Segment> dashed(const std::vector<Segment>& segments, double dash) {
  if (!(dash > 0)) return segments;
  std::vector<Segment> out;
  double phase = 0;  // along the current dash-and-gap period [m]
  for (const Segment& s : segments) {
    const double dx = s[2] - s[0], dy = s[3] - s[1], length = std::hypot(dx, dy);
    double at = 0;
    while (length - at > 1e-9 * dash) {  // no sliver of rounding at the end
      const bool on = phase < dash;
      const double step = std::min(length - at, (on ? dash : 2 * dash) - phase);
      if (on)
        out.push_back({s[0] + dx * at / length, s[1] + dy * at / length,
                       s[0] + dx * (at + step) / length, s[1] + dy * (at + step) / length});
      at += step;
      phase = std::fmod(phase + step, 2 * dash);
    }
  }
  return out;
}

}  // namespace rockfdem::workflows
