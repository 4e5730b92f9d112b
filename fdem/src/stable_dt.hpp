// The central-difference stability limit of the current model.
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// The stability limit used by the engine: 2 / omega_max of the linearised
/// model by power iteration (at most 200 iterations, Rayleigh quotient
/// settled to 1e-4), reduced for damping, capped at 1.5 times the bound below.
double critical_dt(const EngineData& d);

/// 2 / omega reduced for viscous, mass-proportional and local damping.
double damped_limit(const EngineData& d, double omega, double xi_viscous);

/// Power-iteration estimate alone.
double power_critical_dt(const EngineData& d, int max_iterations);

/// Conservative element bound: per node, omega^2 = (largest exact linearised
/// frequency^2 of its active triangles, lumped mass) + (Gershgorin row sum of
/// its live crack elements' penalty stiffness); dt = min over nodes of
/// (2 / omega) (sqrt(1 + xi^2) - xi), with xi the triangles' viscous damping
/// ratio in their stiffest mode. Exact for a lone triangle and for a lone
/// crack between rigid faces; see docs/engine.md for how tight it is.
double bound_critical_dt(const EngineData& d);

/// The bound above per node (infinity for a node without stiffness); with
/// contact, each triangle's frequency^2 also takes its contact term
/// (contact_triangle_omega2).
void node_limits(const EngineData& d, std::vector<double>& limit, bool with_contact);

/// Largest frequency^2 and damping ratio of triangle t in its stiffest mode
/// (linearised at the reference configuration, lumped mass f rho A0 / 3 with
/// the triangle's density factor f).
void triangle_frequency(const EngineData& d, std::size_t t, double& omega2, double& xi);

}  // namespace rockfdem::fdem::detail
