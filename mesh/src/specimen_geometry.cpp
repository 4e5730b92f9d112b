// Laboratory specimens in gmsh: the UCS prism (a rectangle between two
// platens) and the Brazilian disc with its two loading arcs. Every triangle
// of a specimen is rock and may crack.
#include <gmsh.h>

#include <cmath>
#include <string>

#include "gmsh_model.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/constants.hpp"

namespace rockfdem::mesh::detail {

GmshModelMap add_ucs_model(const SpecimenSpec& s) {
  if (!(s.width > 0 && s.height > 0))
    throw InputError("specimen: width and height must be > 0 (got " + std::to_string(s.width) +
                     " x " + std::to_string(s.height) + ")");
  const int rect = gmsh::model::occ::addRectangle(-s.width / 2, 0, 0, s.width, s.height);
  gmsh::model::occ::synchronize();
  GmshModelMap out;
  out.surface_zone.emplace_back(rect, kRock);
  for (int c : boundary_curves(rect))
    out.curve_tag.emplace_back(c, rectangle_side_tag(c, -s.width / 2, 0, s.width / 2, s.height));
  return out;
}

// Four arcs, counter-clockwise from the right end of the upper loading arc:
// load top, left rim, load bottom, right rim. Each is below 180 degrees, so
// OCC's centre-point arc is well defined.
GmshModelMap add_disc_model(const SpecimenSpec& s) {
  if (!(s.diameter > 0))
    throw InputError("specimen: diameter = " + std::to_string(s.diameter) + " must be > 0");
  if (!(s.load_arc_deg > 0 && s.load_arc_deg < 180))
    throw InputError("specimen: load_arc_deg = " + std::to_string(s.load_arc_deg) +
                     " must be in (0, 180)");
  const double r = s.diameter / 2, half = s.load_arc_deg * kPi / 360;
  const double angles[4] = {kPi / 2 - half, kPi / 2 + half, 3 * kPi / 2 - half, 3 * kPi / 2 + half};
  const int tags[4] = {kLoadTop, kRim, kLoadBottom, kRim};
  const int centre = gmsh::model::occ::addPoint(0, 0, 0);
  int points[4];
  for (int i = 0; i < 4; ++i)
    points[i] = gmsh::model::occ::addPoint(r * std::cos(angles[i]), r * std::sin(angles[i]), 0);
  GmshModelMap out;
  std::vector<int> curves;
  for (int i = 0; i < 4; ++i) {
    curves.push_back(gmsh::model::occ::addCircleArc(points[i], centre, points[(i + 1) % 4]));
    out.curve_tag.emplace_back(curves.back(), tags[i]);
  }
  const int disc = gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(curves)});
  gmsh::model::occ::remove({{0, centre}});
  gmsh::model::occ::synchronize();
  out.surface_zone.emplace_back(disc, kRock);
  return out;
}

}  // namespace rockfdem::mesh::detail
