// A validated scene: everything a run needs, typed, with defaults filled in.
// load_scene() checks the whole file (and every --set override) before any
// work starts; the first problem is thrown as rockfdem::InputError naming
// the file, the key, the value and what is allowed.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::workflows {

/// Most values insitu.alpha may hold: each is a full implicit solve.
inline constexpr std::size_t kMaxAlphas = 100;

struct MaterialSpec {
  double density = 2700;                ///< kg/m^3
  double young = 0;                     ///< Pa
  double poisson = 0;                   ///< -
  double tensile_strength = 0;          ///< Pa (0: not given)
  double cohesion = 0;                  ///< Pa (0: not given)
  double friction_angle = 30;           ///< deg
  double residual_friction_angle = 30;  ///< deg
  double fracture_energy_I = 0;         ///< J/m^2 (0: not given)
  double fracture_energy_II = 0;        ///< J/m^2 (0: not given)
  double penalty_factor = 10;           ///< penalty / Young's modulus
  double heterogeneity = 0;             ///< Weibull modulus of crack strengths; 0: homogeneous
  std::uint64_t heterogeneity_seed = 1;
  double compressive_strength = 0;  ///< Pa, lining only: its capacity check (0: not given)
};

struct InsituSettings {
  double sigma_h = 0;      ///< Pa, compression positive
  double sigma_v = 0;      ///< Pa, compression positive
  double angle_deg = 0;    ///< rotation of sigma_h from x, counter-clockwise
  double unit_weight = 0;  ///< N/m^3
  bool kirsch_boundary = false;
  std::vector<double> alpha{1.0};  ///< at most kMaxAlphas values
  bool lining_active = false;
  std::string solver = "auto";
  double tolerance = 1e-10;
  /// Outer boundary in the explicit stages: rollers (normal displacement
  /// held at the hand-off's) or the in-situ tractions alone.
  bool rollers = true;
  /// The continuum counterpart of a tunnel run: "elastic" or "mohr_coulomb".
  std::string continuum = "elastic";
  double dilation_angle = 0;  ///< deg, Mohr-Coulomb continuum
};

struct EngineSettings {
  long steps = 10000;
  double dt = 0;  ///< s; 0: automatic
  double dt_safety = 0.8;
  double damping_ratio = 0.1;
  /// Cundall local damping; -1: the kind's default (kTunnelLocalDamping in
  /// tunnel stages, none in specimen runs). Shown in the run summary.
  double local_damping = -1;
  double mass_damping = 0;       ///< 1/s
  bool kinetic_damping = false;  ///< Cundall's kinetic damping in tunnel stages
  double gravity = 0;            ///< m/s^2, acting in -y
  bool mass_scaling = false;     ///< quasi-static mass scaling (engine.mass_scaling resolved)
  double mass_scaling_dt = 0;    ///< s; 0: automatic
  double platen_velocity = 0.5;  ///< m/s, each platen (specimens)
  bool rough_platens = true;     ///< platens hold the ends laterally (specimens)
  double stop_after_peak = 0;    ///< post-peak stop: fraction of the peak; 0: none
  bool contact = true;
  double contact_penalty_factor = 1;  ///< times the rock's Young's modulus
  double contact_damping = 0;
  bool contact_friction = true;
};

/// One construction stage of a tunnel run (scene [[stages]]).
struct StageSpec {
  std::string kind;     ///< soften, lining, remove_core, equilibrium
  double alpha = 0;     ///< soften: target core stiffness factor
  long max_steps = 0;   ///< explicit steps at most
  double ratio = 1e-3;  ///< stop when the unbalanced-force ratio is below
  double time = 0;      ///< stop after this simulated time [s]; 0: no limit
  int every_steps = 1000;
  long trigger_broken = 0;  ///< grout: broken crack elements that trigger grouting
  /// With the ratio, equilibrium needs the monitors settled: the largest
  /// monitor displacement change over one output interval, per 1000 steps,
  /// at most this fraction of the largest monitor displacement; 0: the
  /// ratio alone.
  double settle = 1e-3;
  /// Consecutive outputs at which ratio and settle must both hold.
  int hold = 2;
  /// A monitor displaced by more than this fraction of the opening's span
  /// makes the run unstable (the opening is closing, not stabilising).
  double unstable_fraction = 0.05;
  /// Whether finding the opening unstable ends the run there; false runs
  /// on to the cap, the status stays unstable with the first finding.
  bool stop_when_unstable = true;
};

/// Local damping of tunnel stages when engine.local_damping is not given.
constexpr double kTunnelLocalDamping = 0.8;

