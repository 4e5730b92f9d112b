// The typed parts of a run's record (RunRecord): what the stages and the
// outputs fill and the report, the plots and the timeline read. Each is
// written to summary.json by summary.cpp alone, under the key its comment
// names (docs/output-formats.md).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"

namespace rockfdem::workflows {

/// The key point moving most over a stage's last output interval.
struct MovingMost {
  std::string key_point;
  double mm_per_1000_steps = 0;
};

/// What a stage changed in the model, as the stage reports it
/// ("fdem"."stages"[i]."changes", each member under its own name; unset
/// members are left out). Stage::apply fills it, Stage::step may add to it.
struct StageChanges {
  // lining
  std::optional<long> interface_cracks;  ///< lining-rock crack elements bonded
  // bolts
  std::optional<long> bolts;           ///< bolts and cables installed
  std::optional<long> bolt_triangles;  ///< their steel triangles made active
  std::optional<long> steel_cracks;    ///< their steel crack elements
  std::optional<long> grout_cracks;    ///< their grout-bond crack elements
  /// bolts.install_stress = "current": crack points whose traction reached
  /// the steel's or grout's strength and start at it
  std::optional<long> clipped_points;
  // lining, bolts
  std::optional<long> broken_at_install;  ///< broken crack elements right after installation
  // grout
  std::optional<bool> triggered;  ///< its trigger (or the stage's time) was reached
  /// The trigger that fired ("time": the stage's time passed first), or the
  /// one given when none fired; its value, and the step and simulated time
  /// [s] at which it fired.
  std::optional<std::string> trigger;
  std::optional<double> trigger_value;
  std::optional<long> trigger_step;
  std::optional<double> trigger_time;
  std::optional<long> broken_at_support;      ///< N0 of the since-support triggers
  std::optional<long> broken_before;          ///< broken crack elements when the stepping ended
  std::optional<long> rejoined;               ///< of them, re-joined with grout (triggered only)
  std::optional<long> broken_after;           ///< broken crack elements after the re-joining
  std::optional<std::string> positions_file;  ///< the re-joined ones' list (grouted_cracks.csv)
  /// The re-joined crack elements and their midpoints [m], in crack order:
  /// what the stage did, for the outputs to list (not in summary.json).
  struct Grouted {
    std::size_t crack = 0;
    double x = 0, y = 0;
  };
  std::vector<Grouted> grouted;
  // soften
  std::optional<bool> skipped;  ///< the hand-off was already at or below its alpha
  /// A stage kind none of these describe (one registered outside the
  /// library) reports by name; the names differ from the members above.
  using Figure = std::variant<bool, long, double, std::string>;
  std::map<std::string, Figure> other;
};

/// One explicit stage as it ended ("fdem"."stages"[i]).
struct StageRecord {
  std::string kind;
  int number = 0;        ///< the stage's number (outputs/step_outputs.hpp, StageTag)
  StageChanges changes;  ///< the stage's own report of its changes
  long steps = 0;
  double simulated_time = 0;     ///< [s]
  std::optional<double> dt;      ///< [s]; none when it took no step
  double unbalanced_ratio = 0;   ///< at its end
  std::optional<double> settle;  ///< of its last output interval; none before one
  /// The broken count's growth then, per 1000 steps, of the count; none before one.
  std::optional<double> broken_growth;
  std::optional<bool> converged;  ///< none when it took no step
  long max_steps = 0;
  // Its criteria ("criteria"): the scene's StageSpec values.
  double ratio = 0;
  double settle_limit = 0;
  double broken_settle_limit = 0;  ///< 0: not a criterion
  int hold = 0;
  double unstable_fraction = 0;
  std::optional<MovingMost> moving_most;
  double support_pressure_ratio = 0;  ///< the core's factor alpha at its end
};

/// "specimen": a specimen's peak load, read from the upper platen after
/// every step, and its post-peak stop.
struct SpecimenRecord {
  std::string kind;            ///< "ucs" or "brazilian"
  double peak_stress = 0;      ///< UCS: mean axial stress; disc: tensile stress 2P/(pi D) [Pa]
  double peak_force = 0;       ///< the platen's reaction per unit thickness at the peak [N/m]
  long peak_step = 0;          ///< the step of the peak
  double peak_strain = 0;      ///< nominal axial strain at the peak [-]
  double strain_rate = 0;      ///< nominal axial strain rate 2 v / L [1/s]
  double stop_after_peak = 0;  ///< loading.stop_after_peak [-]
  std::optional<long> stopped_after_peak_at_step;  ///< none: not stopped after the peak
  /// UCS: the pre-peak modulus, the slope of stress against nominal strain
  /// over 0.2-0.6 of the peak (prepeak_curve.hpp) [Pa]; none for a disc.
  std::optional<double> modulus;
};

/// One implicit solve ("insitu"."stages"[i], `rockfdem insitu` only).
struct InsituSolveFigures {
  double alpha = 0;
  std::string solver;
  long dofs = 0;
  double assembly_seconds = 0, solve_seconds = 0, total_seconds = 0;
  double preconditioner_seconds = 0;  ///< of solve_seconds: GAMG's hierarchy built
  double unbalanced_ratio = 0;
};

/// "insitu": the implicit stage, one entry per core stiffness factor alpha.
struct InsituRecord {
  std::vector<double> alpha;
  std::vector<long> solver_iterations;  ///< CG iterations (0: direct)
  std::optional<double> kirsch_rel_l2;  ///< stress error against Kirsch; none: not compared
  std::optional<double> kirsch_wall_ur_rel_l2;
  std::optional<long> kirsch_triangles;
  std::optional<std::vector<InsituSolveFigures>> stages;
};

/// Where the implicit stage handed over ("fdem"."handoff"): the rule, and
/// for every solved alpha how far its field loads the crack elements.
struct HandoffFigures {
  std::string rule;                    ///< insitu.handoff: "last" or "first_crack"
  std::vector<double> alphas;          ///< every alpha solved
  std::vector<double> strength_ratio;  ///< largest crack traction / strength, per alpha
  /// Crack element points whose traction the engine clipped to their
  /// strength at the hand-off (over-stress handed over at once).
  long crack_points_over_strength = 0;
};

/// The explicit part of a run ("fdem"): present once the stages report.
struct FdemRecord {
  std::optional<double> unbalanced_ratio_at_start;  ///< after the hand-off step
  std::optional<double> unbalanced_ratio_at_end;
  std::optional<double> handoff_alpha;
  std::optional<double> handoff_dt;  ///< "handoff_step": one step of this dt [s]
  std::optional<HandoffFigures> handoff;
  std::optional<std::vector<StageRecord>> stages;
};

/// The engine's state the record describes (steps, dt, simulated_time,
/// broken, energy, state_hash): the end's, or a failed run's last good one.
struct EngineState {
  long steps = 0;
  double dt = 0;              ///< [s]
  double simulated_time = 0;  ///< [s]
  fdem::BrokenCounts broken;
  std::optional<fdem::EnergyBalance> energy;  ///< [J/m]; none before the engine's
  std::string state_hash;
};

/// "counts": the model's sizes.
struct ModelCounts {
  long triangles = 0;
  long nodes = 0;  ///< the engine's (before it, the mesh's vertices)
  long crack_elements = 0;
  long bolts = 0;  ///< bolts and cables
};

/// The engine's own figures at the end ("fdem_modules", "contact",
/// "mass_scaling", "memory_bytes", "memory_bytes_per_triangle",
/// "memory_breakdown_bytes").
struct EngineFigures {
  fdem::PhaseTimes modules;  ///< [s] per phase of the step
  fdem::ContactCounters contact;
  fdem::MassScalingReport mass_scaling;
  long memory_bytes = 0;
  double memory_bytes_per_triangle = 0;
  /// The engine's arrays one by one (Engine::memory_breakdown()): which of
  /// them a mesh size or a scene makes large, read from any run.
  std::vector<fdem::MemoryPart> memory_parts;
};

/// One key point of the opening ("monitors".NAME) [mm, m].
struct KeyPointFigures {
  double ux_mm = 0, uy_mm = 0, u_mm = 0;
  double radial_mm = 0;  ///< towards the opening, convergence positive
  double x = 0, y = 0;   ///< its node
  double inward_x = 0, inward_y = 0;
  std::optional<double> radial_since_support_mm;
  /// As monitoring reads it (record/survey_reading.hpp), since the support.
  std::optional<double> survey_since_support_mm;
  /// At the hand-off (history's first row): what the implicit stage gave.
  std::optional<double> radial_at_handoff_mm;
  /// (ux, uy) as a model loaded from zero stress on a fixed base reads it
  /// (outputs/loading_frame.hpp); none where the loading is not uniform.
  std::optional<std::array<double, 2>> from_unloaded_mm;
};

/// A scene's [[monitors]] point ("monitors".NAME) [mm, m].
struct MonitorPointFigures {
  double ux_mm = 0, uy_mm = 0, u_mm = 0;
  double x = 0, y = 0;
  long triangle = 0;
  std::string from;  ///< "support" or "in-situ state"
};

/// The vault's settlement and the two chords' closure [mm].
struct ChordFigures {
  double vault_settlement_mm = 0;
  double wall_chord_convergence_mm = 0;
  double shoulder_chord_convergence_mm = 0;
};

/// "monitors": the key points, the chords and the scene's monitors.
struct MonitorRecord {
  std::map<std::string, KeyPointFigures> key_points;
  std::optional<ChordFigures> chords;
  std::map<std::string, MonitorPointFigures> points;
};

/// A support characteristic line ("convergence_confinement"."support"[i]).
struct SupportLineFigures {
  std::string name;
  double p_max_Pa = 0, stiffness_Pa_per_m = 0, max_displacement_mm = 0;
  std::string note;  ///< a ring of parts: which part's p_max, how K is taken
};

/// "convergence_confinement": the support's lines on the equivalent
/// circle, where they start and where the run ended.
struct ConvergenceConfinementFigures {
  double radius_m = 0;            ///< the equivalent circle's
  double lining_thickness_m = 0;  ///< the ring's on it (0: none)
  std::vector<SupportLineFigures> support;
  /// The first support stage's start: the key points' mean radial
  /// displacement [mm] and the core's alpha then.
  double install_radial_mm = 0, install_alpha = 0;
  /// With insitu.install_at_face_distance.
  struct FaceDistance {
    double face_distance_m = 0, plastic_radius_m = 0, x_star = 0, r_star = 0, u_star = 0;
    double alpha = 0;
  };
  std::optional<FaceDistance> face;
  /// The end of the run: the key points' mean radial displacement [mm] and
  /// the lining's pressure, its mean thrust over R [Pa] (none: no lining).
  double end_radial_mm = 0;
  std::optional<double> end_pressure_Pa;
};

/// One point of the ground reaction curve ("ground_reaction_curve"[i]).
struct GroundReactionPoint {
  double support_pressure_ratio = 0;  ///< the core's factor alpha (not p/p0: ground_reaction.hpp)
  double vault_settlement_mm = 0;
  std::string point;  ///< what the point is, in words
  /// An implicit solve's point in pressure, per key point.
  struct InPressure {
    double radial_mm = 0;    ///< towards the opening
    double pressure_Pa = 0;  ///< the core's normal traction on the opening, compression +
    double insitu_Pa = 0;    ///< the in-situ normal stress there, p0
  };
  std::map<std::string, InPressure> key_points;
};

}  // namespace rockfdem::workflows
