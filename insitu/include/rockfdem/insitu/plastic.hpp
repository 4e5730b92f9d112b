// The Mohr-Coulomb elasto-plastic continuum: the same mesh and in-situ state
// as the elastic stage (rockfdem/insitu/insitu.hpp), the rock perfectly
// plastic (or strain-softening to a residual strength) with non-associated
// flow, the excavation made by releasing the in-situ traction on the
// opening in increments (the convergence-confinement method's fictitious
// support pressure (1 - lambda) sigma0 . n).
//
// Conventions as in insitu.hpp: input strengths positive, output stresses
// TENSION POSITIVE [Pa], displacements caused by the excavation [m], the
// rigid motion that best fits the outer boundary removed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu {

/// Perfectly plastic Mohr-Coulomb strength of the rock zone.
struct MohrCoulombStrength {
  double cohesion = 0;       ///< c [Pa], >= 0
  double friction_deg = 30;  ///< phi [deg], in (0, 90)
  double dilation_deg = 0;   ///< psi [deg], in [0, phi]: 0 = no volume change in flow
};

/// Strain softening of the rock: c and phi fall linearly from the peak
/// (MohrCoulombStrength) to these values as the equivalent plastic shear
/// strain gamma_p = eps_p1 - eps_p3 grows from 0 to softening_strain; psi is
/// kept. Residual equal to the peak is perfect plasticity, bit for bit.
struct ResidualStrength {
  double cohesion = 0;          ///< c_r [Pa], in [0, peak cohesion]
  double friction_deg = 30;     ///< phi_r [deg], in [dilation, peak friction], > 0
  double softening_strain = 0;  ///< gamma_p at the residual [-], >= 0 (0: elastic-brittle)
};

struct PlasticSpec {
  MohrCoulombStrength rock;
  std::optional<ResidualStrength> residual;  ///< none: perfectly plastic
  /// Release fractions lambda at which a field is reported, strictly
  /// increasing in (0, 1]; 1 = the open, unsupported opening. The lining
  /// (InsituSpec::lining, when active) goes in, stress-free, at
  /// lambda = 1 - install_alpha: the alpha of the elastic stage.
  std::vector<double> release{1.0};
  double max_increment = 0.05;  ///< largest lambda step of the Newton loop
  int max_newton = 25;          ///< iterations per step before it is halved
  int max_halvings = 8;         ///< halvings of one step before giving up
  /// Failed steps (each then halved) allowed over the whole release before
  /// giving up as max_halvings does; 0: no limit. Ground at the limit of
  /// collapse can creep on at steps of max_increment / 2^max_halvings,
  /// each success doubling the step into another failure: a verdict
  /// (insitu.continuum_post_peak) needs a bound on that work.
  int max_failed_steps = 0;
  /// Newton stops when ||residual|| <= tolerance * ||in-situ nodal forces||.
  double tolerance = 1e-9;
  /// A release step that fails ends the sequence quietly: the fields of the
  /// lambdas reached are returned (a ground reaction curve up to the
  /// ground's collapse) instead of a NumericalError.
  bool stop_at_failure = false;
  /// With stop_at_failure: the last state reached is returned too when it
  /// lies between two lambdas of the release (its field's lambda then says
  /// where the ground gave way; a verdict needs that, a curve does not).
  bool output_at_failure = false;
};

struct PlasticField {
  double lambda = 0;  ///< released fraction of the in-situ wall traction
  bool lining_installed = false;
  std::vector<Stress> stress;         ///< per mesh triangle (0 where not in the system)
  std::vector<std::uint8_t> active;   ///< per mesh triangle: 1 if in the system
  std::vector<std::uint8_t> yielded;  ///< per mesh triangle: 1 if it ever flowed plastically
  std::vector<double> plastic_shear;  ///< per mesh triangle: gamma_p [-] (0 outside the rock)
  std::vector<double> ux, uy;         ///< per mesh vertex [m]
  std::size_t n_yielded = 0;          ///< triangles with yielded = 1
  std::size_t n_residual = 0;         ///< triangles at the residual strength (softening only)
  int steps = 0;                      ///< lambda steps since the previous field
  int newton_iterations = 0;          ///< summed over those steps
  double unbalanced_ratio = 0;        ///< ||residual|| / ||in-situ nodal forces|| at the end
  double seconds = 0;                 ///< wall time since the previous field
};

/// Solves the release sequence. Needs spec.materials.rock (elastic) and
/// far-field loading (gravity allowed: the base of the box then takes the
/// released weight, as in the elastic stage). Zones kCore, and kLining until installed, are
/// excavated from the start. Throws InputError for bad input, NumericalError
/// when a step does not converge after max_halvings.
std::vector<PlasticField> solve_mohr_coulomb(const mesh::Mesh& mesh, const InsituSpec& spec,
                                             const PlasticSpec& plastic);

/// Throws InputError naming the key when plastic cannot be solved.
void validate(const PlasticSpec& plastic);

// ---------------------------------------------------------------------------
// The closed form: a circular opening of radius a in hydrostatic stress p0,
// internal pressure pi (both compression positive [Pa]), plane strain.
// ---------------------------------------------------------------------------

struct PlasticRingCase {
  double a = 0, p0 = 0, pi = 0;  ///< [m], [Pa], [Pa]
  double E = 0, nu = 0;          ///< rock [Pa], [-]
  MohrCoulombStrength strength;  ///< peak (and psi throughout)
  /// Elastic-brittle-plastic (Brown et al. 1983): the plastic zone at this
  /// c, phi (softening_strain is not used: the drop is immediate).
  std::optional<ResidualStrength> residual;
};

struct PlasticRingSolution {
  double k = 0;                  ///< (1 + sin phi) / (1 - sin phi)
  double sigma_cm = 0;           ///< 2 c cos phi / (1 - sin phi) [Pa]
  double k_r = 0, sigma_cr = 0;  ///< the same of the plastic zone (residual or peak)
  double critical_pressure = 0;  ///< pi below which the wall yields [Pa]
  double plastic_radius = 0;     ///< R_pl [m] (= a when pi >= critical_pressure)
  double wall_displacement = 0;  ///< inward radial displacement of the wall [m]
};

/// Salencon (1969), with a residual Brown et al. (1983), for R_pl and the
/// stresses; the wall displacement from the flow rule, see docs/insitu.md.
PlasticRingSolution plastic_ring(const PlasticRingCase& c);

/// The radial stress at radius r >= a (compression positive) [Pa].
double plastic_ring_radial_stress(const PlasticRingCase& c, double r);

}  // namespace rockfdem::insitu
