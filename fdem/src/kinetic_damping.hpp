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
/// after rising, every free velocity component is set to zero (prescribed
/// ones keep their value, fixed ones are zero already) and the stored energy
/// this takes out is booked as damping: the kinetic energy, and the shift
/// of the half-step placement x - v dt/2 at which the strain, crack and
/// contact energies are evaluated (energy.hpp), so that the energy balance
/// still closes. Returns true when the velocities were zeroed.
bool kinetic_damping(EngineData& d);

}  // namespace rockfdem::fdem::detail
