// Crack elements that start carrying the initial stress.
//
// A tunnel run hands the in-situ field to the engine as per-triangle initial
// stresses on the undeformed mesh. Without a fracture zone that state is in
// equilibrium; with one, every fracture triangle has its own nodes and its
// initial stress pushes on them while the crack elements, at zero opening,
// carry nothing. This gives each crack element opening/slip offsets such
// that at the start it transmits exactly the force its nodes need.
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// For every active crack element: per-point offsets such that, in the
/// current configuration, the crack elements balance the triangle forces
/// (initial stress and strain) and external loads at every split node, as
/// closely as the same state balances without splitting; among the balancing
/// force sets the one closest to the uniform traction ((sA + sB)/2) n of the
/// two triangles' initial stresses (exactly that for a uniform field).
/// Demands at or above a crack's strength are clipped to it (they cannot be
/// carried undamaged). Writes the triangle slots of the current state.
/// Returns the number of clipped integration points.
long prestress_cracks(EngineData& d);

/// Offsets of element c such that its undamaged law (its material and
/// strength factor now) carries the normal and shear stresses `st`
/// ((sigma, tau) at end 0, midpoint, end 1) at the current positions;
/// demands at or above its strength are clipped to it. Returns the number
/// of clipped points.
int carry_point_stresses(EngineData& d, std::size_t c, const double st[6]);

}  // namespace rockfdem::fdem::detail
