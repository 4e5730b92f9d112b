// Kinetic damping (kinetic_damping.hpp).
#include "kinetic_damping.hpp"

#include "energy.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Zeroes the free velocity components of every node.
void zero_free_velocities(EngineData& d) {
  Nodes& n = d.nodes;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const int b = n.bc[i];
    if (b < 0 || d.bc_records[b].x == Constraint::kFree) n.vel[2 * i] = 0.0;
    if (b < 0 || d.bc_records[b].y == Constraint::kFree) n.vel[2 * i + 1] = 0.0;
  }
}

}  // namespace

bool kinetic_damping(EngineData& d) {
  KineticDampingState& s = d.kinetic_damping;
  const double ke = kinetic_energy(d);
  if (!(s.rising && ke < s.previous)) {
    s.rising = ke > s.previous;
    s.previous = ke;
    return false;
  }
  const double before = stored_energy(d);
  zero_free_velocities(d);
  const double after = stored_energy(d);
  book(d, &EnergyLedger::kinetic_damping, before, after);
  s.previous = kinetic_energy(d);  // 0 unless some velocity is prescribed
  s.rising = false;
  ++s.resets;
  return true;
}

}  // namespace rockfdem::fdem::detail
