// Which crack elements of an engine join the lining ring to the rock: the
// lining stage gives them the bond's material, the outputs count them.
#pragma once

#include <cstddef>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::coupling {

/// Crack elements joining a lining triangle to a triangle of another zone
/// (the shotcrete-rock bond), in crack order.
std::vector<std::size_t> lining_interface_cracks(const fdem::Engine& engine, const mesh::Mesh& m);

}  // namespace rockfdem::coupling