/// The steel of one kind of bolt (seed sec. 2.2).
struct SteelSettings {
  double diameter = 0.025, row_spacing = 1;
  double young = 200e9, yield_strength = 400e6, ultimate_strength = 500e6;
  double tangent_modulus = 2e9, shear_yield_strength = 240e6, shear_fracture_energy = 1e4;
};

/// Rockbolts and cables (long bolts of strand, the seed's simplification),
/// each a segment from its head on the excavation boundary into the rock.
struct BoltSettings {
  SteelSettings bolt, cable;
  std::vector<std::array<double, 4>> segments;  ///< (x0, y0, x1, y1) per bolt, fans expanded
  std::vector<std::uint8_t> is_cable;           ///< per segment
};

/// A bond modelled by crack elements: the grout (bolt-rock bond, and what
/// re-joins broken cracks when grouting) or the shotcrete-rock interface.
struct BondSettings {
  double young = 10e9, tensile_strength = 1e6, cohesion = 2e6, friction_angle = 30;
  double fracture_energy_I = 20, fracture_energy_II = 100;
};
using GroutSettings = BondSettings;

/// A history point of the user's (scene [[monitor]]): the rock's material
/// point at (x, y) of the mesh.
struct MonitorSpec {
  std::string name;
  double x = 0, y = 0;               ///< [m]
  bool relative_to_support = false;  ///< read from the first lining or bolts stage on
};

/// A borehole extensometer (scene [[extensometer]]): a head and `anchors`
/// anchors at equal spacing to `length` along a line into the rock.
struct ExtensometerSpec {
  std::string name;
  std::string from;               ///< key point the head is at (its outward normal); empty: given
  double head_x = 0, head_y = 0;  ///< [m], when `from` is empty
  double dir_x = 0, dir_y = 0;    ///< unit vector into the rock, when `from` is empty
  double length = 0;              ///< head to the deepest anchor [m]
  int anchors = 3;
};

struct OutputSettings {
  int every_steps = 1000;
  bool vtk = true;
  bool plots = true;
  long checkpoint_every = 0;  ///< steps between checkpoints; 0: none
  /// Origin of the convergence plots: the support's installation (where
  /// the scene has one) rather than the in-situ state.
  bool convergence_from_support = true;
};

/// Figures the run is compared with in report.md (scene [references]).
struct ReferenceSettings {
  /// [mm] by name: key points (radial, towards the opening positive),
  /// "wall_chord", "shoulder_chord" (closure); only those given.
  std::map<std::string, double> mm;
  bool from_support = false;  ///< measured from the support's installation
  std::string source;         ///< where they come from
};

struct Scene {
  std::string source;  ///< the scene file's path, or "default"
  std::string title;
  bool plane_stress = false;
  mesh::MeshSpec mesh;
  std::map<std::string, MaterialSpec> materials;  ///< "rock", "core", "lining" as present
  InsituSettings insitu;
  EngineSettings engine;
  std::vector<StageSpec> stages;  ///< explicit stages after the implicit one (tunnels)
  BoltSettings bolts;
  GroutSettings grout;
  BondSettings lining_interface;      ///< re-joins the lining-rock crack elements at installation
  std::vector<MonitorSpec> monitors;  ///< scene [[monitor]]
  std::vector<ExtensometerSpec> extensometers;  ///< scene [[extensometer]]
  OutputSettings output;
  ReferenceSettings references;
  std::string
      canonical;  ///< the validated scene as TOML (overrides applied), for hashing and records
  /// canonical without output.checkpoint_every: what a checkpoint must match
  std::string restart_key;
  /// canonical with msh.file made absolute: a scene file that reruns this scene from anywhere
  std::string as_run;
  std::vector<std::string> overrides;  ///< the --set arguments applied, in order
  std::vector<std::string> warnings;   ///< inputs that look wrong (a stress in Pa meant as MPa)
};

/// Whether the model has a lining ring with its material: a generated
/// tunnel's tunnel.lining_thickness > 0, or a .msh group mapped to "lining".
bool has_lining_ring(const Scene& scene);

/// Reads and validates a scene file; `overrides` are "section.key=value" strings.
/// A `path` of "-" reads the scene from stdin (named "<stdin>" in messages;
/// msh.file relative to the working directory), bounded as a file is.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

/// The built-in default scene (the seed's tunnel), with overrides.
Scene load_default_scene(const std::vector<std::string>& overrides = {});

/// Validates scene text; `source` names it in messages, `base_dir` resolves relative paths.
Scene parse_scene(const std::string& text, const std::string& source, const std::string& base_dir,
                  const std::vector<std::string>& overrides = {});

/// The text of the built-in default scene (scenes/tunnel-seed.toml).
const std::string& default_scene_text();

}  // namespace rockfdem::workflows
