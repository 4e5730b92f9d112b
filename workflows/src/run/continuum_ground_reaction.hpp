// The Mohr-Coulomb ground reaction curve of the continuum counterpart
// (convergence-confinement, Carranza-Torres and Fairhurst 2000): the scene's
// rock, unsupported (no lining), its in-situ wall traction released in
// twenty equal steps to lambda = 1; at each, per wall point, the inward
// radial displacement against the fictitious support pressure
// (1 - lambda) p0, p0 the in-situ normal stress on the wall's plane there
// (gravity left out). A release that fails ends the curve where the ground
// stood last (it collapses beyond).
#pragma once

#include <string>
#include <vector>

#include "record/continuum_figures.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// A point of the opening's wall: a mesh vertex and the unit direction
/// towards the opening (inward).
struct WallPoint {
  std::string name;
  int vertex = 0;
  double inward_x = 0, inward_y = 0;
};

/// The curve (above) at `points`; needs insitu.continuum's Mohr-Coulomb
/// strength (materials.rock cohesion > 0, friction_angle; dilation_angle).
std::vector<ContinuumGroundReactionPoint> mohr_coulomb_ground_reaction(
    const Scene& scene, const mesh::Mesh& m, const std::vector<WallPoint>& points);

}  // namespace rockfdem::workflows
