// Boundary conditions: resolving tagged edges to engine nodes, and turning a
// list of BoundaryCondition into per-node records (kinematic constraints and
// dashpots) plus constant nodal loads (consistent split of tractions).
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// Resolves each tagged edge to its owning triangle and builds the
/// vertex -> engine node map. Throws InputError for an edge not in the mesh.
void resolve_edges(const ModelInput& in, EngineData& d);

/// Replaces the boundary records, loads and per-tag node lists.
void apply_boundary_conditions(const std::vector<BoundaryCondition>& bcs, EngineData& d);

}  // namespace rockfdem::fdem::detail
