// A validated scene: everything a run needs, typed, with defaults filled in.
// load_scene() checks the whole file (and every --set override) before any
// work starts; the first problem is thrown as rockfdem::InputError naming
// the file, the key, the value and what is allowed.
//
// Defaults are the schema's (scene_schema.cpp), the one place they are
// written: load_scene() fills every member from the file or the schema's
// default. Members are therefore value-initialised ({}: 0, false, empty);
// a member with another initialiser holds a neutral value for a key the
// schema gives no default, and says so.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/mesh/joints.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"
#include "rockfdem/workflows/rock_mass.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

namespace rockfdem::workflows {

/// The section a ring part's capacity check takes (materials.lining and
/// materials.invert; docs/support.md, "Section types"). Per metre of tunnel.
struct LiningSectionSpec {
  std::string kind;               ///< "plain", "reinforced" or "steel_sets"
  double steel_young{};           ///< Pa, of the bars or the sets
  double steel_yield_strength{};  ///< Pa (0: not given, plain)
  double bar_area{};              ///< reinforced: m^2 per m of tunnel, each face (0: not given)
  double bar_cover{};             ///< reinforced: face to the bars' centroid [m]
  double set_area{};              ///< steel_sets: one set's cross-section [m^2]
  double set_inertia{};           ///< steel_sets: one set's second moment [m^4]
  double set_depth{};             ///< steel_sets: one set's depth [m]
  double set_spacing{};           ///< steel_sets: along the tunnel [m]
};

struct MaterialSpec {
  double density{};                  ///< kg/m^3
  double young{};                    ///< Pa
  double poisson{};                  ///< -
  double tensile_strength{};         ///< Pa (0: not given)
  double cohesion{};                 ///< Pa (0: not given)
  double friction_angle{};           ///< deg
  double residual_friction_angle{};  ///< deg
  double fracture_energy_I{};        ///< J/m^2 (0: not given)
  double fracture_energy_II{};       ///< J/m^2 (0: not given)
  double penalty_factor{};           ///< penalty / Young's modulus
  double heterogeneity{};            ///< Weibull modulus of crack strengths; 0: homogeneous
  std::uint64_t heterogeneity_seed{};
  double compressive_strength{};  ///< Pa, lining only: its capacity check (0: not given)
  LiningSectionSpec section;      ///< lining and invert only: the capacity check's section
};

struct InsituSettings {
  double sigma_h{};      ///< Pa, compression positive (0: not given, specimens)
  double sigma_v{};      ///< Pa, compression positive (0: not given, specimens)
  double angle_deg{};    ///< rotation of sigma_h from x, counter-clockwise
  double unit_weight{};  ///< N/m^3
  bool kirsch_boundary{};
  std::vector<double> alpha;  ///< at most kMaxAlphas values
  /// The hand-off at the last alpha before a crack element is over-stressed
  /// (insitu.handoff = "first_crack") rather than at the list's last.
  bool handoff_first_crack{};
  bool lining_active{};
  std::string solver;
  double tolerance{};
  /// Outer boundary in the explicit stages: rollers (normal displacement
  /// held at the hand-off's) or the in-situ tractions alone.
  bool rollers{};
  /// The continuum counterpart of a tunnel run: "elastic" or "mohr_coulomb".
  std::string continuum;
  double dilation_angle{};  ///< deg, Mohr-Coulomb continuum
  /// Also solve the Mohr-Coulomb continuum with the FDEM's post-peak
  /// strength (c 0, residual friction): does the ground itself stand?
  bool continuum_post_peak{};
  /// Convergence-confinement: the support goes in this far behind the face
  /// [m]; the hand-off alpha follows from the longitudinal displacement
  /// profile (outputs/face_distance.hpp). None: at the last alpha.
  std::optional<double> install_at_face_distance;
};

struct EngineSettings {
  long steps{};
  double dt{};  ///< s; 0: automatic
  double dt_safety{};
  double damping_ratio{};
  /// Cundall local damping; -1 (neutral, the key has no default): the
  /// kind's (kTunnelLocalDamping in tunnel stages, none in specimen runs).
  /// Shown in the run summary.
  double local_damping = -1;
  double mass_damping{};     ///< 1/s
  bool kinetic_damping{};    ///< Cundall's kinetic damping in tunnel stages
  double gravity{};          ///< m/s^2, acting in -y
  bool mass_scaling{};       ///< quasi-static mass scaling (engine.mass_scaling resolved)
  double mass_scaling_dt{};  ///< s; 0: automatic
  double platen_velocity{};  ///< m/s, each platen (specimens)
  bool rough_platens{};      ///< platens hold the ends laterally (specimens)
  double stop_after_peak{};  ///< post-peak stop: fraction of the peak; 0: none
  bool contact{};
  double contact_penalty_factor{};  ///< times the rock's Young's modulus
  double contact_damping{};
  bool contact_friction{};
};

/// A stage kind's own values of its [[stages]] entry (soften's alpha,
/// grout's trigger). The kind's stage file defines them, its read fills
/// them and only its stage reads them: a new kind with a key of its own
/// changes nothing here.
struct StageValues {
  virtual ~StageValues() = default;
};

/// One construction stage of a tunnel run (scene [[stages]]).
struct StageSpec {
  std::string kind;  ///< soften, lining, remove_core, equilibrium
  long max_steps{};  ///< explicit steps at most
  double ratio{};    ///< stop when the unbalanced-force ratio is below
  double time{};     ///< stop after this simulated time [s]; 0: no limit
  int every_steps{};
  /// With the ratio, equilibrium needs the monitors settled: the largest
  /// monitor displacement change over one output interval, per 1000 steps,
  /// at most this fraction of the largest monitor displacement; 0: the
  /// ratio alone.
  double settle{};
  /// Equilibrium also needs the broken count settled: its growth over one
  /// output interval, per 1000 steps, at most this fraction of the count;
  /// 0: not checked. Key points can settle while cracks keep breaking.
  double broken_settle{};
  /// Consecutive outputs at which ratio and settle must both hold.
  int hold{};
  /// A monitor displaced by more than this fraction of the opening's span
  /// makes the run unstable (the opening is closing, not stabilising).
  double unstable_fraction{};
  /// Whether finding the opening unstable ends the run there; false runs
  /// on to the cap, the status stays unstable with the first finding.
  bool stop_when_unstable{};
  /// The kind's own values, made by the read of the kind named above as
  /// the scene is read (so of that kind's type); null for a kind with none.
  std::shared_ptr<const StageValues> own;
};

/// The steel of one kind of bolt (seed sec. 2.2).
struct SteelSettings {
  double diameter{}, row_spacing{};
  double young{}, yield_strength{}, ultimate_strength{};
  double tangent_modulus{}, shear_yield_strength{}, shear_fracture_energy{};
};

/// Rockbolts and cables (long bolts of strand, the seed's simplification),
/// each a segment from its head on the excavation boundary into the rock.
struct BoltSettings {
  SteelSettings bolt, cable;
  std::vector<std::array<double, 4>> segments;  ///< (x0, y0, x1, y1) per bolt, fans expanded
  std::vector<std::uint8_t> is_cable;           ///< per segment
  /// bolts.install_stress = "current": the strips keep the rock's stress
  /// and their cracks its tractions at installation (else stress-free).
  bool keep_current_stress{};
};

/// A bond modelled by crack elements: the grout (bolt-rock bond, and what
/// re-joins broken cracks when grouting) or the shotcrete-rock interface.
struct BondSettings {
  double young{}, tensile_strength{}, cohesion{}, friction_angle{};
  double fracture_energy_I{}, fracture_energy_II{};
};
using GroutSettings = BondSettings;

/// A history point of the user's (scene [[monitor]]): the rock's material
/// point at (x, y) of the mesh.
struct MonitorSpec {
  std::string name;
  double x{}, y{};             ///< [m]
  bool relative_to_support{};  ///< read from the first lining or bolts stage on
};

/// A borehole extensometer (scene [[extensometer]]): a head and `anchors`
/// anchors at equal spacing to `length` along a line into the rock.
struct ExtensometerSpec {
  std::string name;
  std::string from;           ///< key point the head is at (its outward normal); empty: given
  double head_x{}, head_y{};  ///< [m], when `from` is empty
  double dir_x{}, dir_y{};    ///< unit vector into the rock, when `from` is empty
  double length{};            ///< head to the deepest anchor [m]
  int anchors{};
  bool relative_to_support{};  ///< read from the first lining or bolts stage
};

struct OutputSettings {
  int every_steps{};
  bool vtk{};
  bool plots{};
  long checkpoint_every{};  ///< steps between checkpoints; 0: none
  /// Origin of the convergence plots: the support's installation (where
  /// the scene has one) rather than the in-situ state.
  bool convergence_from_support{};
};

/// Figures the run is compared with in report.md (scene [references]).
struct ReferenceSettings {
  /// [mm] by name: key points (radial, towards the opening positive),
  /// "wall_chord", "shoulder_chord" (closure); only those given.
  std::map<std::string, double> mm;
  bool from_support{};  ///< measured from the support's installation
  /// Key points read as monitoring does (record/survey_reading.hpp), not radially.
  bool survey{};
  std::string source;  ///< where they come from
};

/// [materials.rock] gsi: the model's rock is the rock mass derived from
/// the laboratory figures the section gives (rock_mass.hpp).
struct RockMassSpec {
  double gsi = 0, disturbance = 0, mi = 0;
  /// materials.rock.mass_ft_over_ucs: the mass's ft as this fraction of
  /// its Mohr-Coulomb UCS; 0: Hoek-Brown's s sigma_ci / mb.
  double ft_over_ucs = 0;
  double gamma_h = 0;  ///< the in-situ stress the fit is for [Pa]: insitu.sigma_v
  MaterialSpec lab;    ///< [materials.rock] as given: the intact rock
  IntactRock intact;   ///< E_i and sigma_ci (the lab set's Mohr-Coulomb UCS)
  RockMassFigures mass;
};

/// [joints] and [[joint_set]]: the joint material and where the traces come
/// from (the traces themselves are in mesh.joints).
struct JointSettings {
  double tensile_strength{}, cohesion{};               ///< Pa
  double friction_angle{}, residual_friction_angle{};  ///< deg
  double fracture_energy_I{}, fracture_energy_II{};    ///< J/m^2
  double penalty_factor{};                             ///< times the rock's Young's modulus
  bool barton_bandis{};  ///< shear_strength = "barton_bandis" (else Mohr-Coulomb)
  double jrc{}, jcs{};   ///< Barton-Bandis JRC [-] and JCS [Pa]; 0 with Mohr-Coulomb
  std::uint64_t seed{};
  double margin{};                       ///< m: the sets fill the opening's box grown by it
  std::string dfn_file;                  ///< resolved path; empty: none
  std::vector<mesh::JointSetSpec> sets;  ///< [[joint_set]]
  long set_traces{};                     ///< traces the sets generated
  long dfn_traces{};                     ///< traces read from dfn_file
};

struct Scene {
  std::string source;  ///< the scene file's path, or "default"
  std::string title;
  bool plane_stress{};
  mesh::MeshSpec mesh;
  std::map<mesh::Zone, MaterialSpec> materials;  ///< rock, core, lining as present
  /// [materials.invert]: the lining ring's floor part (an invert arch of
  /// its own material); none: the lining's material all round.
  std::optional<MaterialSpec> invert;
  std::optional<RockMassSpec> rock_mass;  ///< with materials.rock.gsi
  InsituSettings insitu;
  EngineSettings engine;
  std::vector<StageSpec> stages;  ///< explicit stages after the implicit one (tunnels)
  BoltSettings bolts;
  GroutSettings grout;
  BondSettings lining_interface;      ///< re-joins the lining-rock crack elements at installation
  JointSettings joints;               ///< [joints]; mesh.joints holds the traces
  std::vector<MonitorSpec> monitors;  ///< scene [[monitor]]
  std::vector<ExtensometerSpec> extensometers;  ///< scene [[extensometer]]
  OutputSettings output;
  ReferenceSettings references;
  bool lining_ring{};  ///< has_lining_ring(), as build_scene found it
  std::string
      canonical;  ///< the validated scene as TOML (overrides applied), for hashing and records
  /// canonical without output.checkpoint_every: what a checkpoint must match
  std::string restart_key;
  /// restart_key without output.plots and output.vtk: what a study's
  /// finished variant must match to be taken instead of rerun
  std::string results_key;
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
