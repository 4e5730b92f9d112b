// The tunnel model in gmsh: a rock rectangle fragmented with the opening
// (and, with a lining, the opening's inward offset). Fragmenting rather than
// cutting keeps the core (and lining) as surfaces of their own that share
// the boundary curves with the rock, so the mesh is conformal across them.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "gmsh_model.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/constants.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::mesh::detail {
namespace {

int add_arc_points(const OutlinePiece& p, std::vector<int>& curves, int start, int end) {
  const int n_sub = std::max(1, static_cast<int>(std::ceil((p.a1 - p.a0) / (kPi / 2) - 1e-9)));
  const int centre = gmsh::model::occ::addPoint(p.cx, p.cy, 0);
  int from = start;
  for (int k = 1; k <= n_sub; ++k) {
    const double a = p.a0 + (p.a1 - p.a0) * k / n_sub;
    const int to = k == n_sub ? end
                              : gmsh::model::occ::addPoint(p.cx + p.radius * std::cos(a),
                                                           p.cy + p.radius * std::sin(a), 0);
    curves.push_back(gmsh::model::occ::addCircleArc(from, centre, to));
    from = to;
  }
  return centre;
}

void check_fits_domain(const MeshSpec& spec) {
  const HalfExtent e = opening_half_extent(spec.tunnel);
  const DomainSpec& d = spec.domain;
  if (!(d.width > 0 && d.height > 0)) throw InputError("domain: width and height must be > 0");
  const double margin = std::min(
      {d.width / 2 - std::abs(d.center_x) - e.hx, d.height / 2 - std::abs(d.center_y) - e.hy});
  if (margin <= 0)
    throw InputError("domain: the tunnel opening (half size " + std::to_string(e.hx) + " x " +
                     std::to_string(e.hy) + " m) does not fit inside the " +
                     std::to_string(d.width) + " x " + std::to_string(d.height) +
                     " m domain; make the domain larger");
}

bool in(const std::vector<std::pair<int, int>>& m, int tag) {
  return std::any_of(m.begin(), m.end(), [&](const auto& p) { return p.second == tag; });
}

// Surfaces from the fragment map: the rectangle's pieces inside the opening
// are core or lining; inside the inset too they are core.
void classify_surfaces(const std::vector<gmsh::vectorpair>& map, bool has_lining,
                       GmshModelMap& out) {
  for (const auto& [dim, tag] : map[0]) {
    if (dim != 2) continue;
    const bool in_opening = in(map[1], tag);
    const bool in_inset = has_lining && in(map[2], tag);
    const int zone = !in_opening ? kRock : (has_lining && !in_inset ? kLining : kCore);
    out.surface_zone.emplace_back(tag, zone);
  }
}

std::set<int> curves_of_zone(const GmshModelMap& m, int zone) {
  std::set<int> curves;
  for (const auto& [s, z] : m.surface_zone)
    if (z == zone)
      for (int c : boundary_curves(s)) curves.insert(c);
  return curves;
}

void classify_curves(const DomainSpec& d, GmshModelMap& out) {
  std::set<int> rock = curves_of_zone(out, kRock);
  for (const auto& [c, trace] : out.joint_curve) rock.erase(c);  // inside the rock
  const std::set<int> lining = curves_of_zone(out, kLining);
  const std::set<int> core = curves_of_zone(out, kCore);
  const double x0 = d.center_x - d.width / 2, y0 = d.center_y - d.height / 2;
  for (int c : rock) {
    if (lining.count(c) || core.count(c))
      out.curve_tag.emplace_back(c, kExcavation);
    else
      out.curve_tag.emplace_back(c, rectangle_side_tag(c, x0, y0, x0 + d.width, y0 + d.height));
  }
  for (int c : lining)
    if (core.count(c)) out.curve_tag.emplace_back(c, kLiningInner);
}

}  // namespace

