// Joint traces made meshable: clipped to the rock (the domain rectangle,
// out of the convex opening, exactly: intersections with the outline's
// segments and arcs), then slivers removed at size_near / 4 (joints.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "rockfdem/mesh/constants.hpp"
#include "rockfdem/mesh/joints.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh {
namespace {

struct Point {
  double x, y;
};

Point at(const JointTrace& t, double s) {
  return {t.x0 + s * (t.x1 - t.x0), t.y0 + s * (t.y1 - t.y0)};
}

JointTrace piece(const JointTrace& t, double s0, double s1) {
  const Point a = at(t, s0), b = at(t, s1);
  return {a.x, a.y, b.x, b.y};
}

/// Parameters s in (0, 1) where trace t crosses segment (a, b).
void cross_segment(const JointTrace& t, Point a, Point b, std::vector<double>& s) {
  const double dx = t.x1 - t.x0, dy = t.y1 - t.y0, ex = b.x - a.x, ey = b.y - a.y;
  const double den = dx * ey - dy * ex;
  if (den == 0) return;
  const double fx = a.x - t.x0, fy = a.y - t.y0;
  const double u = (fx * ey - fy * ex) / den, v = (fx * dy - fy * dx) / den;
  if (u > 0 && u < 1 && v >= 0 && v <= 1) s.push_back(u);
}

/// Parameters s in (0, 1) where trace t crosses arc p.
void cross_arc(const JointTrace& t, const OutlinePiece& p, std::vector<double>& s) {
  const double dx = t.x1 - t.x0, dy = t.y1 - t.y0, fx = t.x0 - p.cx, fy = t.y0 - p.cy;
  const double a = dx * dx + dy * dy, b = 2 * (fx * dx + fy * dy);
  const double c = fx * fx + fy * fy - p.radius * p.radius;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return;
  for (double sign : {-1.0, 1.0}) {
    const double u = (-b + sign * std::sqrt(disc)) / (2 * a);
    if (!(u > 0 && u < 1)) continue;
    const Point q = at(t, u);
    double ang = std::atan2(q.y - p.cy, q.x - p.cx);
    while (ang < p.a0 - 1e-12) ang += 2 * kPi;
    if (ang <= p.a1 + 1e-12) s.push_back(u);
  }
}

/// The parts of t outside the (convex) opening.
std::vector<JointTrace> outside_opening(const JointTrace& t, const Outline& o) {
  std::vector<double> s{0.0, 1.0};
  for (const OutlinePiece& p : o.pieces) {
    if (p.is_arc)
      cross_arc(t, p, s);
    else
      cross_segment(t, {p.x0, p.y0}, {p.x1, p.y1}, s);
  }
  std::sort(s.begin(), s.end());
  std::vector<JointTrace> out;
  double start = -1;  // start of the current outside run
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const Point mid = at(t, 0.5 * (s[i] + s[i + 1]));
    const bool outside = s[i + 1] > s[i] && !inside_outline(o, mid.x, mid.y);
    if (outside && start < 0) start = s[i];
    if (!outside && start >= 0 && s[i + 1] > s[i]) {
      out.push_back(piece(t, start, s[i]));
      start = -1;
    }
  }
  if (start >= 0) out.push_back(piece(t, start, 1.0));
  return out;
}

/// Liang-Barsky clip of t to the domain; false when nothing is left.
bool clip_to_domain(const DomainSpec& d, JointTrace& t) {
  const JointRegion r{d.center_x - d.width / 2, d.center_y - d.height / 2, d.center_x + d.width / 2,
                      d.center_y + d.height / 2};
  const double dx = t.x1 - t.x0, dy = t.y1 - t.y0;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {t.x0 - r.xmin, r.xmax - t.x0, t.y0 - r.ymin, r.ymax - t.y0};
  double s0 = 0, s1 = 1;
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double s = q[i] / p[i];
    if (p[i] < 0)
      s0 = std::max(s0, s);
    else
      s1 = std::min(s1, s);
  }
  if (!(s1 > s0)) return false;
  t = piece(t, s0, s1);
  return true;
}

