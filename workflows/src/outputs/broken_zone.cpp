#include "outputs/broken_zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "rockfdem/mesh/opening.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {
namespace {

using Segment = std::array<double, 4>;  // x0, y0, x1, y1

double distance_to_segment(double px, double py, const Segment& s) {
  const double dx = s[2] - s[0], dy = s[3] - s[1], len2 = dx * dx + dy * dy;
  const double t =
      len2 > 0 ? std::clamp(((px - s[0]) * dx + (py - s[1]) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - s[0] - t * dx, py - s[1] - t * dy);
}

double nearest(double px, double py, const std::vector<Segment>& segs) {
  double d = std::numeric_limits<double>::infinity();
  for (const Segment& s : segs) d = std::min(d, distance_to_segment(px, py, s));
  return d;
}

Segment segment(const mesh::Mesh& m, int a, int b) { return {m.x[a], m.y[a], m.x[b], m.y[b]}; }

// The opening's boundary as mesh/ finds it (the rock's inner boundary,
// against core, lining or nothing): a user's .msh need not tag it.
std::vector<Segment> excavation_boundary(const mesh::Mesh& m) {
  std::vector<Segment> out;
  if (const auto b = mesh::find_opening(m))
    for (const auto& e : b->edges) out.push_back(segment(m, e[0], e[1]));
  return out;
}

// The broken crack elements between two rock triangles of the fracture
// zone, no bolt on either side (bolts carry crack elements of their own,
// beyond the zone too), as segments of the reference configuration; with
// `grouted` (per crack element, or empty) also those flagged there.
std::vector<Segment> broken_rock_cracks(const fdem::Engine& e, const mesh::Mesh& m,
                                        const std::vector<char>& bolt_triangle,
                                        const std::vector<char>& grouted = {}) {
  const auto in_zone = [&](int tri) {
    return m.zone[tri] == mesh::kRock && m.fracture[tri] &&
           (bolt_triangle.empty() || !bolt_triangle[tri]);
  };
  const std::vector<int>& vertex = e.node_vertex();
  std::vector<Segment> out;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const bool was_grouted = c < grouted.size() && grouted[c];
    if (!was_grouted && e.crack_state(c) != fdem::CrackState::kBroken) continue;
    const auto t = e.crack_triangles(c);
    if (!in_zone(t[0]) || !in_zone(t[1])) continue;
    const auto nodes = e.crack_nodes(c);
    out.push_back(segment(m, vertex[nodes[0]], vertex[nodes[1]]));
  }
  return out;
}

// Distance from a segment to a half-line: 0 where they cross, else the
// least of the endpoints' distances to the half-line and the origin's to
// the segment.
double distance_to_ray(const Segment& s, const Ray& r) {
  const double far = 1e6;  // longer than any model: the half-line as a segment
  const Segment ray{r.x, r.y, r.x + far * r.dx, r.y + far * r.dy};
  const auto cross = [](double ax, double ay, double bx, double by) { return ax * by - ay * bx; };
  const double ex = s[2] - s[0], ey = s[3] - s[1];
  const double den = cross(ex, ey, ray[2] - ray[0], ray[3] - ray[1]);
  if (den != 0) {
    const double u = cross(ray[0] - s[0], ray[1] - s[1], ray[2] - ray[0], ray[3] - ray[1]) / den;
    const double v = cross(ray[0] - s[0], ray[1] - s[1], ex, ey) / den;
    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) return 0;
  }
  return std::min({distance_to_segment(s[0], s[1], ray), distance_to_segment(s[2], s[3], ray),
                   distance_to_segment(r.x, r.y, s)});
}

}  // namespace

std::vector<Segment> fracture_zone_edge(const mesh::Mesh& m) {
  if (m.fracture.empty()) return {};
  std::map<std::pair<int, int>, int> sides;  // edge -> bit 1: fracture side, bit 2: other rock
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    const auto& v = m.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = v[k], b = v[(k + 1) % 3];
      sides[{std::min(a, b), std::max(a, b)}] |= m.fracture[t] ? 1 : 2;
    }
  }
  std::vector<Segment> out;
  for (const auto& [edge, bits] : sides)
    if (bits == 3) out.push_back(segment(m, edge.first, edge.second));
  return out;
}

Resolution resolution_at(const Scene& scene, double h) {
  Resolution r;
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  if (rock.tensile_strength > 0 && rock.fracture_energy_I > 0)
    r.l_ch = rock.young * rock.fracture_energy_I / (rock.tensile_strength * rock.tensile_strength);
  r.h = h;
  r.ratio = r.l_ch > 0 ? r.h / r.l_ch : 0.0;
  return r;
}

Resolution fracture_resolution(const Scene& scene, const mesh::Mesh* m) {
  double sum = 0;
  long n = 0;
  if (m)
    for (std::size_t t = 0; t < m->n_triangles(); ++t) {
      if (m->fracture.empty() || !m->fracture[t]) continue;
      const auto& v = m->triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int a = v[k], b = v[(k + 1) % 3];
        sum += std::hypot(m->x[b] - m->x[a], m->y[b] - m->y[a]);
        ++n;
      }
    }
  return resolution_at(scene, n > 0 ? sum / double(n) : scene.mesh.size.size_near);
}

BrokenZone broken_zone(const fdem::Engine& e, const mesh::Mesh& m, double h,
                       const std::vector<char>& bolt_triangle) {
  BrokenZone z;
  const std::vector<Segment> opening = excavation_boundary(m);
  const std::vector<Segment> edge = fracture_zone_edge(m);
  if (opening.empty()) return z;
  for (const Segment& s : edge) z.zone_depth = std::max(z.zone_depth, nearest(s[0], s[1], opening));
  double clearance = std::numeric_limits<double>::infinity();
  for (const Segment& s : broken_rock_cracks(e, m, bolt_triangle)) {
    const double px = (s[0] + s[2]) / 2, py = (s[1] + s[3]) / 2;
    ++z.broken;
    z.depth = std::max(z.depth, nearest(px, py, opening));
    if (!edge.empty()) clearance = std::min(clearance, nearest(px, py, edge));
  }
  if (z.broken > 0 && std::isfinite(clearance)) {
    z.clearance = clearance;
    z.at_edge = clearance < kEdgeElements * h;
  }
  return z;
}

std::vector<char> bolt_triangles(const fdem::BoltPlan* bolts, std::size_t n_triangles) {
  std::vector<char> out;
  if (!bolts || bolts->specs.empty()) return out;
  out.assign(n_triangles, 0);
  for (const std::vector<int>& owned : bolts->owned)
    for (int t : owned) out[std::size_t(t)] = 1;
  return out;
}

std::vector<double> broken_depth_along_rays(const fdem::Engine& e, const mesh::Mesh& m,
                                            const std::vector<Ray>& rays, double half_width,
                                            const std::vector<char>& bolt_triangle,
                                            const std::vector<char>& grouted) {
  std::vector<double> depth(rays.size(), 0.0);
  for (const Segment& s : broken_rock_cracks(e, m, bolt_triangle, grouted))
    for (std::size_t i = 0; i < rays.size(); ++i)
      if (distance_to_ray(s, rays[i]) <= half_width) {
        const double t = ((s[0] + s[2]) / 2 - rays[i].x) * rays[i].dx +
                         ((s[1] + s[3]) / 2 - rays[i].y) * rays[i].dy;
        depth[i] = std::max(depth[i], t);
      }
  return depth;
}

}  // namespace rockfdem::workflows
