// The explicit FDEM engine: finite-strain constant-strain triangles, four-node
// crack elements and central-difference time integration, parallel with
// OpenMP and bit-identical for any thread count.
//
//   rockfdem::fdem::ModelInput in = ...;        // mesh, materials, BCs
//   rockfdem::fdem::Engine engine(in);          // builds nodes, cracks, dt
//   engine.run(10000);                          // or run_to_equilibrium(...)
//   engine.state_hash();                        // equal hashes = identical runs
//
// Lifecycle: construct (validates the input, throws InputError), then any
// mix of run()/step() and stage controls (stiffness factors, activity,
// boundary conditions, damping). A blow-up throws NumericalError naming step,
// element or node, quantity and value; the state is then that of the failing
// step. Three checks run every step at negligible cost: J > 0 and finite for
// every triangle, finite velocities, and the signature of a time step above
// the stability limit: the free nodes' velocities reversing with growth,
// sum v_old.v_new < -1.1 sum |v_old|^2, three steps in a row (this also
// catches instabilities that break crack elements instead of inverting
// triangles).
//
// Numbering: triangles keep the ModelInput's order; engine nodes and crack
// elements are the engine's own (node_vertex() maps nodes back to the mesh).
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "rockfdem/error.hpp"
#include "rockfdem/fdem/model_input.hpp"

