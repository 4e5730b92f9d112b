// Cundall's kinetic damping for dynamic relaxation (DampingSettings::kinetic;
// reference sec. 8): the undamped motion is let run, and each time the
// total kinetic energy passes a peak, all velocities are set to zero. At a
// peak of the kinetic energy the potential energy is near a minimum along
// the path the model is moving on, so each reset keeps the model close to
// it and the next oscillation starts from there; the statics are unchanged.
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// After a step (velocities at the half step n + 1/2): the total kinetic
/// energy K (fixed-block sum) is compared with the last step's. When K fell
/// after rising, every free velocity component is zeroed and its node moved
/// back to the step's midpoint x(n+1/2) = x(n+1) - v dt/2 (prescribed and
/// fixed components stay as they are). Zeroing the velocity alone at
/// x(n+1) can pump energy into the stiffest modes: for a mode of frequency
/// w, central differences conserve v^2/2 + w^2 x(n) x(n+1)/2, and a mode
/// that alternates in sign from step to step (x(n) = -x(n+1) = a, v = 2a/dt)
/// goes from a^2 (2/dt^2 - w^2/2) to w^2 a^2/2, which grows when
/// (w dt)^2 > 2 (dt_safety 0.8 allows up to 2.56), and a run that resets
/// every other step then blows up. From the midpoint the change is
/// (x(n) - x(n+1))^2 (w^2/4 - 1/dt^2)/2 <= 0 for every stable mode. The
/// midpoint is also where the ledger places the stored energies
/// (half_step_placement), so exactly the kinetic energy of the zeroed
/// components leaves the stored energy: it is booked as damping
/// (EnergyLedger::kinetic_damping). Returns true when it reset.
bool kinetic_damping(EngineData& d);

}  // namespace rockfdem::fdem::detail
