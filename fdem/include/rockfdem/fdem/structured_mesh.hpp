// A built-in structured mesh so the engine can be tested and benchmarked
// without gmsh: a rectangle split into nx * ny cells, each cut into two right
// triangles with alternating diagonals (no preferred crack direction).
//
//   (x0, y0+height) +--+--+   edge tags: 1 bottom, 2 right, 3 top, 4 left
//                   |\ | /|   (the same numbers as mesh::EdgeTag)
//                   | \|/ |
//                   +--+--+ (x0+width, y0)
#pragma once

#include <vector>

#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem {

enum RectangleTag : int { kTagBottom = 1, kTagRight = 2, kTagTop = 3, kTagLeft = 4 };

struct RectangleSpec {
  double width = 0.05, height = 0.1;  ///< [m]
  int nx = 10, ny = 20;               ///< cells; triangles = 2 nx ny
  double x0 = 0, y0 = 0;              ///< lower-left corner
  bool fracture = true;               ///< crack elements allowed everywhere
};

/// The hard rock of the tests and benchmarks: rho = 2700 kg/m^3, E = 30 GPa,
/// nu = 0.25, ft = 5 MPa, c = 15 MPa, phi = 30 deg, GfI = 10 J/m^2,
/// GfII = 50 J/m^2, penalties 10 E, no viscous damping.
Material benchmark_rock();

/// Mesh part of a ModelInput (vertices, triangles, material 0, fracture
/// flags, tagged boundary edges) with `material` as the only material.
ModelInput structured_rectangle(const RectangleSpec& spec, const Material& material);

/// Fracturing UCS specimen: the rectangle with platens at top and bottom,
/// each moving towards the other at `platen_velocity` [m/s] (y prescribed,
/// x fixed: fully rough platens).
ModelInput ucs_specimen(const RectangleSpec& spec, const Material& material,
                        double platen_velocity);

/// Rollers on the bottom (y fixed) and left (x fixed) sides and a dead-load
/// traction (0, ty) [Pa] on the top: uniaxial stress in a rectangle.
std::vector<BoundaryCondition> rollers_with_top_traction(double ty);

/// Grid with about `n_triangles` triangles and a 1:2 aspect (UCS shape).
RectangleSpec ucs_grid(double width, double height, long n_triangles);

}  // namespace rockfdem::fdem
