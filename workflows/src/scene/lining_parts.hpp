// The lining ring's two parts: the floor part (the invert, below the inner
// boundary's wall feet) and the rest (walls and arch). A scene may give the
// floor part a thickness (tunnel.invert_thickness) and a material
// ([materials.invert]) of its own.
#pragma once

#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The ring's floor part lies below this height [m]; -infinity where the
/// scene gives it no material of its own.
double invert_top(const Scene& s);

/// Per mesh triangle: 1 for a lining triangle of the floor part (its
/// centroid in it). All 0 where the scene gives no [materials.invert].
std::vector<char> invert_triangles(const Scene& s, const mesh::Mesh& m);

}  // namespace rockfdem::workflows
