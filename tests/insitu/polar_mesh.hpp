// A structured test mesh for the in-situ stage, independent of gmsh: a square
// box [-L, L]^2 with a circular opening of radius a at the origin, meshed on
// rays from the circle to the square with geometric radial grading (cells
// about as long as they are wide), and the opening filled by a core disc
// (rings whose node count halves inwards, a fan at the centre), optionally
// with a lining ring a - t <= r <= a. All triangles counter-clockwise,
// conformal across the excavation boundary, edges tagged as mesh/ tags them.
//
// Why a private generator: the Kirsch and softening tests want exact
// circles (vertices exactly on r = a) and a mesh whose size is set by one
// number, so that refinement studies are clean.
#pragma once

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::insitu::test {

struct PolarMeshSpec {
  double a = 1;                 ///< opening radius
  double half_width = 8;        ///< L: the box is [-L, L]^2
  int n_theta = 64;             ///< divisions around the opening (multiple of 8)
  bool core = true;             ///< mesh the opening (zone kCore)
  double lining_thickness = 0;  ///< > 0: zone kLining ring inside the opening
};

mesh::Mesh polar_box_mesh(const PolarMeshSpec& spec);

}  // namespace rockfdem::insitu::test
