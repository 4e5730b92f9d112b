// Quasi-static mass scaling (density scaling, MassScaling in model_input.hpp).
//
// The explicit step is limited by the stiffest node, the number of steps to
// equilibrium by the slowest mode: in a graded tunnel mesh (0.35 m at the
// wall, 5 m far away, crack penalties and steel bolts near the wall) the
// smallest, stiffest elements set a step hundreds of times below what the
// coarse elements could take, and a static answer needs many wave transits
// of that step. Raising each triangle's density until all nodes are stable
// at the coarse elements' step changes no static equilibrium (masses do not
// enter K u = f) and cuts the steps per transit to about the element count
// across the model. Gravity keeps the true masses (node_update.cpp).
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// The largest node bound (node_limits: triangles, crack penalties, contact,
/// damping) on the current masses, over the nodes of triangles that are not
/// softened (alpha >= 1): the step the least constrained part of the model
/// could take on its own. The default target step.
double largest_node_limit(const EngineData& d);

/// Sets the density factors (>= 1) of the active triangles so that every
/// node's stability bound (node_limits) reaches the target step, then
/// rebuilds the masses. The target is resolved once, at the first call,
/// and kept through later stage changes.
void scale_masses(EngineData& d);

}  // namespace rockfdem::fdem::detail