double distance_to_segment(Point p, const JointTrace& t, double* s_out = nullptr) {
  const double dx = t.x1 - t.x0, dy = t.y1 - t.y0, len2 = dx * dx + dy * dy;
  double s = len2 > 0 ? ((p.x - t.x0) * dx + (p.y - t.y0) * dy) / len2 : 0;
  s = std::clamp(s, 0.0, 1.0);
  if (s_out) *s_out = s;
  const Point q = at(t, s);
  return std::hypot(p.x - q.x, p.y - q.y);
}

/// Moves end `which` (0: start) of t by `len` along the trace's direction.
JointTrace extended(const JointTrace& t, int which, double len) {
  const double l = trace_length(t), ux = (t.x1 - t.x0) / l, uy = (t.y1 - t.y0) / l;
  JointTrace e = t;
  if (which == 0) {
    e.x0 -= len * ux, e.y0 -= len * uy;
  } else {
    e.x1 += len * ux, e.y1 += len * uy;
  }
  return e;
}

/// An end within tol of the opening or a domain side is carried onto it:
/// the trace is extended by 2 tol there and clipped again.
bool snap_to_boundaries(const MeshSpec& spec, const Outline& o, double tol, JointTrace& t) {
  bool moved = false;
  for (int which = 0; which < 2; ++which) {
    const Point end = which == 0 ? Point{t.x0, t.y0} : Point{t.x1, t.y1};
    const DomainSpec& d = spec.domain;
    const double to_side = std::min({std::abs(end.x - (d.center_x - d.width / 2)),
                                     std::abs(end.x - (d.center_x + d.width / 2)),
                                     std::abs(end.y - (d.center_y - d.height / 2)),
                                     std::abs(end.y - (d.center_y + d.height / 2))});
    const double to_opening = distance_to_outline(o, end.x, end.y);
    if (std::min(to_side, to_opening) >= tol || std::min(to_side, to_opening) == 0) continue;
    JointTrace e = extended(t, which, 2 * tol);
    if (!clip_to_domain(spec.domain, e)) continue;
    const std::vector<JointTrace> parts = outside_opening(e, o);
    for (const JointTrace& p : parts)  // the part that holds the other end
      if (distance_to_segment(which == 0 ? Point{t.x1, t.y1} : Point{t.x0, t.y0}, p) < 1e-12) {
        moved = moved || std::abs(trace_length(p) - trace_length(t)) > 0;
        t = p;
      }
  }
  return moved;
}

/// The points an end within tol of which moves onto them: the outline's
/// vertices (springings, corners) and the domain's corners; the ends of the
/// traces kept so far join them. An end a hair from one of them would leave
/// a piece of boundary or a triangle that thin.
std::vector<Point> fixed_points(const MeshSpec& spec, const Outline& o) {
  std::vector<Point> p;
  for (const OutlinePiece& piece : o.pieces) p.push_back({piece.x0, piece.y0});
  const DomainSpec& d = spec.domain;
  for (double sx : {-0.5, 0.5})
    for (double sy : {-0.5, 0.5})
      p.push_back({d.center_x + sx * d.width, d.center_y + sy * d.height});
  return p;
}

/// Moves each end of t within tol of a point of `anchors` onto it (the
/// nearest); then its ends join the anchors.
bool snap_to_points(JointTrace& t, std::vector<Point>& anchors, double tol) {
  bool moved = false;
  for (int which = 0; which < 2; ++which) {
    double& x = which == 0 ? t.x0 : t.x1;
    double& y = which == 0 ? t.y0 : t.y1;
    double best = tol;
    const Point* to = nullptr;
    for (const Point& a : anchors) {
      const double d = std::hypot(a.x - x, a.y - y);
      if (d < best) best = d, to = &a;
    }
    if (to && best > 0) {
      x = to->x, y = to->y;
      moved = true;
    }
  }
  anchors.push_back({t.x0, t.y0});
  anchors.push_back({t.x1, t.y1});
  return moved;
}

