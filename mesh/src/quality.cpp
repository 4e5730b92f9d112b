// Triangle quality. The smallest altitude sets the explicit engine's stable
// time step; the smallest angle says how well shaped the worst element is.
#include <algorithm>
#include <cmath>
#include <limits>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::mesh {

double signed_area(const Mesh& m, std::size_t t) {
  const auto& [a, b, c] = m.triangles[t];
  return 0.5 * ((m.x[b] - m.x[a]) * (m.y[c] - m.y[a]) - (m.x[c] - m.x[a]) * (m.y[b] - m.y[a]));
}

namespace {

struct TriangleShape {
  double area, altitude, min_angle;
};

// Altitude onto the longest side = 2A / longest; the smallest angle is
// opposite the shortest side (law of cosines, clamped against rounding).
TriangleShape shape(const Mesh& m, std::size_t t) {
  const auto& v = m.triangles[t];
  double len[3];
  for (int k = 0; k < 3; ++k) {
    const int p = v[(k + 1) % 3], q = v[(k + 2) % 3];
    len[k] = std::hypot(m.x[q] - m.x[p], m.y[q] - m.y[p]);
  }
  std::sort(len, len + 3);
  const double area = std::abs(signed_area(m, t));
  const double cos_min = std::clamp(
      (len[1] * len[1] + len[2] * len[2] - len[0] * len[0]) / (2 * len[1] * len[2]), -1.0, 1.0);
  return {area, len[2] > 0 ? 2 * area / len[2] : 0, std::acos(cos_min)};
}

}  // namespace

MeshQuality measure_quality(const Mesh& m) {
  constexpr double kDeg = 180 / 3.14159265358979323846;
  MeshQuality q;
  if (m.triangles.empty()) return q;
  q.min_altitude = q.min_angle_deg = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const TriangleShape s = shape(m, t);
    q.total_area += s.area;
    q.min_altitude = std::min(q.min_altitude, s.altitude);
    q.min_angle_deg = std::min(q.min_angle_deg, s.min_angle * kDeg);
  }
  return q;
}

}  // namespace rockfdem::mesh
