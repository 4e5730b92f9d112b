// The work of the joint elements' residual friction, for the energy ledger
// (energy.hpp). The joint law's shear traction (crack_law_joint.hpp) is
//   tau = pre_peak(|s| / sp) [z(D) fp + (1 - z(D)) fr] sign(s),
// and its potential (crack_point_potential) holds the first part only, the
// softened peak curve. The second,
//   tau_f = pre_peak(|s| / sp) (1 - z(D)) fr sign(s),
// the residual friction an element has gained as it softened, has no
// potential: a joint sliding at its residual does work that no stored term
// holds. It is booked as friction, as the ledger books every force without
// a potential: the force of step n times its nodes' mid-step displacement
// h = (v(n-1/2) + v(n+1/2)) dt / 2, in two halves (as the viscous stress):
// at step n, f(n) . v(n-1/2) dt / 2 and the previous step's
// f(n-1) . v(n-1/2) dt_prev / 2, from f(n-1) kept per joint element; the
// last half is pending when the balance is asked, and is booked before
// kinetic damping zeroes the velocities.
//
// The joint elements are listed once (Cracks::joints, sorted), so the step
// loops over them only; each writes its own kept force, and the sum is a
// fixed-block sum over the list: the same bits for any thread count. Only
// the listed elements keep forces; a model without a joint-law material
// keeps nothing and does nothing.
#pragma once

#include <cstddef>

namespace rockfdem::fdem::detail {

struct EngineData;

/// Lists the joint elements and sizes their kept forces (4 per listed
/// element, in the list's order): at construction.
void init_joint_friction(EngineData& d);

/// Keeps Cracks::joints in step with element c's law after its material
/// changed (set_crack_material).
void update_joint_list(EngineData& d, std::size_t c);

/// Called by the step after the crack forces (positions x(n), damage
/// raised, velocities v(n-1/2)): books both halves into
/// EnergyLedger::joint_friction and keeps f(n).
void book_joint_friction(EngineData& d);

/// The work of the kept forces with the current velocities over half the
/// last step (dissipated, as booked): pending in a balance asked now.
double joint_friction_pending(const EngineData& d);

}  // namespace rockfdem::fdem::detail
