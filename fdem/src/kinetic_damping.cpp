// Kinetic damping (kinetic_damping.hpp).
#include "kinetic_damping.hpp"

#include "energy.hpp"
#include "joint_friction.hpp"
#include "parallel.hpp"
#include "triangle_force.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Moves every free velocity component's node back to its half-step
/// position x - v dt/2 (the bits of half_step_placement) and zeroes the
/// velocity; prescribed and fixed components are left as they are.
void settle_free_components(EngineData& d) {
  Nodes& n = d.nodes;
  const double back = 0.5 * d.energy.last_dt;
  NodeListCursor records(n.bc_node, 0);
  for (std::size_t i = 0; i < n.size(); ++i) {
    const long b = records.at(long(i));
    const bool free[2] = {b < 0 || d.bc_records[b].x == Constraint::kFree,
                          b < 0 || d.bc_records[b].y == Constraint::kFree};
    for (int k = 0; k < 2; ++k) {
      if (!free[k]) continue;
      n.pos[2 * i + k] = n.pos[2 * i + k] - back * n.vel[2 * i + k];
      n.vel[2 * i + k] = 0.0;
    }
  }
}

}  // namespace

bool kinetic_damping(EngineData& d) {
  KineticDampingState& s = d.kinetic_damping;
  const double ke = d.kinetic_after_step;  // the node loop's sum: no second pass
  if (!(s.rising && ke < s.previous)) {
    s.rising = ke > s.previous;
    s.previous = ke;
    return false;
  }
  // The viscous stress of the last step works with these velocities too
  // (the half the next step would book, energy.hpp): booked now, as the
  // next step finds them zero.
  if (!d.tris.viscous_stress.empty())
    d.energy.viscous += block_sum(static_cast<long>(d.tris.size()), d.threads,
                                  [&](long t) { return triangle_viscous_pending(d, t); });
  d.energy.joint_friction += joint_friction_pending(d);  // likewise
  settle_free_components(d);
  const double left = kinetic_energy(d);  // of prescribed velocities, if any
  d.energy.kinetic_damping += ke - left;
  s.previous = left;
  s.rising = false;
  ++s.resets;
  return true;
}

}  // namespace rockfdem::fdem::detail
