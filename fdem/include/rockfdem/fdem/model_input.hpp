// The front door of the explicit engine: one plain record that describes a
// model completely. coupling/ fills it from the mesh and the implicit in-situ
// stage; tests and benchmarks fill it from the structured generator
// (structured_mesh.hpp). Nothing here knows gmsh, deal.II or OpenMP.
//
// Units are SI throughout: m, kg, s, Pa, N/m (fracture energies per unit
// crack area, i.e. J/m^2). The model is 2D per unit thickness (1 m).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rockfdem::fdem {

/// How a crack element's traction follows its opening and slip: the id of a
/// crack law's traits (crack_law.hpp, which turns it into the law once per
/// element; no virtual call). A new law adds its file, an enumerator here
/// and an entry in CrackLaws. Grout and the lining bond are rock-law
/// materials.
enum class CrackLaw : std::uint8_t {
  kRock = 0,       ///< Evans-Marathe softening, Mohr-Coulomb shear strength (reference sec. 2)
  kBoltSteel = 1,  ///< bilinear hardening in tension, brittle shear (seed eqs. 11-19)
  kJoint = 2,      ///< rock joint: Mohr-Coulomb peak and residual friction, ft >= 0, never breaks
};

enum class Plane : std::uint8_t { kStrain, kStress };

/// One material. Elastic constants feed the triangles; strengths, fracture
/// energies and penalties feed the crack elements whose law this material
/// selects.
struct Material {
  double density = 2700;              ///< [kg/m^3]
  double young = 30e9;                ///< Young's modulus E [Pa]
  double poisson = 0.25;              ///< Poisson ratio nu (< 0.5)
  double tensile_strength = 5e6;      ///< ft [Pa] (rock law)
  double cohesion = 15e6;             ///< c [Pa] (rock law; Mohr-Coulomb)
  double friction_deg = 30;           ///< internal friction angle phi [deg]
  double residual_friction_deg = 30;  ///< friction of broken cracks [deg]; used by contact
  double gf_I = 10;                   ///< mode I fracture energy [J/m^2]
  double gf_II = 50;                  ///< mode II fracture energy [J/m^2]
  double normal_penalty = 0;          ///< crack penalty pn [Pa]; 0 selects 10 E
  double tangential_penalty = 0;      ///< crack penalty pt [Pa]; 0 selects pn
  double damping_ratio = 0;           ///< triangle viscous damping, a multiple of Munjiza's
                                      ///< eta = 2 h sqrt(E rho) (h = smallest altitude); the
                                      ///< stiffest mode's ratio is 1.7-1.8 times it
  CrackLaw crack_law = CrackLaw::kRock;
  // Joint law only (CrackLaw::kJoint): Barton-Bandis peak shear strength
  // instead of Mohr-Coulomb's when jcs > 0 (crack_law_joint.hpp),
  // tau = c + sigma_n tan(phi_r + JRC log10(JCS / sigma_n)), the angle capped
  // at kBartonBandisMaxAngleDeg and at least phi_r (residual_friction_deg).
  double jrc = 0;  ///< joint roughness coefficient JRC [-], 0 to 20
  double jcs = 0;  ///< joint wall compressive strength JCS [Pa]; 0: Mohr-Coulomb peak
  // Bolt steel only (CrackLaw::kBoltSteel), seed eqs. 11-19.
  double yield_strength = 0;        ///< sigma_y [Pa]
  double ultimate_strength = 0;     ///< sigma_u [Pa] (>= sigma_y)
  double shear_yield_strength = 0;  ///< tau_y = tau_u [Pa]
  // Strength heterogeneity (rock law only). With weibull_modulus m > 0 each
  // rock crack element of this material draws one factor k from a Weibull
  // distribution of shape m and mean 1 (scale 1 / Gamma(1 + 1/m)), clamped
  // to [kMinStrengthFactor, kMaxStrengthFactor] (crack_law_parts.hpp), and carries
  // k ft and k c; the fracture energies stay, so the softening ranges follow
  // from the scaled strengths. The draw is a hash of (heterogeneity_seed,
  // the element's two mesh vertex ids, sorted): the same for any thread
  // count, element order or engine numbering. m = 0: every factor is 1.
  double weibull_modulus = 0;            ///< Weibull shape m (0 = homogeneous)
  std::uint64_t heterogeneity_seed = 0;  ///< seed of the factors' hash
};

/// An edge of the mesh carrying an integer tag (the mesh's EdgeTag values).
struct TaggedEdge {
  int a = 0;  ///< first vertex
  int b = 0;  ///< second vertex
  int tag = 0;
};

