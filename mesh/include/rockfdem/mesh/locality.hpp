// Ordering a mesh's triangles for cache locality. gmsh numbers the
// triangles of a graded mesh in the order its meshing passes made them, so
// two triangles that touch can lie far apart in the engine's arrays.
// Sorting the triangles along a Hilbert curve through their centroids puts
// neighbours next to each other; the explicit engine numbers its nodes in
// order of first use by the triangles and its crack elements by their first
// triangle, so they follow. Vertex ids are kept: they name the same points
// as before (in the .msh copy, the implicit stage's fields and the crack
// strength draws, which hash them).
#pragma once

#include <cstdint>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::mesh {

/// Position of (x, y), both in [0, 2^order), along the Hilbert curve of
/// that order (1 <= order <= 31).
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int order);

/// The locality order of `m`'s triangles (new id -> old id): by the Hilbert
/// index of their centroid on a 2^20 grid over the mesh's bounding square,
/// ties by old id. Depends on coordinates and connectivity only, and is the
/// identity on a mesh already in this order.
std::vector<int> locality_order(const Mesh& m);

/// `m` with its triangles (and their zones and fracture flags) in `order`
/// (new id -> old id); vertices, each triangle's corner order, tagged
/// edges and joint edges unchanged.
/// @pre `order` is a permutation of 0..n_triangles-1.
Mesh with_triangle_order(const Mesh& m, const std::vector<int>& order);

}  // namespace rockfdem::mesh
