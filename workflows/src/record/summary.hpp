// The run's record, written as summary.json (docs/output-formats.md). The
// stages and outputs fill it as the run goes; summary.cpp alone turns it
// into JSON. It is written atomically at the end of a run (status
// completed or not_at_equilibrium), and where a run stops early once its
// output directory is claimed: a numerical failure, a stage's refusal of
// engine.dt, a signal. A scene or checkpoint refused before anything is
// written leaves no summary; checkpoints do not rewrite it.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "record/continuum_figures.hpp"
#include "record/phase_timer.hpp"
#include "record/run_figures.hpp"
#include "record/support_equilibrium.hpp"
#include "record/support_figures.hpp"
#include "record/support_verdict.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::mesh {
struct Mesh;
struct MeshReport;
}  // namespace rockfdem::mesh
namespace rockfdem::insitu {
struct InsituField;
}

namespace rockfdem::workflows {

struct Scene;
struct OutputSettings;

/// summary.json's "format_version": raised whenever a key is renamed,
/// removed or changes meaning (docs/output-formats.md lists the changes).
constexpr int kSummaryFormatVersion = 3;

/// A checkpoint a run wrote or continued from, and its step.
struct CheckpointMark {
  std::string path;
  long step = 0;
};

class RunRecord {
 public:
  /// The fixed keys (format_version, rockfdem_version, scene, overrides,
  /// title), with counts.bolts the scene's bolts and cables and the
  /// scene's warnings.
  RunRecord(const Scene& scene, int threads);

  /// How the run ended: completed, not_at_equilibrium, failed, interrupted
  /// (empty: not yet; no key).
  std::string status;
  std::optional<std::string> status_reason;  ///< why not at equilibrium
  std::optional<std::string> failure;        ///< the diagnostic of a failed or interrupted run
  std::vector<std::string> warnings;         ///< the scene's, then the run's
  std::vector<std::string> skipped;          ///< modules and outputs left out, and why
  std::optional<CheckpointMark> restarted_from;
  std::optional<CheckpointMark> checkpoint;  ///< the last one written
  int threads = 0;
  std::optional<mesh::MeshReport> mesh;  ///< "mesh": sizes and quality
  ModelCounts counts;
  EngineState state;                     ///< steps, dt, ..., state_hash
  double triangle_steps_per_second = 0;  ///< "throughput" over the time loop
  std::optional<EngineFigures> engine;
  std::optional<std::pair<double, double>> dt_range;  ///< dt_min, dt_max [s]
  InsituRecord insitu;
  std::optional<FdemRecord> fdem;
  MonitorRecord monitors;
  std::vector<GroundReactionPoint> ground_reaction_curve;  ///< empty: not drawn (no key)
  std::optional<ConvergenceConfinementFigures> convergence_confinement;
  /// Where the support lines meet the ground's curve, found once from the
  /// three figures it rests on (record_convergence_confinement); none: no
  /// curve to meet (fewer than two points) or no convergence_confinement.
  std::optional<SupportEquilibria> support_equilibria;
  /// The stages' kinds by number ("insitu" first): history.csv's stage
  /// column and fdem.stages[].stage index it.
  std::optional<std::vector<std::string>> history_stages;
  std::optional<BoltRecord> bolts;
  LiningRecord lining;                    ///< empty: no key
  std::optional<SupportVerdict> support;  ///< whether lining and bolts hold; none: no support
  std::optional<ResolutionFigures> resolution;
  std::optional<RockPlausibilityFigures> rock_plausibility;
  std::optional<RockMassSpec> rock_mass;  ///< the scene's lab-to-rock-mass reduction
  std::optional<OuterBoundaryFigures> outer_boundary;
  std::optional<DampingFigures> damping;
  std::map<std::string, ExtensometerFigures> extensometers;  ///< empty: no key
  std::optional<BrokenZoneRecord> broken_zone;
  std::optional<JointRecord> joints;       ///< "joints": a model with joint traces
  std::optional<SpecimenRecord> specimen;  ///< a specimen's peak and post-peak stop
  // Once the core is removed: the open excavation (no lining ring) and the
  // construction sequence's continuum counterpart (none: not solved).
  std::optional<ContinuumComparison> comparison;
  std::optional<CounterpartComparison> continuum_comparison;
  std::optional<PostPeakCounterpart> continuum_post_peak;

  /// Notes in `skipped` the outputs the scene turned off: `paraview_files`
  /// (what output.vtk = false leaves out) and, where the command renders
  /// any, the plots.
  void note_turned_off(const OutputSettings& output, const std::string& paraview_files,
                       bool renders_plots);
  /// counts (triangles; the mesh's vertices as nodes), "mesh" (sizes and
  /// quality) and the state hash of the mesh: its vertex coordinates' bits.
  /// A later stage's figures replace counts and hash.
  void record_mesh(const mesh::Mesh& m, const mesh::MeshReport& report);
  /// Each implicit solve's alpha and iterations, and the state hash of the
  /// last: the bits of its displacement field (ux, uy per vertex), which
  /// the coordinates' bits would blur.
  void record_insitu(const std::vector<insitu::InsituField>& fields);
  /// convergence_confinement, and where its support lines meet the ground's
  /// curve (support_equilibria): after ground_reaction_curve and
  /// continuum_comparison, the curves it meets.
  void record_convergence_confinement(ConvergenceConfinementFigures c);
  void set_timings(const PhaseTimer& timer);

  /// summary.json's content.
  nlohmann::json to_json() const;
  void write(const std::string& path) const;

 private:
  std::string scene_source_;  ///< "scene": the scene file's path, or "default"
  std::vector<std::string> overrides_;
  std::string title_;
  std::map<std::string, double> timings_;  ///< per phase (snake_case) and "total" [s]
  /// The process's peak resident set at each phase's end [MiB]
  std::map<std::string, double> peak_memory_mib_;
};

/// summary.json's "fdem"."stages" (also the checkpoints' copy of them).
nlohmann::json stage_records_json(const std::vector<StageRecord>& stages);
/// The stage records a checkpoint file holds (stage_records_json's form).
std::vector<StageRecord> stage_records_from_json(const nlohmann::json& stages);
/// A stage's "changes" (also the checkpoints' copy of the running stage's).
nlohmann::json stage_changes_json(const StageChanges& changes);
/// The changes a checkpoint file holds (stage_changes_json's form), each
/// entry checked first with stage_change_mismatch.
StageChanges stage_changes_from_json(const nlohmann::json& changes);
/// What a "changes" entry named `key` must be ("an integer", ...); empty
/// when `value` is that.
std::string stage_change_mismatch(const std::string& key, const nlohmann::json& value);

}  // namespace rockfdem::workflows
