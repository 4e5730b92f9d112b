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

/// Node masses (and their inverses) from the active triangles and their
/// density factors; a node left without mass is frozen with zero velocity.
void refresh_masses(EngineData& d);

/// Gathers each node's slots in CSR order, adds external, dashpot and
/// damping forces, then v += f/m dt (kinematic conditions override), x += v dt.
/// Returns the lowest node whose new velocity is not finite, or -1.
long node_update(EngineData& d);

/// Net force on node i from its slots and external load (no damping).
inline void node_force(const EngineData& d, std::size_t i, double& fx, double& fy) {
  fx = d.nodes.fext[2 * i];
  fy = d.nodes.fext[2 * i + 1];
  const double* slots = d.slots.data();
  for (int k = d.nodes.slot_start[i]; k < d.nodes.slot_start[i + 1]; ++k) {
    const int s = d.nodes.slot_index[k];
    fx += slots[2 * s];
    fy += slots[2 * s + 1];
  }
}

}  // namespace rockfdem::fdem::detail
