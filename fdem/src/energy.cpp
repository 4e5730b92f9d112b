// The energy balance (energy.hpp): closed forms of the stored energies, the
// ledger's start and the bookings of stage controls, and the public
// Engine::energy_balance().
#include "energy.hpp"

#include <algorithm>
#include <cmath>

#include "contact.hpp"
#include "crack_elements.hpp"
#include "engine_impl.hpp"
#include "joint_friction.hpp"
#include "parallel.hpp"
#include "triangle_force.hpp"

namespace rockfdem::fdem {
namespace detail {

/// Summed over the node loop's blocks in block order, as the node loop sums
/// it (EngineData::kinetic_after_step): the same bits either way.
double kinetic_energy(const EngineData& d) {
  const auto& n = d.nodes;
  return block_sum(
      static_cast<long>(n.size()), d.threads,
      [&](long i) { return kinetic_energy_term(n.mass[i], n.vel[2 * i], n.vel[2 * i + 1]); },
      kNodeBlock);
}

namespace {

double strain(const EngineData& d, const Placement& at) {
  return block_sum(static_cast<long>(d.tris.size()), d.threads,
                   [&](long t) { return triangle_stored_energy(d, t, at); });
}

double crack(const EngineData& d, const Placement& at) {
  return block_sum(static_cast<long>(d.cracks.size()), d.threads,
                   [&](long c) { return crack_element_energy(d, c, at); });
}

}  // namespace

Placement half_step_placement(const EngineData& d) {
  return Placement{d.nodes.pos.data(), d.nodes.vel.data(), 0.5 * d.energy.last_dt};
}

double stored_energy(const EngineData& d) {
  const Placement at = half_step_placement(d);
  return kinetic_energy(d) + strain(d, at) + crack(d, at) + contact_energy(d, at);
}

double kinetic_and_crack_energy(const EngineData& d) {
  return kinetic_energy(d) + crack(d, half_step_placement(d));
}

void start_ledger(EngineData& d) {
  EnergyLedger& e = d.energy;
  e = EnergyLedger{};
  e.last_dt = d.dt;  // the first step's half step back
  e.initial = stored_energy(d);
  e.started = true;
  std::fill(d.tris.viscous_stress.begin(), d.tris.viscous_stress.end(), 0.0f);
  std::fill(d.cracks.joint_force.begin(), d.cracks.joint_force.end(), 0.0);
}

double node_energy(const EngineData& d, std::size_t n) {
  const Placement at = half_step_placement(d);
  const double vx = d.nodes.vel[2 * n], vy = d.nodes.vel[2 * n + 1];
  double e = 0.5 * d.nodes.mass[n] * (vx * vx + vy * vy);
  const int tri_slots = static_cast<int>(d.crack_slot0());
  for (int k = d.nodes.slot_start[n]; k < d.nodes.slot_start[n + 1]; ++k) {
    const int s = entry_slot(d.nodes.slot_index[k]);
    e += s < tri_slots ? triangle_stored_energy(d, s / 3, at)
                       : crack_element_energy(d, (s - tri_slots) / 2, at);
  }
  return e;
}

double contact_energy_of_triangle(const EngineData& d, int t, const Placement& at) {
  if (!d.contact_on) return 0.0;
  double e = 0.0;
  const auto& pairs = d.contact.pairs;
  for (std::size_t q = 0; q < pairs.size(); ++q)
    if (pairs[q][0] == t || pairs[q][1] == t) e += contact_pair_energy(d, q, at);
  return e;
}

}  // namespace detail

double EnergyBalance::stored() const { return kinetic + strain + crack_elastic + contact_elastic; }

double EnergyBalance::dissipated() const { return damping + fracture + friction + absorbing; }

double EnergyBalance::residual() const {
  return external_work - (stored() - initial_stored) - dissipated() - softening - removed;
}

double EnergyBalance::imbalance() const {
  const double magnitude_stored = std::fabs(kinetic) + std::fabs(strain) +
                                  std::fabs(crack_elastic) + std::fabs(contact_elastic) +
                                  std::fabs(initial_stored);
  const double magnitude_out = std::fabs(damping) + std::fabs(fracture) + std::fabs(friction) +
                               std::fabs(absorbing) + std::fabs(softening) + std::fabs(removed);
  const double scale =
      std::max({std::fabs(external_work), magnitude_stored, magnitude_out, 1e-300});
  return residual() / scale;
}

EnergyBalance Engine::energy_balance() const {
  const auto& d = impl_->d;
  const auto& e = d.energy;
  const detail::Placement at = detail::half_step_placement(d);
  EnergyBalance b;
  b.kinetic = detail::kinetic_energy(d);
  b.strain = detail::strain(d, at);
  b.crack_elastic = detail::crack(d, at);
  b.contact_elastic = detail::contact_energy(d, at);
  if (!e.started) {  // nothing has happened yet: the state is the start
    b.initial_stored = b.stored();
    return b;
  }
  b.initial_stored = e.initial;
  b.external_work = e.external;
  // The last step's viscous force worked with v(n+1/2) too: the half the
  // next step would book.
  const double pending =
      d.tris.viscous_stress.empty()
          ? 0.0
          : detail::block_sum(static_cast<long>(d.tris.size()), d.threads,
                              [&](long t) { return detail::triangle_viscous_pending(d, t); });
  b.damping = e.viscous + pending + e.nodal_damping + e.contact_damping + e.kinetic_damping;
  b.fracture = e.fracture;
  b.joint_friction = e.joint_friction + detail::joint_friction_pending(d);
  b.friction = e.friction + b.joint_friction;
  b.absorbing = e.absorbing;
  b.softening = e.softening;
  b.removed = e.removed;
  return b;
}

}  // namespace rockfdem::fdem
