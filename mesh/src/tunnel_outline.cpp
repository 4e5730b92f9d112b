// Exact tunnel outlines and the geometry computed from them. Every shape is
// convex and built from a floor, two vertical walls and an arch (or a full
// circle), so one "arched box" constructor covers horseshoe, arched and
// rectangular openings and their inward offsets.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/constants.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::mesh {
namespace {

OutlinePiece segment(double x0, double y0, double x1, double y1) {
  OutlinePiece p;
  p.x0 = x0, p.y0 = y0, p.x1 = x1, p.y1 = y1;
  return p;
}

OutlinePiece arc(double cx, double cy, double r, double a0, double a1) {
  OutlinePiece p;
  p.is_arc = true;
  p.cx = cx, p.cy = cy, p.radius = r, p.a0 = a0, p.a1 = a1;
  p.x0 = cx + r * std::cos(a0), p.y0 = cy + r * std::sin(a0);
  p.x1 = cx + r * std::cos(a1), p.y1 = cy + r * std::sin(a1);
  return p;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("tunnel geometry: " + what);
}

// A circle as two half arcs: no single piece may exceed pi (see OutlinePiece).
Outline circle(double r) {
  Outline o;
  o.pieces = {arc(0, 0, r, 0, kPi), arc(0, 0, r, kPi, 2 * kPi)};
  return o;
}

// The floor between x = -w and x = +w: flat at y_foot, or an invert arc of
// radius ri about (0, yi) bulging down to meet the walls' feet at y_foot.
OutlinePiece floor_piece(double w, double y_foot, double yi, double ri) {
  if (ri <= 0) return segment(-w, y_foot, w, y_foot);
  const double b = std::acos(std::min(1.0, w / ri));
  OutlinePiece p = arc(0, yi, ri, kPi + b, 2 * kPi - b);
  p.x0 = -w, p.y0 = y_foot, p.x1 = w, p.y1 = y_foot;  // exact joints
  return p;
}

// A floor (flat or an invert, floor_piece), vertical walls from y_foot, and
// an arch of radius r about (0, yc) meeting the wall tops (r >= w). r = w
// gives a semicircular (horseshoe) arch. Zero-length walls are left out.
Outline arched_box(double w, double y_foot, double yc, double r, double yi = 0, double ri = 0) {
  const double a0 = std::acos(std::min(1.0, w / r));
  const double y_wall = yc + r * std::sin(a0);
  Outline o;
  o.pieces.push_back(floor_piece(w, y_foot, yi, ri));
  if (y_wall > y_foot) o.pieces.push_back(segment(w, y_foot, w, y_wall));
  OutlinePiece top = arc(0, yc, r, a0, kPi - a0);
  top.x0 = w, top.y0 = y_wall, top.x1 = -w, top.y1 = y_wall;  // exact joints
  o.pieces.push_back(top);
  if (y_wall > y_foot) o.pieces.push_back(segment(-w, y_wall, -w, y_foot));
  return o;
}

Outline box(double w, double h) {
  Outline o;
  o.pieces = {segment(-w, -h, w, -h), segment(w, -h, w, h), segment(w, h, -w, h),
              segment(-w, h, -w, -h)};
  return o;
}

double arc_radius_for_rise(double span, double rise) {
  return (span * span / 4 + rise * rise) / (2 * rise);
}

double segment_distance(const OutlinePiece& p, double x, double y) {
  const double dx = p.x1 - p.x0, dy = p.y1 - p.y0;
  const double len2 = dx * dx + dy * dy;
  double s = len2 > 0 ? ((x - p.x0) * dx + (y - p.y0) * dy) / len2 : 0;
  s = std::clamp(s, 0.0, 1.0);
  return std::hypot(x - (p.x0 + s * dx), y - (p.y0 + s * dy));
}

// Nearest point of an arc: radially onto the circle when the point's angle
// lies within the arc, otherwise one of the end points.
double arc_distance(const OutlinePiece& p, double x, double y) {
  const double d = std::hypot(x - p.cx, y - p.cy);
  double a = std::atan2(y - p.cy, x - p.cx);
  while (a < p.a0) a += 2 * kPi;
  while (a >= p.a0 + 2 * kPi) a -= 2 * kPi;
  if (a <= p.a1) return std::abs(d - p.radius);
  return std::min(std::hypot(x - p.x0, y - p.y0), std::hypot(x - p.x1, y - p.y1));
}

// Crossing-number test against the polygon through the pieces' end points.
bool inside_chord_polygon(const Outline& o, double x, double y) {
  bool inside = false;
  for (const OutlinePiece& p : o.pieces) {
    if ((p.y0 > y) != (p.y1 > y)) {
      const double xc = p.x0 + (y - p.y0) * (p.x1 - p.x0) / (p.y1 - p.y0);
      if (x < xc) inside = !inside;
    }
  }
  return inside;
}

// The circular segment between an outward-bulging arc and its chord: inside
// the circle and to the right of the chord (the loop's interior is on the
// left of every piece).
bool inside_arc_segment(const OutlinePiece& p, double x, double y) {
  if (std::hypot(x - p.cx, y - p.cy) >= p.radius) return false;
  const double cross = (p.x1 - p.x0) * (y - p.y0) - (p.y1 - p.y0) * (x - p.x0);
  return cross < 0;
}

// Horseshoe and arched openings: the arch's crown at +height/2, the floor's
// lowest point at -height/2; with an invert the walls' feet are invert_rise
// above it. The inset outline offsets the walls and arch inwards by `inset`
// and the floor by `floor_inset`: the same centres, radii less the insets.
Outline arched_outline(const TunnelSpec& t, double inset, double floor_inset) {
  const bool horseshoe = t.shape == TunnelShape::kHorseshoe;
  const double rise = horseshoe ? t.span / 2 : t.rise;
  require(t.span > 0 && t.height > 0, "span and height must be > 0");
  require(rise > 0 && rise <= t.span / 2 + 1e-12,
          "arch rise = " + std::to_string(rise) + " must be in (0, span/2]");
  require(t.invert_rise >= 0 && t.invert_rise <= t.span / 2 + 1e-12,
          "invert rise = " + std::to_string(t.invert_rise) + " must be in [0, span/2]");
  require(rise + t.invert_rise <= t.height,
          "arch rise (span/2 for a horseshoe) plus invert rise must not exceed the height");
  require(2 * inset < std::min(t.span, t.height),
          "lining thickness must be below half the span and half the height");
  const double r = horseshoe ? t.span / 2 : arc_radius_for_rise(t.span, rise);
  const double yc = t.height / 2 - r;  // crown at +height/2
  const double w = t.span / 2 - inset;
  // The walls must keep a length above the floor part.
  const double wall_top = yc + (r - inset) * std::sin(std::acos(std::min(1.0, w / (r - inset))));
  if (t.invert_rise <= 0) {
    const double y_floor = -t.height / 2 + floor_inset;
    require(y_floor < wall_top, "invert thickness leaves no wall below the arch");
    return arched_box(w, y_floor, yc, r - inset);
  }
  const double ri = arc_radius_for_rise(t.span, t.invert_rise);
  const double yi = -t.height / 2 + ri;  // lowest point at -height/2
  require(floor_inset < t.invert_rise && inset < t.invert_rise,
          "lining and invert thickness must be below the invert rise");
  const double y_foot = yi - std::sqrt((ri - floor_inset) * (ri - floor_inset) - w * w);
  require(y_foot < wall_top, "invert thickness leaves no wall below the arch");
  return arched_box(w, y_foot, yc, r - inset, yi, ri - floor_inset);
}

Outline inset_outline(const TunnelSpec& t, double inset, double floor_inset) {
  require(inset >= 0 && floor_inset >= 0, "inset " + std::to_string(inset) + " must be >= 0");
  switch (t.shape) {
    case TunnelShape::kCircular:
      require(t.radius > 0, "radius = " + std::to_string(t.radius) + " must be > 0");
      require(inset < t.radius, "lining thickness must be below the radius");
      return circle(t.radius - inset);
    case TunnelShape::kRectangular:
      require(t.span > 0 && t.height > 0, "span and height must be > 0");
      require(2 * inset < std::min(t.span, t.height),
              "lining thickness must be below half the span and half the height");
      return box(t.span / 2 - inset, t.height / 2 - inset);
    case TunnelShape::kHorseshoe:
    case TunnelShape::kArched:
      return arched_outline(t, inset, floor_inset);
  }
  throw InputError("tunnel geometry: unknown shape");
}

bool has_floor_part(const TunnelSpec& t) {
  return t.shape == TunnelShape::kHorseshoe || t.shape == TunnelShape::kArched;
}

double floor_thickness(const TunnelSpec& t) {
  return has_floor_part(t) && t.invert_thickness > 0 ? t.invert_thickness : t.lining_thickness;
}

}  // namespace

