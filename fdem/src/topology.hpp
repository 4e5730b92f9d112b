// Building the engine's discrete structure from a ModelInput: engine nodes
// (one per vertex for the non-fracture triangles around it, one per fracture
// triangle), crack elements on edges next to a fracture triangle, triangle
// reference geometry, and the node -> force-slot incidence (CSR).
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// Throws InputError naming the first inconsistency found.
void validate_input(const ModelInput& in);

/// Fills nodes (positions, vertex map), triangles (nodes, reference inverse,
/// area, material) and crack elements, then the slot incidence.
void build_topology(const ModelInput& in, EngineData& d);

/// Sets triangle t's reference configuration to its nodes' current positions.
void set_reference_to_current(EngineData& d, std::size_t t);

}  // namespace rockfdem::fdem::detail