/// What a boundary condition does to one velocity component.
enum class Constraint : std::uint8_t {
  kFree,      ///< no kinematic condition
  kFixed,     ///< velocity held at zero
  kVelocity,  ///< velocity held at the prescribed value (platens)
};

/// Boundary condition on every edge carrying `tag`.
/// Kinematic parts (Constraint) act on every engine node at the edges'
/// vertices; force parts (traction, pressure, absorbing dashpots) are split
/// consistently (half the edge's share to each end) onto the nodes of the
/// triangle that owns the edge: the only triangle of a boundary edge, or the
/// one in which a->b runs counter-clockwise for an interface edge.
/// When two tags prescribe the same component of one node, the later
/// condition in the list wins.
struct BoundaryCondition {
  int tag = 0;
  Constraint x = Constraint::kFree;
  Constraint y = Constraint::kFree;
  double vx = 0, vy = 0;  ///< prescribed velocity [m/s] (Constraint::kVelocity)
  double tx = 0, ty = 0;  ///< distributed traction [Pa], dead load
  double pressure = 0;    ///< normal pressure [Pa], positive pushes into the owning triangle
  bool absorbing =
      false;  ///< viscous dashpots -rho c_p v_n, -rho c_s v_t (owning triangle's material)
};

/// Damping for quasi-static stages (applied in the node update).
struct DampingSettings {
  double local =
      0;  ///< Cundall local damping alpha in [0, 1): f -= alpha |f| sign(v) per component
  double mass_proportional = 0;  ///< c [1/s]: f -= c m v
  /// Cundall's kinetic damping (dynamic relaxation): after each step, when
  /// the total kinetic energy has passed a peak (lower than at the step
  /// before, after rising), every free velocity component is set to zero
  /// (prescribed ones keep their value). May be combined with the others.
  bool kinetic = false;
};

/// Quasi-static mass scaling (density scaling): each triangle's density is
/// raised, never lowered, until its nodes are stable at one common time step,
/// by default the step the least constrained node (coarsest triangle, with
/// its crack penalties and damping) could take on its true mass. Static equilibria
/// do not depend on the masses, so a quasi-static stage reaches the same
/// state in far fewer steps (about one step per element across the model
/// instead of one per smallest element); the dynamics, and with them the
/// simulated time, are no longer physical. Gravity keeps the true masses.
struct MassScaling {
  bool enabled = false;
  /// Target step [s] before local damping (which divides it by sqrt(1 + alpha))
  /// and dt_safety; 0 selects the least constrained node's limit.
  double dt = 0;
};

/// Contact between triangles (Munjiza's potential-based penalty contact with
/// Coulomb friction, reference sec. 3). Off by default: a run enables it
/// when fragments or separate bodies can touch. Only triangles on a free
/// surface (outer boundary, next to an inactive triangle, next to a broken
/// crack element) take part, so an intact body costs nothing.
struct ContactSettings {
  bool enabled = false;
  double penalty = 0;        ///< p [Pa]; 0 selects the largest Young's modulus
  double buffer = 0;         ///< detection buffer [m]; 0 selects 0.125 x the mean edge length
  double damping_ratio = 0;  ///< normal contact damping as a fraction of critical
  bool friction = true;      ///< Coulomb friction, mu = tan(residual friction angle)
};

/// Everything the engine needs. Only x, y, triangles, material and
/// materials are required; empty optional vectors mean "none".
struct ModelInput {
  // Mesh.
  std::vector<double> x, y;                   ///< vertex coordinates [m]
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise vertex ids
  std::vector<int> material;                  ///< per triangle: index into materials
  std::vector<std::uint8_t> fracture;         ///< per triangle: 1 where crack elements may form;
                                              ///< empty = nowhere
  std::vector<Material> materials;
  Plane plane = Plane::kStrain;

  // Initial state. The implicit in-situ stage hands over the stress alone,
  // on the undeformed mesh (its displacements are not passed on).
  std::vector<std::array<double, 3>>
      initial_stress;  ///< per triangle (sxx, syy, sxy) [Pa], tension positive
  std::vector<std::array<double, 2>>
      initial_displacement;  ///< per vertex (ux, uy) [m]; the displaced
                             ///< configuration is the stress reference

  // Loads and supports.
  std::vector<TaggedEdge> edges;
  std::vector<BoundaryCondition> boundary_conditions;
  double gravity_x = 0, gravity_y = 0;  ///< [m/s^2]
  DampingSettings damping;
  MassScaling mass_scaling;
  ContactSettings contact;

  // Time step: dt > 0 is checked against the stability limit; dt = 0 takes
  // dt_safety times the computed critical step.
  double dt = 0;
  double dt_safety = 0.8;
  int threads = 0;  ///< OpenMP threads; 0 = OpenMP's default
};

}  // namespace rockfdem::fdem
