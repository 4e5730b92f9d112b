// From the laboratory to the rock mass: the reductions an engineer makes
// from intact rock's figures to a jointed rock mass's, by the Geological
// Strength Index GSI and the disturbance factor D.
//
// - Generalised Hoek-Brown (Hoek, Carranza-Torres and Corkum 2002):
//     mb = mi exp((GSI - 100) / (28 - 14 D)),  s = exp((GSI - 100) / (9 - 3 D)),
//     a  = 1/2 + (exp(-GSI / 15) - exp(-20 / 3)) / 6,
//   sigma1 = sigma3 + sigma_ci (mb sigma3 / sigma_ci + s)^a.
// - Its Mohr-Coulomb equivalent c', phi' over sigma_t < sigma3 < sigma3max
//   (ibid., eqs. 13-14), with sigma3max for tunnels
//   sigma3max / sigma_cm = 0.47 (sigma_cm / (gamma H))^-0.94 (ibid., eq. 19),
//   gamma H the in-situ stress, sigma_cm the rock mass's global strength
//   (ibid., eq. 18).
// - Tensile strength sigma_t = s sigma_ci / mb (ibid., eq. 5).
// - Modulus (Hoek and Diederichs 2006, simplified):
//     E_rm = E_i (0.02 + (1 - D/2) / (1 + exp((60 + 15 D - GSI) / 11))).
// The fracture energies are kept: with E and ft reduced, l_ch = E GfI / ft^2
// grows, so h / l_ch only falls.
#pragma once

#include <utility>

namespace rockfdem::workflows {

/// The intact rock (laboratory) figures the reduction starts from.
struct IntactRock {
  double young = 0;  ///< E_i [Pa]
  double ucs = 0;    ///< sigma_ci [Pa]
  double mi = 0;     ///< Hoek-Brown constant of the intact rock
};

/// The rock mass's figures and the Hoek-Brown constants behind them.
struct RockMassFigures {
  double mb = 0, s = 0, a = 0;
  double sigma_cm = 0;          ///< global rock mass strength [Pa]
  double sigma_3max = 0;        ///< upper end of the Mohr-Coulomb fit [Pa]
  double young = 0;             ///< E_rm [Pa]
  double cohesion = 0;          ///< c' [Pa]
  double friction_angle = 0;    ///< phi' [deg]
  double tensile_strength = 0;  ///< s sigma_ci / mb [Pa]
};

/// Mohr-Coulomb uniaxial compressive strength [Pa] of cohesion `c` [Pa]
/// and friction angle `phi_deg`: 2 c cos(phi) / (1 - sin(phi)).
double mohr_coulomb_ucs(double c, double phi_deg);

/// Hoek-Brown's mb, s, a for `gsi` and `disturbance` D (in the figures).
RockMassFigures hoek_brown_constants(double mi, double gsi, double disturbance);

/// The Mohr-Coulomb c' [Pa] and phi' [deg] fitted to the Hoek-Brown curve
/// of `f` over sigma_t < sigma3 < `sigma_3max` (ibid., eqs. 13-14).
std::pair<double, double> mohr_coulomb_fit(const RockMassFigures& f, double sigma_ci,
                                           double sigma_3max);

/// Hoek-Brown's rock-mass tensile strength s sigma_ci / mb [Pa] of `f`.
double hoek_brown_tensile_strength(const RockMassFigures& f, double sigma_ci);

/// The rock mass of `intact` at `gsi` and `disturbance`, its Mohr-Coulomb
/// fit for a tunnel under the in-situ stress `gamma_h` [Pa].
RockMassFigures rock_mass(const IntactRock& intact, double gsi, double disturbance, double gamma_h);

/// sigma1 of the generalised Hoek-Brown criterion at `sigma3` [Pa].
double hoek_brown_sigma1(const RockMassFigures& f, double sigma_ci, double sigma3);

}  // namespace rockfdem::workflows
