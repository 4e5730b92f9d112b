// Lining section forces (see lining_forces.hpp and docs/support.md).
#include "outputs/lining_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "rockfdem/mesh/opening.hpp"

namespace rockfdem::workflows {
namespace {

using Edge = std::array<int, 2>;

double distance_to_edge(const mesh::Mesh& m, const Edge& e, double x, double y) {
  const double ax = m.x[e[0]], ay = m.y[e[0]];
  const double ex = m.x[e[1]] - ax, ey = m.y[e[1]] - ay;
  const double len2 = ex * ex + ey * ey;
  const double s = len2 > 0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(x - ax - s * ex, y - ay - s * ey);
}

std::pair<int, int> undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// The lining's boundary edges that do not face the rock: its inner face
// (against the core, or free once the core is gone).
std::vector<Edge> inner_edges(const mesh::Mesh& m, const std::vector<Edge>& outer) {
  std::map<std::pair<int, int>, int> count;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == mesh::kLining)
      for (int k = 0; k < 3; ++k)
        ++count[undirected(m.triangles[t][k], m.triangles[t][(k + 1) % 3])];
  std::set<std::pair<int, int>> facing_rock;
  for (const Edge& e : outer) facing_rock.insert(undirected(e[0], e[1]));
  std::vector<Edge> out;
  for (const auto& [e, n] : count)
    if (n == 1 && !facing_rock.count(e)) out.push_back({e.first, e.second});
  return out;
}

// The segment of one outer edge (running clockwise, rock on its left):
// its frame, and the thickness as the distance from the edge's midpoint to
// the inner face (normal to the outer edge on the ring's smooth parts).
LiningSegment segment_of(const mesh::Mesh& m, const Edge& e, const std::vector<Edge>& inner) {
  const double px = (m.x[e[0]] + m.x[e[1]]) / 2, py = (m.y[e[0]] + m.y[e[1]]) / 2;
  const double ex = m.x[e[1]] - m.x[e[0]], ey = m.y[e[1]] - m.y[e[0]], len = std::hypot(ex, ey);
  LiningSegment s;
  s.tx = -ex / len, s.ty = -ey / len;  // counter-clockwise
  s.nx = -ey / len, s.ny = ex / len;   // left of the edge: the rock
  s.thickness = std::numeric_limits<double>::infinity();
  for (const Edge& f : inner) s.thickness = std::min(s.thickness, distance_to_edge(m, f, px, py));
  s.x = px - s.thickness / 2 * s.nx;
  s.y = py - s.thickness / 2 * s.ny;
  return s;
}

// Each lining triangle goes to the segment whose outer edge is nearest its
// centroid; its offset n is measured along that segment's normal.
void assign_triangles(const mesh::Mesh& m, const std::vector<Edge>& outer,
                      std::vector<LiningSegment>& segs) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kLining) continue;
    const auto& v = m.triangles[t];
    const double cx = (m.x[v[0]] + m.x[v[1]] + m.x[v[2]]) / 3;
    const double cy = (m.y[v[0]] + m.y[v[1]] + m.y[v[2]]) / 3;
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < outer.size(); ++i) {
      const double d = distance_to_edge(m, outer[i], cx, cy);
      if (d < best_d) best_d = d, best = i;
    }
    LiningSegment& s = segs[best];
    s.triangles.push_back(int(t));
    s.area.push_back(std::abs(mesh::signed_area(m, t)));
    s.offset.push_back((cx - s.x) * s.nx + (cy - s.y) * s.ny);
  }
}

// Counter-clockwise from 0 deg, with the arc length along the mid-line.
void order_segments(LiningGeometry& g) {
  for (LiningSegment& s : g.segments) {
    const double a = std::atan2(s.y - g.cy, s.x - g.cx) * 180 / M_PI;
    s.angle_deg = a < 0 ? a + 360 : a;
  }
  std::sort(
      g.segments.begin(), g.segments.end(),
      [](const LiningSegment& a, const LiningSegment& b) { return a.angle_deg < b.angle_deg; });
  const std::size_t n = g.segments.size();
  for (std::size_t i = 1; i < n; ++i) {
    const LiningSegment &a = g.segments[i - 1], &b = g.segments[i];
    g.segments[i].arc_m = a.arc_m + std::hypot(b.x - a.x, b.y - a.y);
  }
  const double cos_turn = std::cos(kCornerTurnDeg * M_PI / 180);
  for (std::size_t i = 0; i < n && n > 1; ++i) {
    LiningSegment &a = g.segments[i], &b = g.segments[(i + 1) % n];
    if (a.tx * b.tx + a.ty * b.ty < cos_turn) a.corner = b.corner = true;
  }
}

// Compression-positive stress components in a segment's frame.
double s_tt(const LiningSegment& s, const std::array<double, 3>& sig) {
  return -(sig[0] * s.tx * s.tx + sig[1] * s.ty * s.ty + 2 * sig[2] * s.tx * s.ty);
}
double s_nt(const LiningSegment& s, const std::array<double, 3>& sig) {
  return -(sig[0] * s.tx * s.nx + sig[1] * s.ty * s.ny + sig[2] * (s.tx * s.ny + s.ty * s.nx));
}

