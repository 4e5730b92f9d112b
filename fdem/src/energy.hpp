// The energy ledger: what the step accumulates, and the closed
// forms of the stored energies it is checked against.
//
// Central differences move energy exactly as
//   K(n+1/2) - K(n-1/2) = sum_i f_i(n) . v_i(n) dt,   v(n) = (v(n-1/2) + v(n+1/2)) / 2,
// so every force's work over one step is its force times the mid-step
// velocity. The ledger books, each from its own mechanism and never as a
// remainder:
//   external  dead loads (gravity, tractions, pressures) f . v(n) dt, and the
//             reactions of prescribed velocities, m dv/dt - f_elements, times v(n) dt
//   viscous   triangles' eta D stress: A sigma_v(n) : D(v(n)), the half with
//             v(n+1/2) booked at the next step from w(n) = dt/2 A sigma_v(n)
//             kept per triangle (Triangles::viscous_stress, in single
//             precision: the booking's last digits, never the state)
//   nodal     local and mass-proportional damping f . v(n) dt (node loop)
//   absorbing dashpots f . v(n) dt (node loop)
//   kinetic_damping  what zeroing the velocities at a kinetic-energy peak
//             takes out of the stored energy (kinetic_damping.hpp)
//   fracture  the crack law's potential released when damage grows
//             (phi(D_old) - phi(D_new) at the opening and slip of x(n-1/2)),
//             an element's whole potential when it breaks, less the contact
//             energy of pairs that detection finds already overlapping
//   friction  plastic slip of the contact friction springs,
//             F (F_trial - F) / k_t when the spring is clipped at mu F_n;
//             and the joint elements' residual friction, its force times
//             the mid-step displacement (joint_friction.hpp)
//   contact_damping  normal contact damping f_d v_n dt
// while kinetic, strain, crack and contact energies are closed forms of the
// state. Their balance is then a test of the scheme and of the ledger, not a
// tautology. Stored energies are evaluated at the velocities' half step,
// x - v dt/2, where the work sums end (Placement below).
//
// Every accumulation is a partial sum over fixed blocks of elements or
// nodes, added in block order: the ledger is identical for any thread count.
#pragma once

#include <cstddef>

namespace rockfdem::fdem::detail {

struct EngineData;

/// One node's kinetic energy, m |v|^2 / 2.
inline double kinetic_energy_term(double m, double vx, double vy) {
  return 0.5 * m * (vx * vx + vy * vy);
}

/// Accumulated energy terms since the first step [J/m]. A plain struct of
/// scalars (trivially copyable): checkpoints store it as one block. (For a
/// bit-exact ledger across a restart the per-triangle
/// Triangles::viscous_stress goes with it; without it the first step after
/// the restart misses half a step of viscous work.)
struct EnergyLedger {
  bool started = false;  ///< the first step has recorded the initial state
  double last_dt = 0;    ///< dt of the last step taken
  double initial = 0;    ///< kinetic + stored energy when the first step began
  double external = 0;
  double viscous = 0, nodal_damping = 0, contact_damping = 0;
  double kinetic_damping = 0;  ///< stored energy taken out at kinetic-energy peaks
  double absorbing = 0;
  double fracture = 0;  ///< released crack potential, net of the contact handover
  double friction = 0;
  double joint_friction =
      0;                 ///< work of the joint elements' residual friction (joint_friction.hpp)
  double softening = 0;  ///< stored energy taken out by stiffness-factor changes
  double removed = 0;    ///< energy taken out by other stage controls (negative: added)
};

/// Node positions at which a stored energy is evaluated: pos - back * vel
/// (back = dt/2 puts them at the half step of the velocities; 0 = as they are).
struct Placement {
  const double* pos;
  const double* vel;
  double back;
  double x(int n) const { return pos[2 * n] - back * vel[2 * n]; }
  double y(int n) const { return pos[2 * n + 1] - back * vel[2 * n + 1]; }
};

/// Fixed block of the energy partial sums in the triangle and crack loops:
/// small, so that static scheduling over blocks stays balanced.
constexpr long kEnergyBlock = 128;

/// Current positions, moved back to the half step of the last velocities.
Placement half_step_placement(const EngineData& d);

/// Kinetic energy of the nodes' (half-step) velocities, sum m v^2 / 2 as a
/// fixed-block sum.
double kinetic_energy(const EngineData& d);

/// Kinetic + strain + crack + contact energy at the half step.
double stored_energy(const EngineData& d);

/// Kinetic + crack energy: what a refresh of masses and crack activity can
/// change (refresh_nodes books the difference).
double kinetic_and_crack_energy(const EngineData& d);

/// Called by the first step before any force is computed: records the
/// initial energy and clears the accumulators (the crack pre-stress and
/// anything else done before the first step belong to the initial state).
void start_ledger(EngineData& d);

/// Energy of node n and of the elements that act on it (its triangles and
/// crack elements) at the half step: before and after a stage control that
/// moves the node, their difference is what the control removed.
double node_energy(const EngineData& d, std::size_t n);

/// Stored energy of the contact pairs that involve triangle t.
double contact_energy_of_triangle(const EngineData& d, int t, const Placement& at);

/// Runs `change` (a stage control) and books the energy it took out in
/// `term`: `stored()` before the change minus `stored()` after it. Before the
/// ledger has started nothing is measured and `change` alone runs (what it
/// does belongs to the initial state).
template <class Stored, class Change>
void book_change(EnergyLedger& ledger, double EnergyLedger::*term, const Stored& stored,
                 const Change& change) {
  if (!ledger.started) {
    change();
    return;
  }
  const double before = stored();
  change();
  ledger.*term += before - stored();
}

}  // namespace rockfdem::fdem::detail