/// Merges trace j into i when j lies within tol of i's line at both ends
/// and their extents along i overlap: i grows to the union.
bool merge_if_coincident(JointTrace& i, const JointTrace& j, double tol) {
  const double l = trace_length(i), ux = (i.x1 - i.x0) / l, uy = (i.y1 - i.y0) / l;
  auto along = [&](Point p) { return (p.x - i.x0) * ux + (p.y - i.y0) * uy; };
  auto across = [&](Point p) { return std::abs(-(p.x - i.x0) * uy + (p.y - i.y0) * ux); };
  const Point a{j.x0, j.y0}, b{j.x1, j.y1};
  if (across(a) >= tol || across(b) >= tol) return false;
  const double lo = std::min(along(a), along(b)), hi = std::max(along(a), along(b));
  if (hi < -tol || lo > l + tol) return false;
  const double s0 = std::min(0.0, lo), s1 = std::max(l, hi);
  i = {i.x0 + s0 * ux, i.y0 + s0 * uy, i.x0 + s1 * ux, i.y0 + s1 * uy};
  return true;
}

/// An end of t within tol of trace o (not on it) moves to where t's line
/// meets o, when that is within 2 tol of the end: a T junction instead of
/// a sliver between the end and o.
bool snap_to_trace(JointTrace& t, const JointTrace& o, double tol) {
  bool moved = false;
  for (int which = 0; which < 2; ++which) {
    const Point end = which == 0 ? Point{t.x0, t.y0} : Point{t.x1, t.y1};
    const double dist = distance_to_segment(end, o);
    if (dist >= tol || dist < 1e-12) continue;
    const double dx = t.x1 - t.x0, dy = t.y1 - t.y0, ex = o.x1 - o.x0, ey = o.y1 - o.y0;
    const double den = dx * ey - dy * ex;
    if (den == 0) continue;
    const double fx = o.x0 - t.x0, fy = o.y0 - t.y0;
    const double u = (fx * ey - fy * ex) / den, v = (fx * dy - fy * dx) / den;
    const double shift = std::abs(u - which) * trace_length(t);
    if (v < 0 || v > 1 || shift > 2 * tol || (u <= 0 && which == 1) || (u >= 1 && which == 0))
      continue;
    const double tx = o.x0 + v * ex, ty = o.y0 + v * ey;
    (which == 0 ? t.x0 : t.x1) = tx;
    (which == 0 ? t.y0 : t.y1) = ty;
    moved = true;
  }
  return moved;
}

}  // namespace

std::vector<JointTrace> prepare_joint_traces(const MeshSpec& spec,
                                             const std::vector<JointTrace>& traces,
                                             JointTraceReport* report) {
  JointTraceReport r;
  r.given = long(traces.size());
  r.tolerance = 0.25 * spec.size.size_near;
  const double tol = r.tolerance;
  const Outline opening = tunnel_outline(spec.tunnel);
  std::vector<JointTrace> out;
  std::vector<Point> anchors = fixed_points(spec, opening);
  for (JointTrace t : traces) {
    if (!(trace_length(t) > 0) || !clip_to_domain(spec.domain, t)) {
      ++r.outside;
      continue;
    }
    const std::vector<JointTrace> parts = outside_opening(t, opening);
    if (parts.empty()) ++r.outside;
    if (parts.size() > 1) ++r.split;
    for (JointTrace p : parts) {
      const bool moved = snap_to_boundaries(spec, opening, tol, p);
      r.snapped += snap_to_points(p, anchors, tol) || moved;
      out.push_back(p);
    }
  }
  std::vector<char> gone(out.size(), 0);
  for (std::size_t j = 0; j < out.size(); ++j)
    for (std::size_t i = 0; i < j && !gone[j]; ++i)
      if (!gone[i] && merge_if_coincident(out[i], out[j], tol)) {
        gone[j] = 1;
        ++r.merged;
      }
  std::vector<JointTrace> kept;
  for (std::size_t j = 0; j < out.size(); ++j) {
    if (gone[j]) continue;
    for (std::size_t i = 0; i < out.size(); ++i)
      if (i != j && !gone[i]) r.snapped += snap_to_trace(out[j], out[i], tol);
    if (trace_length(out[j]) < tol) {
      ++r.too_short;
      continue;
    }
    kept.push_back(out[j]);
    r.length += trace_length(out[j]);
  }
  r.kept = long(kept.size());
  if (report) *report = r;
  return kept;
}

}  // namespace rockfdem::mesh