namespace rockfdem::fdem {

enum class CrackState : std::uint8_t { kIntact = 0, kYielding = 1, kBroken = 2 };
enum class FailureMode : std::uint8_t { kNone = 0, kModeI = 1, kModeII = 2, kMixed = 3 };

/// Whether set_dt may exceed the stability limit.
enum class DtCheck { kRefuseAboveLimit, kForce };

/// Reference configuration of a triangle when it is (re)activated.
enum class ActivationReference {
  kKeep,     ///< keep the original reference (strain measured from the mesh)
  kCurrent,  ///< stress-free in the current, deformed configuration (lining)
};

/// Relative displacement of a crack element's faces (first face less the
/// second, in the element's current frame: opening along the normal,
/// positive apart; slip along the element from end 0 to end 1) at its
/// three integration points, end 0, midpoint and end 1 [m].
struct CrackDisplacement {
  /// From the node positions: 0 where the faces coincide, i.e. measured
  /// from the mesh (the explicit stage's start, the in-situ state).
  std::array<double, 3> opening{}, slip{};
  /// What the element's law sees: the same less its offsets (the crack
  /// pre-stress of an in-situ start, a re-join's new zero). A negative
  /// opening is the compressive penalty's overlap.
  std::array<double, 3> law_opening{}, law_slip{};
  double length = 0;  ///< current length h [m]
};

struct BrokenCounts {
  long mode_I = 0, mode_II = 0, mixed = 0;
  long total() const { return mode_I + mode_II + mixed; }
};

/// Stop a stage when both ratios are at or below their tolerances.
struct EquilibriumCriteria {
  double force_ratio = 1e-3;    ///< unbalanced_force_ratio()
  double kinetic_ratio = 1e-3;  ///< kinetic energy over its peak during this call
  long check_interval = 100;    ///< steps between checks
  long max_steps = 100000;
};

struct EquilibriumResult {
  bool converged = false;
  long steps = 0;
  double force_ratio = 0;
  double kinetic_ratio = 0;
};

/// Wall time spent in each phase of the step since construction [s].
struct PhaseTimes {
  double triangles = 0, cracks = 0, nodes = 0;
  double contact = 0;  ///< detection, contact forces and their gather
};

/// One of the engine's arrays and the bytes it holds (memory_breakdown()).
struct MemoryPart {
  std::string name;  ///< "record.member", e.g. "nodes.pos", "contact.pairs"
  std::size_t bytes = 0;
};

/// What contact did (contact_counters()): for the run summary.
struct ContactCounters {
  bool enabled = false;
  long candidates = 0;        ///< triangles on a free surface at the last detection
  long pairs = 0;             ///< candidate pairs from the last detection
  long touching = 0;          ///< pairs with a contact force in the last step
  long detections = 0;        ///< broad-phase runs since construction
  long steps_with_pairs = 0;  ///< steps in which the narrow phase ran
  long steps_skipped = 0;     ///< steps in which nothing could touch (no narrow phase)
  long updates = 0;           ///< local broad-phase updates after breakage (no detection)
  /// Instruction set of the narrow phase's (and the crack elements')
  /// kernel on this processor ("avx512", "avx2", "sse2", "baseline"): the
  /// same results on each, not the same speed.
  const char* kernel = "";
};

/// Checks the environment variables the engine reads: ROCKFDEM_ISA,
/// unset or sse2, avx2, avx512 (the widest instruction set the vector
/// kernels of contact and crack elements may use; the results are the same
/// on each). Throws InputError naming the variable, its value and the
/// allowed ones. The Engine's constructor checks too; a command line calls
/// it first so that nothing is written before the error.
void check_environment();

/// What quasi-static mass scaling did (mass_scaling_report()).
struct MassScalingReport {
  bool enabled = false;
  double target_dt = 0;       ///< the step the masses were scaled for, with local damping [s]
  double max_factor = 1;      ///< largest triangle density factor
  double mass_ratio = 1;      ///< scaled over true mass of the active triangles
  long scaled_triangles = 0;  ///< active triangles with a factor above 1
};

/// Energy terms since the first step [J/m] (plane problems: per unit
/// thickness). Each term is its own computation, so the balance is a check,
/// not an identity: the stored terms are closed forms of the state, the
/// others are accumulated every step from their own mechanisms (force times
/// the mid-step velocity of central differences, the crack law's released
/// potential, the friction springs' plastic slip). docs/engine.md, "Energy
/// balance", gives each formula.
///
///   external_work = (stored() - initial_stored) + dissipated() + softening + removed
struct EnergyBalance {
  /// Work of gravity, tractions and pressures (dead loads) and of the
  /// reactions of prescribed velocities (platens).
  double external_work = 0;
  /// Stored now, at the half step of the current velocities: kinetic
  /// (lumped masses); strain: alpha A0 (W(F) + S0 : E), the hyperelastic
  /// energy plus the initial stress's potential (measured from the
  /// pre-stressed reference, so it can be negative); crack_elastic: the
  /// crack elements' potential at their current damage; contact_elastic:
  /// the penalty potential of the overlaps plus the friction springs.
  double kinetic = 0, strain = 0, crack_elastic = 0, contact_elastic = 0;
  double initial_stored = 0;  ///< kinetic + stored when the first step began
  /// Dissipated since the first step: damping (triangles' viscous eta D,
  /// local, mass-proportional and contact damping), fracture (potential
  /// released by damage growth and breakage), friction (contact, plastic
  /// slip), absorbing (boundary dashpots).
  double damping = 0, fracture = 0, friction = 0, absorbing = 0;
  /// Of friction: the work of the joint elements' residual friction (the
  /// part of a joint law's shear traction its potential leaves out: the
  /// friction gained as it softened; docs/engine.md, "Energy balance").
  double joint_friction = 0;
  /// Stored energy taken out by stiffness-factor changes (core softening;
  /// negative when a factor rises).
  double softening = 0;
  /// Energy taken out by other stage controls: deactivated triangles (their
  /// strain energy, their nodes' kinetic energy, the crack elements and
  /// contacts that stop acting), rejoined or re-assigned crack elements,
  /// replaced initial stresses, overwritten node states (negative: added).
  double removed = 0;

  double stored() const;      ///< kinetic + strain + crack_elastic + contact_elastic
  double dissipated() const;  ///< damping + fracture + friction + absorbing
  /// external_work - (stored() - initial_stored) - dissipated() - softening - removed.
  double residual() const;
  /// residual() over the largest of |external_work|, the summed magnitudes
  /// of the stored terms (initial included) and those of the others.
  double imbalance() const;
};

class Engine {
 public:
  /// Builds nodes, crack elements, masses, boundary records and the time
  /// step from `input`. Throws InputError for inconsistent input or a dt
  /// above the stability limit.
  explicit Engine(const ModelInput& input);
  ~Engine();
  Engine(Engine&&) noexcept;
  Engine& operator=(Engine&&) noexcept;
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  // --- Sizes and numbering ------------------------------------------------
  std::size_t n_nodes() const;
  std::size_t n_triangles() const;
  std::size_t n_cracks() const;
  /// Engine node -> mesh vertex.
  const std::vector<int>& node_vertex() const;
  std::array<int, 3> triangle_nodes(std::size_t t) const;
  /// Crack element's nodes: 0,1 on the first face, 3,2 facing them.
  std::array<int, 4> crack_nodes(std::size_t c) const;
  /// The two triangles a crack element joins (first face's triangle first).
  std::array<int, 2> crack_triangles(std::size_t c) const;

