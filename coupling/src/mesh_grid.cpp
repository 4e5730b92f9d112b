#include "rockfdem/coupling/mesh_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rockfdem::coupling {
namespace {

struct TriangleQuality {
  double area, min_angle_deg, min_altitude;
};

TriangleQuality quality(const mesh::Mesh& m, const std::array<int, 3>& t) {
  double len[3];
  for (int i = 0; i < 3; ++i) {
    const int a = t[i], b = t[(i + 1) % 3];
    len[i] = std::hypot(m.x[b] - m.x[a], m.y[b] - m.y[a]);
  }
  const double area = 0.5 * ((m.x[t[1]] - m.x[t[0]]) * (m.y[t[2]] - m.y[t[0]]) -
                             (m.x[t[2]] - m.x[t[0]]) * (m.y[t[1]] - m.y[t[0]]));
  const double longest = std::max({len[0], len[1], len[2]});
  double min_angle = 180;
  for (int i = 0; i < 3; ++i) {
    // Angle opposite edge i from the law of cosines.
    const double a = len[i], b = len[(i + 1) % 3], c = len[(i + 2) % 3];
    const double cosine = std::clamp((b * b + c * c - a * a) / (2 * b * c), -1.0, 1.0);
    min_angle = std::min(min_angle, std::acos(cosine) * 180.0 / M_PI);
  }
  return {area, min_angle, 2 * std::abs(area) / longest};
}

}  // namespace

VtkGrid mesh_grid(const mesh::Mesh& m) {
  VtkGrid g;
  g.x = m.x;
  g.y = m.y;
  g.triangles = m.triangles;
  for (const mesh::TaggedEdge& e : m.edges) g.lines.push_back({e.a, e.b});

  std::vector<std::int32_t> zone(m.zone.begin(), m.zone.end());
  std::vector<std::int32_t> fracture(m.fracture.begin(), m.fracture.end());
  std::vector<double> area, angle, altitude;
  for (const auto& t : m.triangles) {
    const TriangleQuality q = quality(m, t);
    area.push_back(q.area);
    angle.push_back(q.min_angle_deg);
    altitude.push_back(q.min_altitude);
  }
  std::vector<std::int32_t> tag;
  for (const mesh::TaggedEdge& e : m.edges) tag.push_back(e.tag);

  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("zone", std::move(zone))));
  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("fracture", std::move(fracture))));
  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("area", std::move(area))));
  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("min_angle_deg", std::move(angle))));
  g.cell_arrays.push_back(
      triangle_cell_array(g, scalar_array("min_altitude", std::move(altitude))));
  g.cell_arrays.push_back(line_cell_array(g, scalar_array("edge_tag", std::move(tag))));
  return g;
}

}  // namespace rockfdem::coupling
