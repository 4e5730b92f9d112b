// The exact tunnel outline: a closed counter-clockwise loop of straight
// segments and circular arcs. One description serves three purposes: it is
// what gmsh is given to mesh, what the exact opening area is computed from
// (Green's theorem over the pieces), and what fracture-zone and lining tags
// are decided against (exact distance to the pieces). Tests use it too.
#pragma once

#include <vector>

#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh {

/// One piece of an outline. A segment runs from (x0,y0) to (x1,y1). An arc
/// runs counter-clockwise about (cx,cy) with `radius` from angle `a0` to
/// `a1` (radians, a1 > a0, at most pi per piece); its end points are given
/// too so consecutive pieces share exact coordinates.
struct OutlinePiece {
  bool is_arc = false;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double cx = 0, cy = 0, radius = 0, a0 = 0, a1 = 0;
};

/// A closed counter-clockwise loop: pieces[i] ends where pieces[i+1] starts.
/// Every arc bulges outwards (the outlines here are convex).
struct Outline {
  std::vector<OutlinePiece> pieces;
};

/// The opening's outline moved inwards by `inset` (0: the opening itself):
/// arcs keep their centre and lose `inset` of radius, walls and floor move
/// in by `inset`. Throws rockfdem::InputError when the inset leaves nothing.
Outline tunnel_outline(const TunnelSpec& t, double inset = 0);

/// The lining ring's inner boundary: the opening moved in by the lining
/// thickness, its floor (flat or the invert arc) by the invert thickness.
Outline lining_inner_outline(const TunnelSpec& t);

/// The ring's floor part (the invert) lies below this height [m]: the feet
/// of the inner boundary's walls. -infinity for openings without a floor
/// part (circular) or without a lining.
double invert_part_top(const TunnelSpec& t);

/// Exact area enclosed by a closed outline [m^2].
double outline_area(const Outline& o);

/// Exact length of the outline [m].
double outline_perimeter(const Outline& o);

/// Exact area of the tunnel opening [m^2] (core plus lining).
double opening_area(const TunnelSpec& t);

/// Exact (unsigned) distance from (x, y) to the outline curve [m].
double distance_to_outline(const Outline& o, double x, double y);

/// True when (x, y) lies strictly inside the outline (exact for the convex,
/// outward-bulging outlines built here).
bool inside_outline(const Outline& o, double x, double y);

/// Half of the opening's bounding box: (half width, half height) [m].
struct HalfExtent {
  double hx = 0, hy = 0;
};
HalfExtent opening_half_extent(const TunnelSpec& t);

}  // namespace rockfdem::mesh
