// The mesh as a ParaView grid: triangles with zone, fracture flag and
// quality (area, minimum angle, minimum altitude) per cell, tagged edges as
// line cells carrying their tag.
#pragma once

#include "rockfdem/coupling/vtk_grid.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::coupling {

VtkGrid mesh_grid(const mesh::Mesh& m);

}  // namespace rockfdem::coupling