int add_outline_surface(const Outline& o) {
  std::vector<int> starts;
  for (const OutlinePiece& p : o.pieces)
    starts.push_back(gmsh::model::occ::addPoint(p.x0, p.y0, 0));
  std::vector<int> curves, centres;
  for (std::size_t i = 0; i < o.pieces.size(); ++i) {
    const int a = starts[i], b = starts[(i + 1) % starts.size()];
    if (o.pieces[i].is_arc)
      centres.push_back(add_arc_points(o.pieces[i], curves, a, b));
    else
      curves.push_back(gmsh::model::occ::addLine(a, b));
  }
  const int loop = gmsh::model::occ::addCurveLoop(curves);
  const int surface = gmsh::model::occ::addPlaneSurface({loop});
  // Arc centres are construction points only: left in, they would become
  // stray mesh nodes.
  gmsh::vectorpair centre_tags;
  for (int c : centres) centre_tags.emplace_back(0, c);
  gmsh::model::occ::remove(centre_tags);
  return surface;
}

std::vector<int> boundary_curves(int s) {
  gmsh::vectorpair out;
  gmsh::model::getBoundary({{2, s}}, out, /*combined=*/false, /*oriented=*/false);
  std::vector<int> curves;
  for (const auto& [dim, tag] : out) curves.push_back(std::abs(tag));
  return curves;
}

int rectangle_side_tag(int curve, double xmin, double ymin, double xmax, double ymax) {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(1, curve, x0, y0, z0, x1, y1, z1);
  const double eps = 1e-6 * std::max(xmax - xmin, ymax - ymin);
  const double xm = (x0 + x1) / 2, ym = (y0 + y1) / 2;
  if (std::abs(ym - ymin) < eps) return kBottom;
  if (std::abs(ym - ymax) < eps) return kTop;
  if (std::abs(xm - xmax) < eps) return kRight;
  if (std::abs(xm - xmin) < eps) return kLeft;
  throw std::logic_error("rectangle_side_tag: curve " + std::to_string(curve) +
                         " is not on the outer rectangle");
}

// Joint curves from the fragment map: the pieces of trace k are the curves
// its entry maps to (split where traces cross). A curve two traces share
// goes to the first.
void classify_joints(const std::vector<gmsh::vectorpair>& map, std::size_t first,
                     GmshModelMap& out) {
  std::set<int> seen;
  for (std::size_t k = first; k < map.size(); ++k)
    for (const auto& [dim, tag] : map[k])
      if (dim == 1 && seen.insert(tag).second) out.joint_curve.emplace_back(tag, int(k - first));
}

GmshModelMap add_tunnel_model(const MeshSpec& spec, const std::vector<JointTrace>& joints) {
  check_fits_domain(spec);
  const TunnelSpec& t = spec.tunnel;
  const DomainSpec& d = spec.domain;
  const bool has_lining = t.lining_thickness > 0;
  const Outline opening = tunnel_outline(t);
  const Outline inset = has_lining ? lining_inner_outline(t) : Outline{};

  const int rect = gmsh::model::occ::addRectangle(d.center_x - d.width / 2,
                                                  d.center_y - d.height / 2, 0, d.width, d.height);
  gmsh::vectorpair tools{{2, add_outline_surface(opening)}};
  if (has_lining) tools.emplace_back(2, add_outline_surface(inset));
  // Joints go into the same fragment, so the mesh is conformal along them
  // and at their crossings.
  const std::size_t first_joint = 1 + tools.size();
  for (const JointTrace& j : joints) {
    const int a = gmsh::model::occ::addPoint(j.x0, j.y0, 0);
    const int b = gmsh::model::occ::addPoint(j.x1, j.y1, 0);
    tools.emplace_back(1, gmsh::model::occ::addLine(a, b));
  }
  gmsh::vectorpair pieces;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::fragment({{2, rect}}, tools, pieces, map);
  gmsh::model::occ::synchronize();

  GmshModelMap out;
  classify_surfaces(map, has_lining, out);
  classify_joints(map, first_joint, out);
  classify_curves(d, out);
  return out;
}

}  // namespace rockfdem::mesh::detail
