// How far the damage reaches, and whether the mesh resolves it.
//
// Crack elements exist only in the fracture zone (tunnel.fracture_zone, or
// a .msh group): damage that reaches the zone's outer edge is capped by
// construction, and the answer depends on the zone's size. The broken-zone
// depth is measured from the excavation boundary to the farthest broken
// rock crack element; a warning goes out when broken elements come within
// kEdgeElements element sizes of the zone's outer edge.
//
// A cohesive crack needs its process zone resolved: its length is a
// fraction (0.2-1) of Hillerborg's characteristic length l_ch = E GfI / ft^2,
// and cohesive-zone practice asks for about three elements in it. Coarser
// elements make strength and fracture pattern depend on the mesh. The run
// reports h / l_ch and warns above kResolutionLimit.
#pragma once

#include <array>
#include <vector>

#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

struct Scene;

/// Broken elements closer than this many element sizes to the fracture
/// zone's outer edge mean the zone caps the damage.
constexpr double kEdgeElements = 2;

/// h / l_ch above which the run warns that fracture is not resolved.
constexpr double kResolutionLimit = 1.0;

struct Resolution {
  double h = 0;      ///< mean edge length of the fracture zone's triangles [m]
  double l_ch = 0;   ///< E GfI / ft^2 of the rock [m]
  double ratio = 0;  ///< h / l_ch
};

/// The fracture zone's element size against the rock's l_ch; h from `m`
/// when given, else from mesh.size_near (what `check` knows before meshing).
Resolution fracture_resolution(const Scene& scene, const mesh::Mesh* m);

/// The same for a known element size h [m].
Resolution resolution_at(const Scene& scene, double h);

struct BrokenZone {
  long broken = 0;        ///< broken crack elements between two rock triangles
  double depth = 0;       ///< farthest of them from the excavation boundary [m]
  double zone_depth = 0;  ///< the fracture zone's outer edge from the boundary, at most [m]
  double clearance = -1;  ///< nearest of them to the zone's outer edge [m]; -1: none broken
  bool at_edge = false;   ///< clearance below kEdgeElements h
};

/// The broken zone of the engine's state on mesh `m` (fracture zone element
/// size h). Crack elements next to a triangle with `bolt_triangle` set
/// (bolt steel and grout, which reach beyond the fracture zone) are left out.
BrokenZone broken_zone(const fdem::Engine& e, const mesh::Mesh& m, double h,
                       const std::vector<char>& bolt_triangle);

/// The fracture zone's outer edge: the edges between a rock triangle with
/// crack elements and one without, as (x0, y0, x1, y1) of the reference
/// configuration [m]. Empty where every rock triangle can crack.
std::vector<std::array<double, 4>> fracture_zone_edge(const mesh::Mesh& m);

/// Per triangle, 1 where a bolt of `bolts` owns it (steel or grout); empty
/// when there are no bolts.
std::vector<char> bolt_triangles(const fdem::BoltPlan* bolts, std::size_t n_triangles);

/// A ray from a point on the opening into the rock (a key point and its
/// outward normal, the opposite of its inward direction).
struct Ray {
  double x = 0, y = 0;    ///< origin on the opening [m]
  double dx = 0, dy = 0;  ///< unit direction into the rock
};

/// Per ray, the depth of the broken zone along it [m]: over the broken
/// crack elements broken_zone counts (rock on both sides, fracture zone, no
/// bolt) that the ray crosses or passes within `half_width` of, the largest
/// distance along the ray to an element's midpoint, (c - o) . d; 0 when the
/// ray meets none. With `grouted` (1 per crack element re-joined by a
/// grout stage; empty: none) those count too, broken or not now: the
/// depth of the zone that has broken at some time, grouted since.
std::vector<double> broken_depth_along_rays(const fdem::Engine& e, const mesh::Mesh& m,
                                            const std::vector<Ray>& rays, double half_width,
                                            const std::vector<char>& bolt_triangle,
                                            const std::vector<char>& grouted = {});

}  // namespace rockfdem::workflows
