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

/// Dead load on node i (a search: not for the node loop, which walks the
/// loaded nodes with a DeadLoadCursor); zero when no node has one.
inline double dead_load(const Nodes& n, std::size_t i, int axis) {
  if (n.fext.force.empty()) return 0.0;
  const long k = n.fext.find(long(i));
  return k >= 0 ? n.fext.force[2 * k + axis] : (axis == 0 ? n.fext.none_x : n.fext.none_y);
}

/// The dead loads of ascending nodes from `first` on (NodeListCursor).
class DeadLoadCursor {
 public:
  DeadLoadCursor(const DeadLoads& l, long first)
      : force_(l.force.data()), dense_(l.dense), none_{l.none_x, l.none_y}, nodes_(l.node, first) {}
  /// The load on node i, i not below the last node asked for.
  void at(long i, double& gx, double& gy) {
    const long k = dense_ ? i : nodes_.at(i);
    gx = k >= 0 ? force_[2 * k] : none_[0];
    gy = k >= 0 ? force_[2 * k + 1] : none_[1];
  }

 private:
  const double* force_;
  bool dense_;
  double none_[2];
  NodeListCursor nodes_;
};

/// Adds node i's entries of `slots` (a force per slot, laid out as
/// EngineData::slots) to fx, fy in CSR order.
inline void gather_slots(const Nodes& n, const double* slots, std::size_t i, double& fx,
                         double& fy) {
  for (int k = n.slot_start[i]; k < n.slot_start[i + 1]; ++k) {
    // The sign is +-1: x + (-1 y) has the bits of x + (-y), the negative
    // a crack element's nodes 3, 2 had in slots of their own.
    const int e = n.slot_index[k], s = entry_slot(e);
    const double sign = entry_sign(e);
    fx += sign * slots[2 * s];
    fy += sign * slots[2 * s + 1];
  }
}

/// Net force on node i from its slots, starting from the dead load gx, gy.
inline void node_force(const EngineData& d, std::size_t i, double gx, double gy, double& fx,
                       double& fy) {
  fx = gx;
  fy = gy;
  gather_slots(d.nodes, d.slots.data(), i, fx, fy);
}

/// Net force on node i from its slots and external load (no damping).
inline void node_force(const EngineData& d, std::size_t i, double& fx, double& fy) {
  node_force(d, i, dead_load(d.nodes, i, 0), dead_load(d.nodes, i, 1), fx, fy);
}

}  // namespace rockfdem::fdem::detail
