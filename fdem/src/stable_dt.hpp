// The central-difference stability limit of the current model.
#pragma once

#include "engine_data.hpp"

namespace rockfdem::fdem::detail {

/// The stability limit used by the engine: 2 / omega_max of the linearised
/// model by Lanczos (at most 200 products, stopped when the largest Ritz
/// value's residual bound is within 0.3% of it), reduced for damping,
/// capped at 1.5 times the element bound below and at that bound of the
/// nodes with absorbing dashpots.
double critical_dt(const EngineData& d);

/// 2 / omega reduced for viscous, mass-proportional and local damping.
double damped_limit(const EngineData& d, double omega, double xi_viscous);

/// The factor by which that damping raises omega's effective frequency,
/// sqrt(1 + alpha) / (sqrt(1 + xi^2) - xi): 2 / (omega f) is damped_limit
/// up to rounding, and exactly 1 without damping.
double damping_stiffening(const EngineData& d, double omega, double xi_viscous);

/// The linearised model's estimate alone: Lanczos in the mass inner product
/// from a deterministic start, at most max_iterations products, reduced for
/// damping with xi_max, the active triangles' largest viscous ratio
/// (node_frequencies hands it back).
double model_critical_dt(const EngineData& d, int max_iterations, double xi_max);

/// Conservative element bound, per node: omega^2 = (largest exact linearised
/// frequency^2 of its active triangles, lumped mass; with their contact term,
/// contact_triangle_omega2, when asked) + (Gershgorin row sum of its live
/// crack elements' penalty stiffness); xi = the triangles' viscous damping
/// ratio in their stiffest mode plus an absorbing dashpot's c / (2 m omega).
/// Exact for a lone triangle and for a lone crack between rigid faces; see
/// docs/engine.md for how tight it is. `triangle_xi_max`, when given, gets
/// the active triangles' largest viscous ratio (no dashpot in it).
void node_frequencies(const EngineData& d, bool with_contact, std::vector<double>& omega2,
                      std::vector<double>& xi, double* triangle_xi_max = nullptr);

/// The bound above per node, (2 / omega) (sqrt(1 + xi^2) - xi) reduced for
/// the other damping (damped_limit); infinity for a node without stiffness.
void node_limits(const EngineData& d, std::vector<double>& limit, bool with_contact,
                 double* triangle_xi_max = nullptr);

/// Largest eigenvalue of node n's absorbing dashpot matrix [N s/m^2]; 0: none.
double dashpot_max(const EngineData& d, std::size_t n);

/// Square of the largest angular frequency contact can add to a node of
/// triangle t: two roles of normal stiffness 3 p / H per unit length (H its
/// smallest altitude), Gershgorin-bounded, doubled when friction adds its
/// tangential spring of the same stiffness.
double contact_triangle_omega2(const EngineData& d, std::size_t t);

/// The largest contact_triangle_omega2 over the active triangles.
double contact_omega2(const EngineData& d);

/// Largest frequency^2 and damping ratio of triangle t in its stiffest mode
/// (linearised at the reference configuration, lumped mass f rho A0 / 3 with
/// the triangle's density factor f).
void triangle_frequency(const EngineData& d, std::size_t t, double& omega2, double& xi);

}  // namespace rockfdem::fdem::detail
