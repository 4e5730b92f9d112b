// How fine to mesh. Tunnels: gmsh's Distance field measures the distance to
// the excavation curves; a Threshold field turns it into a size that is
// size_near up to the fracture zone's outer edge and grows linearly to
// size_far over the grading distance. A Box field keeps the core and lining
// at size_near (the distance field alone would coarsen them towards the
// opening's centre). The smallest of the two is the background mesh.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "gmsh_model.hpp"

namespace rockfdem::mesh::detail {
namespace {

// Only the background field decides sizes: no sizes from points, curvature,
// or boundary sizes spreading into the surfaces.
void common_options(int algorithm) {
  gmsh::option::setNumber("Mesh.Algorithm", algorithm);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
}

std::vector<double> as_doubles(const std::vector<int>& tags) {
  return std::vector<double>(tags.begin(), tags.end());
}

}  // namespace

void set_uniform_size(double h, int algorithm) {
  common_options(algorithm);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
}

double grading_distance(const MeshSpec& spec) {
  if (spec.size.grading_distance > 0) return spec.size.grading_distance;
  // Automatic: the far size is reached at the nearest outer side.
  const HalfExtent e = opening_half_extent(spec.tunnel);
  const DomainSpec& d = spec.domain;
  const double gap = std::min(d.width / 2 - std::abs(d.center_x) - e.hx,
                              d.height / 2 - std::abs(d.center_y) - e.hy);
  return std::max(spec.size.size_far, gap - spec.tunnel.fracture_zone);
}

void set_tunnel_size_field(const MeshSpec& spec, const GmshModelMap& model) {
  namespace field = gmsh::model::mesh::field;
  common_options(spec.size.algorithm);
  const double near = spec.size.size_near, far = spec.size.size_far;
  std::vector<int> excavation;
  for (const auto& [c, tag] : model.curve_tag)
    if (tag == kExcavation) excavation.push_back(c);

  // Sample each curve at about half the near size so the sampled distance
  // is exact to well below one element.
  const double perimeter = outline_perimeter(tunnel_outline(spec.tunnel));
  const int n_points = static_cast<int>(std::clamp(2 * perimeter / near, 50.0, 1e6));
  const int distance = field::add("Distance");
  field::setNumbers(distance, "CurvesList", as_doubles(excavation));
  field::setNumber(distance, "NumPointsPerCurve", n_points);

  const int threshold = field::add("Threshold");
  field::setNumber(threshold, "InField", distance);
  field::setNumber(threshold, "SizeMin", near);
  field::setNumber(threshold, "SizeMax", far);
  field::setNumber(threshold, "DistMin", spec.tunnel.fracture_zone);
  field::setNumber(threshold, "DistMax", spec.tunnel.fracture_zone + grading_distance(spec));

  // The opening's bounding box at the near size: covers core and lining
  // (plus small rock patches at the box's corners, within 0.42 of the arch
  // radius of the opening). A Restrict field to the core surfaces would be
  // exact but in gmsh 4.8 it leaks onto unrelated curves (measured: the top
  // side of the domain came out at a third of the far size).
  const HalfExtent e = opening_half_extent(spec.tunnel);
  const int box = field::add("Box");
  field::setNumber(box, "VIn", near);
  field::setNumber(box, "VOut", far);
  field::setNumber(box, "XMin", -e.hx), field::setNumber(box, "XMax", e.hx);
  field::setNumber(box, "YMin", -e.hy), field::setNumber(box, "YMax", e.hy);
  field::setNumber(box, "ZMin", -1), field::setNumber(box, "ZMax", 1);

  const int smallest = field::add("Min");
  field::setNumbers(smallest, "FieldsList", {double(threshold), double(box)});
  field::setAsBackgroundMesh(smallest);
  gmsh::option::setNumber("Mesh.MeshSizeMax", far);
}

}  // namespace rockfdem::mesh::detail
