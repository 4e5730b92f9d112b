// Per-node work: lumped masses and external forces (rebuilt when activity,
// gravity or boundary conditions change), and the per-step gather of force
// slots followed by the central-difference update.
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// Masses from the active triangles (rho A0 / 3 per corner), external forces
/// (gravity m g plus the boundary loads), crack activity (both triangles
/// active). A node left without mass is frozen with zero velocity.
void refresh_nodes(EngineData& d);

/// Node masses from the active triangles and their
/// density factors; a node left without mass is frozen with zero velocity.
void refresh_masses(EngineData& d);

/// Gathers each node's slots in CSR order, adds external, dashpot and
/// damping forces, then v += f/m dt (kinematic conditions override), x += v dt.
/// Returns the lowest node whose new velocity is not finite, or -1.
long node_update(EngineData& d);

/// Dead load on node i: fext, or zero when no node has one (fext empty).
inline double dead_load(const Nodes& n, std::size_t i, int axis) {
  return n.fext.empty() ? 0.0 : n.fext[2 * i + axis];
}

/// Net force on node i from its slots and external load (no damping).
inline void node_force(const EngineData& d, std::size_t i, double& fx, double& fy) {
  fx = dead_load(d.nodes, i, 0);
  fy = dead_load(d.nodes, i, 1);
  const double* slots = d.slots.data();
  for (int k = d.nodes.slot_start[i]; k < d.nodes.slot_start[i + 1]; ++k) {
    // The sign is +-1: x + (-1 y) has the bits of x + (-y), the negative
    // a crack element's nodes 3, 2 had in slots of their own.
    const int e = d.nodes.slot_index[k], s = entry_slot(e);
    const double sign = entry_sign(e);
    fx += sign * slots[2 * s];
    fy += sign * slots[2 * s + 1];
  }
}

}  // namespace rockfdem::fdem::detail