  // --- Time step -----------------------------------------------------------
  /// Stability limit of the central-difference scheme for the current model:
  /// per node, the exact linearised CST frequency of its stiffest triangle
  /// plus its crack elements' penalty frequencies, reduced for viscous
  /// damping by sqrt(1 + xi^2) - xi.
  double critical_dt() const;
  /// dt_safety * critical_dt().
  double stable_dt() const;
  double dt() const;
  /// Throws InputError (naming the limit) above critical_dt() unless forced.
  void set_dt(double dt, DtCheck check = DtCheck::kRefuseAboveLimit);

  // --- Running -------------------------------------------------------------
  void step();
  void run(long n_steps);
  EquilibriumResult run_to_equilibrium(const EquilibriumCriteria& criteria);
  long step_count() const;
  double time() const;

  // --- Stage controls ------------------------------------------------------
  /// Scales the whole stress of triangle t, alpha (sigma0 + C:eps + eta D)
  /// (core softening, reference sec. 5). alpha in (0, 1e3].
  void set_stiffness_factor(std::size_t t, double alpha);
  double stiffness_factor(std::size_t t) const;
  /// An inactive triangle has no force and no mass; crack elements act only
  /// between two active triangles. Masses are rebuilt before the next step.
  void set_active(std::size_t t, bool active, ActivationReference ref = ActivationReference::kKeep);
  bool active(std::size_t t) const;
  void set_boundary_conditions(const std::vector<BoundaryCondition>& bcs);
  void set_gravity(double gx, double gy);
  void set_damping(const DampingSettings& damping);
  /// Enables, retargets or disables quasi-static mass scaling (MassScaling).
  /// Masses and the stability limit are rebuilt before the next step, and
  /// again after every change of activity, stiffness factor or crack
  /// material, with the same target step.
  void set_mass_scaling(const MassScaling& scaling);
  /// Brings masses up to date first (like critical_dt()).
  MassScalingReport mass_scaling_report() const;
  /// Assigns material m (and its crack law) to crack element c.
  void set_crack_material(std::size_t c, int material);
  /// Re-joins crack element c with material m (grouting): damage,
  /// state, mode and breakage step are reset, and its current opening and
  /// slip become its new zero, so it starts intact where it is.
  void rejoin_crack(std::size_t c, int material);
  /// Re-joins crack element c with material m (a support installed in
  /// loaded rock) so that it goes on carrying the traction it carries now:
  /// each integration point's normal and shear stress under its present law
  /// and damage (none when broken or inactive) becomes the state of m's
  /// undamaged pre-peak law (damage, state, mode and breakage step reset as
  /// in rejoin_crack). A demand at or above m's strength starts just below
  /// the peak, carrying the strength. Returns the points so clipped (0-3).
  int rejoin_crack_keeping_traction(std::size_t c, int material);
  /// Replaces triangle t's initial stress (sxx, syy, sxy) [Pa] (e.g. a
  /// lining installed stress-free where the in-situ field covered it). The
  /// crack elements keep their state: such a change goes with a new
  /// reference (set_active(..., kCurrent)), and an interface's new zero is
  /// set with rejoin_crack.
  void set_initial_stress(std::size_t t, const std::array<double, 3>& stress);
  /// Enables, changes or disables contact (ContactSettings). Detection is
  /// redone before the next step; the stability limit accounts for the
  /// contact penalty.
  void set_contact(const ContactSettings& contact);
  /// True when the last step evaluated contact pairs (something could touch).
  bool contact_active() const;
  ContactCounters contact_counters() const;
  /// OpenMP threads for every loop; 0 = OpenMP's default.
  void set_threads(int n_threads);
  int threads() const;

