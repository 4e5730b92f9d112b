// Munjiza's finite-strain constant-strain triangle (reference sec. 1).
#pragma once

#include <array>

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// Writes every active triangle's three nodal forces into its slots.
/// Returns the lowest index of a triangle whose Jacobian is not > 0 (inverted
/// or non-finite), or -1 when all are sound.
long triangle_forces(EngineData& d);

/// Cauchy stress (sxx, syy, sxy) of triangle t; J receives the Jacobian.
std::array<double, 3> triangle_stress(const EngineData& d, std::size_t t, double& J);

/// Out-of-plane stress of triangle t (Engine::triangle_stress_zz).
double triangle_stress_zz(const EngineData& d, std::size_t t, double sigma0_zz);

/// Hyperelastic energy A0 alpha W(F) of triangle t (initial stress excluded):
/// W = mu/2 (tr B - 2) - mu ln J + lambda/4 (J^2 - 1 - 2 ln J), whose Cauchy
/// stress is exactly (mu/J)(B - I) + (lambda/2)(J - 1/J) I.
double triangle_strain_energy(const EngineData& d, std::size_t t);

/// Stored energy of triangle t at `at`: alpha A0 (W(F) + S0 : E), the
/// potential whose gradient is the triangle's elastic force, initial stress
/// included (E = (F^T F - I)/2, so it is measured from the pre-stressed
/// reference). 0 for an inactive triangle.
double triangle_stored_energy(const EngineData& d, std::size_t t, const Placement& at);

/// The half of the last step's viscous work that the next step would book:
/// w : D(current velocities), w = dt/2 A sigma_v of the last step.
double triangle_viscous_pending(const EngineData& d, std::size_t t);

}  // namespace rockfdem::fdem::detail
