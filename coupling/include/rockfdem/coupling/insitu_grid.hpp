// The implicit in-situ field as a ParaView grid: mesh triangles with
// displacement per vertex, stress tensor, in-plane principal stresses, zone
// and activity per triangle.
#pragma once

#include "rockfdem/coupling/vtk_grid.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::coupling {

VtkGrid insitu_grid(const mesh::Mesh& m, const insitu::InsituField& field);

}  // namespace rockfdem::coupling