  // --- State ---------------------------------------------------------------
  /// Node positions and velocities, interleaved (x0, y0, x1, y1, ...).
  const std::vector<double>& positions() const;
  const std::vector<double>& velocities() const;
  const std::vector<float>& node_mass() const;
  /// Overwrites one node's position and velocity (mapping a state in,
  /// quasi-static drivers, tests).
  void set_node_state(std::size_t node, double x, double y, double vx, double vy);
  /// Net force on a node from the last step's element forces and external
  /// loads, without damping [N/m].
  std::array<double, 2> node_force(std::size_t node) const;
  /// Position minus the mesh vertex position (includes any initial displacement).
  std::array<double, 2> displacement(std::size_t node) const;
  /// Cauchy stress (sxx, syy, sxy) of triangle t in the current state.
  std::array<double, 3> triangle_stress(std::size_t t) const;
  /// Out-of-plane Cauchy stress sigma_zz of triangle t: in plane strain
  /// alpha ((lambda/2)(J - 1/J) + sigma0_zz / J), the law's zz stress
  /// (F_zz = 1) plus the initial out-of-plane stress `sigma0_zz` the caller
  /// kept (the engine holds only in-plane initial stress; it is dropped where
  /// that was reset, as for a lining activated stress-free); 0 in plane stress.
  double triangle_stress_zz(std::size_t t, double sigma0_zz) const;
  /// Largest damage of the element's three integration points.
  double crack_damage(std::size_t c) const;
  /// Factor k on the element's tensile strength and cohesion (strength
  /// heterogeneity, Material::weibull_modulus); 1 for a homogeneous material.
  double crack_strength_factor(std::size_t c) const;
  CrackState crack_state(std::size_t c) const;
  FailureMode crack_mode(std::size_t c) const;
  /// Crack integration points whose share of the initial stress reached
  /// the crack's strength: they start at the peak and carry the strength,
  /// not the demand (0 when the start is fully balanced). The crack
  /// pre-stress is set just before the first step, with the activity,
  /// initial stresses and boundary conditions of that moment.
  long crack_prestress_clipped() const;
  /// Opening and slip of crack element c now, computed from the node
  /// positions on demand (nothing is kept per step; no allocation).
  CrackDisplacement crack_displacement(std::size_t c) const;
  /// Step at which the element broke; -1 while unbroken.
  long crack_broken_step(std::size_t c) const;

  // --- Global figures (deterministic block sums) ----------------------------
  double kinetic_energy() const;
  /// Kinetic-energy peaks at which kinetic damping (DampingSettings::kinetic)
  /// zeroed the velocities, since construction.
  long kinetic_damping_resets() const;
  /// Hyperelastic energy of Munjiza's law (initial stress excluded).
  double strain_energy() const;
  /// Energy stored in the crack elements: the Simpson-integrated potential
  /// of their laws (penalty and (2x - x^2) curves, scaled by the damage
  /// factor) at their current damage; 0 for broken elements. With
  /// kinetic_energy() and strain_energy() it closes the energy balance of an
  /// elastic run.
  double crack_energy() const;
  /// The energy balance since the first step (EnergyBalance). Costs about
  /// one step (closed forms over all elements); the ledger it reads is kept
  /// by every step at a few per cent of the step's cost.
  EnergyBalance energy_balance() const;
  /// Sum over unconstrained node components of |net force| over the sum of
  /// the magnitudes of the forces acting on them (last step's forces).
  double unbalanced_force_ratio() const;
  BrokenCounts broken_counts() const;
  /// Force the kinematic conditions of `tag` exert on the body [N/m]
  /// (the platen load of a UCS test).
  std::array<double, 2> boundary_force(int tag) const;
  /// FNV-1a 64 over the bytes of the node coordinates, as 16 hex digits.
  std::string state_hash() const;
  PhaseTimes phase_times() const;
  /// Bytes held by the engine's arrays (their capacity): the sum of
  /// memory_breakdown().
  std::size_t memory_bytes() const;
  /// The same, array by array, in a fixed order (empty arrays included).
  std::vector<MemoryPart> memory_breakdown() const;

  // --- Checkpoint ------------------------------------------------------------
  /// Writes the whole mutable state (binary, native byte order) so that an
  /// Engine built from the same ModelInput and given load_state() continues
  /// bit for bit as this one would, with any thread count.
  void save_state(std::ostream& out) const;
  /// Restores a state written by save_state(). Throws InputError when the
  /// stream is truncated, corrupt, from another engine format version or from
  /// a model of another layout (model_fingerprint() differs).
  void load_state(std::istream& in);
  /// FNV-1a 64 over the model's static layout (node, triangle, crack counts,
  /// triangle nodes, materials' constants as built from the ModelInput; also
  /// crack nodes, mesh positions and tagged edges: docs/engine.md).
  std::uint64_t model_fingerprint() const;

 private:
  void check_reversal();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rockfdem::fdem