Outline tunnel_outline(const TunnelSpec& t, double inset) { return inset_outline(t, inset, inset); }

Outline lining_inner_outline(const TunnelSpec& t) {
  return inset_outline(t, t.lining_thickness, floor_thickness(t));
}

double invert_part_top(const TunnelSpec& t) {
  if (!has_floor_part(t) || t.lining_thickness <= 0)
    return -std::numeric_limits<double>::infinity();
  return lining_inner_outline(t).pieces.front().y0;  // the floor piece starts at the left foot
}

double outline_area(const Outline& o) {
  // Green's theorem: A = 1/2 \oint (x dy - y dx), exact on lines and arcs.
  double twice = 0;
  for (const OutlinePiece& p : o.pieces) {
    if (!p.is_arc) {
      twice += p.x0 * p.y1 - p.x1 * p.y0;
    } else {
      const double r = p.radius;
      twice += p.cx * r * (std::sin(p.a1) - std::sin(p.a0)) -
               p.cy * r * (std::cos(p.a1) - std::cos(p.a0)) + r * r * (p.a1 - p.a0);
    }
  }
  return twice / 2;
}

double outline_perimeter(const Outline& o) {
  double length = 0;
  for (const OutlinePiece& p : o.pieces)
    length += p.is_arc ? p.radius * (p.a1 - p.a0) : std::hypot(p.x1 - p.x0, p.y1 - p.y0);
  return length;
}

double opening_area(const TunnelSpec& t) { return outline_area(tunnel_outline(t)); }

double distance_to_outline(const Outline& o, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const OutlinePiece& p : o.pieces)
    best = std::min(best, p.is_arc ? arc_distance(p, x, y) : segment_distance(p, x, y));
  return best;
}

bool inside_outline(const Outline& o, double x, double y) {
  if (inside_chord_polygon(o, x, y)) return true;
  for (const OutlinePiece& p : o.pieces)
    if (p.is_arc && inside_arc_segment(p, x, y)) return true;
  return false;
}

HalfExtent opening_half_extent(const TunnelSpec& t) {
  if (t.shape == TunnelShape::kCircular) return {t.radius, t.radius};
  return {t.span / 2, t.height / 2};
}

}  // namespace rockfdem::mesh
