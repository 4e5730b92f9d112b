// Installing solid bolts in an Engine (seed sec. 2.2.2-2.2.5) through the
// public API alone.
//
//   ModelInput in = ...;                                 // rock, fracture zone
//   BoltPlan plan = plan_bolts(in, specs);               // marks, fracture flags, materials
//   Engine engine(in);
//   ... in-situ, core softening ...
//   install_bolts(engine, plan);                         // the support stage
//   ... run; bolt_axial_profile(engine, plan, b), bolt_counts(engine, plan) ...
//
// Design (the engine has no per-triangle material switch). The bolt strip's
// triangles keep their rock material until installation, so before it they
// are rock in every respect (stiffness, density, in-situ stress, crack
// elements with the rock law). plan_bolts() only allows fracture in them
// (crack elements exist only where fracture is allowed: needed for the
// steel and grout interfaces) and appends one steel crack material and one
// grout material per bolt to ModelInput::materials. install_bolt() then
//   - scales each strip triangle's stiffness by alpha = E_strip / E_rock,uniax
//     (set_stiffness_factor; E_rock,uniax = E / (1 - nu^2) in plane strain),
//     so its uniaxial modulus is the calibrated steel's (bolt_steel.hpp),
//   - makes it stress-free in its current shape (set_active(t, true,
//     kCurrent), set_initial_stress(t, 0)), or with kKeepCurrentStress keeps
//     the stress it carries (initial stress = current / alpha, strain from
//     the installed shape) so the strip takes over the rock's load without
//     a jump,
//   - re-joins every crack element inside the strip with the bolt-steel
//     material and every one between the strip and the rock with the grout
//     material: intact, current opening and slip as zero (rejoin_crack),
//     or with kKeepCurrentStress carrying the traction it carries now
//     (rejoin_crack_keeping_traction), so that no node's force changes.
// What this cannot give (the engine hook wanted, set_triangle_material(t,
// m)): the strip keeps the rock's Poisson ratio and density after
// installation (a steel strip would have its own nu; mass matters only
// dynamically), and a bolt triangle must not be softened by a later
// core-softening stage (its stiffness factor carries the steel).
#pragma once

#include <array>
#include <vector>

#include "rockfdem/fdem/bolt_marking.hpp"
#include "rockfdem/fdem/bolt_steel.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::fdem {

/// One bolt as a scene gives it.
struct BoltSpec {
  Bolt bolt;
  double row_spacing = 1;  ///< s_b [m] (seed eq. 20)
  BoltSteel steel;
  Material grout;  ///< rock law: grout ft, c, phi, GfI, GfII, penalties (10 E by default)
};

/// A bolt's crack elements: inside its strip (steel) or between its strip
/// and anything else (grout), in crack order.
struct BoltCracks {
  std::vector<int> steel, grout;
};

/// Everything install and output need, made before the Engine exists.
struct BoltPlan {
  std::vector<BoltSpec> specs;
  BoltMarks marks;
  std::vector<BoltStrip> strips;           ///< per bolt
  std::vector<BoltSteelModel> steel;       ///< per bolt
  std::vector<int> steel_material;         ///< per bolt: index into ModelInput::materials
  std::vector<int> grout_material;         ///< per bolt
  std::vector<std::vector<double>> alpha;  ///< per bolt, per owned triangle (marks order)
  std::vector<std::vector<int>> owned;     ///< per bolt: its triangles owned by it, head to end
  /// Filled by install_bolt: each owned triangle's stress at installation
  /// (zero when stress-free), subtracted by the outputs.
  std::vector<std::vector<std::array<double, 3>>> installed_stress;
  std::vector<char> installed;  ///< per bolt
  /// Per bolt, once indexed (index_bolt_cracks): the crack topology never
  /// changes, and outputs ask at every history row.
  std::vector<BoltCracks> cracks;
};

/// Marks the bolts, allows fracture in their triangles, appends the steel
/// and grout materials to `in` and calibrates the steel to each strip.
/// Throws InputError for a bolt that marks nothing, a strip the steel
/// cannot be calibrated to (bolt_steel.hpp), or a stiffness factor above
/// the engine's limit (1000).
BoltPlan plan_bolts(ModelInput& in, const std::vector<BoltSpec>& specs);

enum class BoltStart {
  kStressFree,         ///< the strip starts unstressed in its current shape
  kKeepCurrentStress,  ///< the strip keeps the stress it carries; outputs count from there
};

struct BoltInstallReport {
  long triangles = 0, steel_cracks = 0, grout_cracks = 0;
  /// kKeepCurrentStress: crack integration points whose traction reached
  /// the steel's or grout's strength and start at it (the rest is lost).
  long clipped_points = 0;
};

/// Installs bolt b (see the design above). Raises the engine's stiffness,
/// so an automatic dt follows and an explicit one may be refused at the
/// next step (Engine::set_dt).
BoltInstallReport install_bolt(Engine& engine, BoltPlan& plan, int b,
                               BoltStart start = BoltStart::kStressFree);
/// All bolts not yet installed.
BoltInstallReport install_bolts(Engine& engine, BoltPlan& plan,
                                BoltStart start = BoltStart::kStressFree);

/// Crack elements of bolt b: inside its strip (steel) or between its strip
/// and anything else (grout), in crack order: the plan's index when made,
/// else a search of every crack element.
BoltCracks bolt_cracks(const Engine& engine, const BoltPlan& plan, int b);

/// Fills BoltPlan::cracks for every bolt in one pass over the crack
/// elements (install_bolt does when it is empty; a restart after loading).
void index_bolt_cracks(const Engine& engine, BoltPlan& plan);

}  // namespace rockfdem::fdem