// Slope of the area-weighted least-squares line s_tt(n) over the triangles
// of the segments `ids` (each sample in its own segment's frame); NaN when
// their centroids hardly spread through the thickness.
double bending_slope(const LiningGeometry& g, const std::vector<std::size_t>& ids,
                     const std::vector<std::array<double, 3>>& stress) {
  double w = 0, wn = 0, ws = 0, wnn = 0, wns = 0;
  for (std::size_t i : ids) {
    const LiningSegment& s = g.segments[i];
    for (std::size_t k = 0; k < s.triangles.size(); ++k) {
      const double a = s.area[k], n = s.offset[k], v = s_tt(s, stress[s.triangles[k]]);
      w += a, wn += a * n, ws += a * v, wnn += a * n * n, wns += a * n * v;
    }
  }
  if (w <= 0) return std::nan("");
  const double var = wnn / w - (wn / w) * (wn / w), cov = wns / w - (wn / w) * (ws / w);
  const double t = g.segments[ids.front()].thickness;
  return var > 0.0025 * t * t ? cov / var : std::nan("");
}

}  // namespace

std::optional<LiningGeometry> lining_geometry(const mesh::Mesh& m) {
  if (std::find(m.zone.begin(), m.zone.end(), int(mesh::kLining)) == m.zone.end()) return {};
  const std::optional<mesh::OpeningBoundary> opening = mesh::find_opening(m);
  if (!opening) return {};
  const std::vector<Edge>& outer = opening->edges;
  const std::vector<Edge> inner = inner_edges(m, outer);
  if (inner.empty()) return {};
  LiningGeometry g;
  g.cx = opening->cx, g.cy = opening->cy;
  for (const Edge& e : outer) g.segments.push_back(segment_of(m, e, inner));
  assign_triangles(m, outer, g.segments);
  order_segments(g);
  return g;
}

std::vector<SectionForces> lining_forces(const LiningGeometry& g,
                                         const std::vector<std::array<double, 3>>& stress) {
  const std::size_t n = g.segments.size();
  std::vector<SectionForces> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const LiningSegment& s = g.segments[i];
    double w = 0, wt = 0, wv = 0;
    for (std::size_t k = 0; k < s.triangles.size(); ++k) {
      w += s.area[k];
      wt += s.area[k] * s_tt(s, stress[s.triangles[k]]);
      wv += s.area[k] * s_nt(s, stress[s.triangles[k]]);
    }
    const double t = s.thickness;
    // The slope over the segment and its two neighbours (about three
    // element sizes): single constant-strain triangles scatter in bending.
    const double slope =
        bending_slope(g,
                      n > 2 ? std::vector<std::size_t>{(i + n - 1) % n, i, (i + 1) % n}
                            : std::vector<std::size_t>{i},
                      stress);
    out[i].thrust = w > 0 ? t * wt / w : 0;
    out[i].shear = w > 0 ? t * wv / w : 0;
    out[i].moment = std::isnan(slope) ? 0 : slope * t * t * t / 12;
  }
  return out;
}

double safety_factor(const SectionForces& f, double thickness, const ShotcreteStrength& s) {
  const double mean = f.thrust / thickness;
  const double bending = 6 * std::abs(f.moment) / (thickness * thickness);
  double fs = std::numeric_limits<double>::infinity();
  if (mean + bending > 0) fs = s.compressive / (mean + bending);
  if (mean - bending < 0) fs = std::min(fs, s.tensile / (bending - mean));
  return fs;
}

std::vector<std::array<double, 2>> capacity_envelope(double thickness, const ShotcreteStrength& s,
                                                     double fs) {
  const double c = s.compressive / fs, t = s.tensile / fs;
  const double m = (c + t) * thickness * thickness / 12, n = (c - t) * thickness / 2;
  return {{0, c * thickness}, {m, n}, {0, -t * thickness}, {-m, n}, {0, c * thickness}};
}

std::string lining_csv(long step, const LiningGeometry& g, const std::vector<SectionForces>& f,
                       const std::vector<double>* safety_factors) {
  std::string csv =
      "step,segment,angle_deg,arc_m,x_m,y_m,thickness_m,thrust_kN_per_m,moment_kNm_per_m,"
      "shear_kN_per_m,utilisation,safety_factor,corner\n";
  char line[320];
  for (std::size_t i = 0; i < g.segments.size(); ++i) {
    const LiningSegment& s = g.segments[i];
    std::snprintf(line, sizeof line, "%ld,%zu,%.4f,%.4f,%.5f,%.5f,%.5f,%.6g,%.6g,%.6g", step, i,
                  s.angle_deg, s.arc_m, s.x, s.y, s.thickness, f[i].thrust / 1e3, f[i].moment / 1e3,
                  f[i].shear / 1e3);
    csv += line;
    if (safety_factors) {
      const double fs = (*safety_factors)[i];
      std::snprintf(line, sizeof line, ",%.6g,%.6g", 1 / fs, fs);
      csv += line;
    } else {
      csv += ",,";
    }
    csv += s.corner ? ",1\n" : ",0\n";
  }
  return csv;
}

}  // namespace rockfdem::workflows
