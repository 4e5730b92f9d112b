// Everything a tunnel run writes besides the engine's work: history.csv,
// ParaView frames, the ground reaction curve, PNG plots and summary.json.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "outputs/bolt_results.hpp"
#include "outputs/face_distance.hpp"
#include "outputs/frame_output.hpp"
#include "outputs/history.hpp"
#include "outputs/implicit_sample.hpp"
#include "outputs/instruments.hpp"
#include "outputs/last_good.hpp"
#include "outputs/lining_output.hpp"
#include "outputs/monitors.hpp"
#include "outputs/outer_boundary.hpp"
#include "outputs/run_plots.hpp"
#include "outputs/run_timeline.hpp"
#include "outputs/step_outputs.hpp"
#include "record/phase_timer.hpp"
#include "record/run_context.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

class RunOutputs : public StepOutputs {
 public:
  RunOutputs(const Scene& scene, const RunContext& ctx, RunRecord& summary);
  /// summary.json's insitu keys and the implicit part of the ground
  /// reaction curve (from `samples`, one per field). `fields` are the
  /// caller's, kept until the outputs finish; the last, the hand-off's, is
  /// read whole (insitu.vtu, the frames), the others for their reports.
  void record_insitu(const mesh::Mesh& m, const std::vector<insitu::InsituField>& fields,
                     std::vector<ImplicitSample> samples);
  /// insitu.install_at_face_distance: where it put the support, and the
  /// implicit fields' samples down to alpha = 0 it was read from, which
  /// the ground reaction curve then shows (beyond the hand-off).
  void record_face_distance(const FaceDistanceFigures& f, std::vector<ImplicitSample> curve);
  /// The outputs that observe the output steps, made before anything is
  /// written (a restart's run state is checked against history_columns()
  /// next): the key points, displaced from `handoff` and with `m`'s outer
  /// boundary defining the rigid translation removed from reported
  /// displacements; the bolts' results (axial stress in the frames, section
  /// forces) when `bolts` has any; the `instruments` (the scene's monitors,
  /// extensometers and broken depth along rays); the lining ring's forces;
  /// the ParaView frames (their first once record_insitu has given the
  /// implicit fields); history.csv's columns.
  void begin(const mesh::Mesh& m, const KeyPoints& key_points, const fdem::BoltPlan& bolts,
             std::unique_ptr<Instruments> instruments);
  /// history.csv's columns for these key points: the run's figures, then
  /// the bolts' and the instruments' (begin).
  std::vector<std::string> history_columns(const std::vector<Monitor>& monitors) const;
  /// A `lining` or `bolts` stage installed its support (Instruments).
  void support_installed(const fdem::Engine& e) override {
    if (instruments_) instruments_->support_installed(key_points_->node_displacements(e));
  }
  /// Whether the lining ring is installed as lining (before, its triangles
  /// are ground still to be excavated): its forces are written from then.
  void set_lining_installed(bool installed) override;
  /// An output step's history row, with the columns and files of the
  /// outputs that observe output steps (bolts, instruments, lining);
  /// before the run's checks of the step, so that a failing step has its row.
  void record_rows(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                   double support_ratio, const fdem::EnergyBalance& energy) override;
  /// A grout stage's re-joined cracks: grouted_cracks.csv (crack, x, y);
  /// a jointed model's joint_profile_stage_<N>.csv.
  void stage_done(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                  StageChanges& done) override;
  /// The outer boundary's rigid rotation [rad], its largest kept for the summary.
  double outer_rotation(const fdem::Engine& e) override;
  /// The output step once the run's checks passed: the ParaView frame (if
  /// enabled) and the last good state.
  void record_frame(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                    const fdem::EnergyBalance& energy, PhaseTimer& timer) override;
  /// The outputs that observe output steps, in history.csv's column order.
  std::vector<OutputStepObserver*> observers() const;
  /// What a restart needs to continue the outputs: history rows, stage
  /// names, frames written.
  nlohmann::json state() const;
  /// Puts state() back; frames listed there are copied from `from_dir` when
  /// the restart writes to another directory.
  void restore(const nlohmann::json& state, const std::string& from_dir);
  /// Counts, monitors, broken cracks, hash, plots, timings; writes summary.json.
  /// `energy`: the stage loop's check, whose end warning the summary carries.
  void finish(const fdem::Engine& e, const mesh::Mesh& m, PhaseTimer& timer,
              const fdem::BoltPlan& bolts);
  /// The hand-off state, before the first explicit step: what a failure in
  /// that step reports as the last good state (nothing is written yet).
  void keep_start(const fdem::Engine& e) { last_good_.take(e, e.energy_balance()); }
  /// summary.json of a run a NumericalError stopped (`why`): the last good
  /// state's figures (LastGoodState), the dt range, status and diagnostic.
  void report_failure(const fdem::Engine& e, PhaseTimer& timer, const std::string& why);

 private:
  /// The record's monitors: each key point's ux, uy [mm] and position, vault
  /// settlement, wall and shoulder convergence [mm], the scene's monitors.
  MonitorRecord monitor_figures(const fdem::Engine& e) const;
  /// The hand-off step and dt_min, dt_max over it, the stages' dt and the
  /// last step's (the record holds the stage reports by then).
  void report_dt();
  /// The record's ground reaction curve: the implicit stage's points and
  /// the end of the run (after the monitors).
  void record_ground_reaction();
  /// summary "convergence_confinement" (after the monitors and the curve).
  void record_convergence_confinement(const fdem::Engine& e, const mesh::Mesh& m);
  /// With plots asked for and a display: the writer, after the run's
  /// curves against time (run_plots.hpp) and ground_reaction.png; else null.
  std::unique_ptr<PlotWriter> curves();
  /// The explicit stages on the history's time axis (run_timeline.hpp).
  std::vector<StageSpan> timeline() const;
  /// The history row of the support's installation (the first lining or
  /// bolts stage's start); nothing when the run installed no support.
  std::optional<std::size_t> support_row() const;
  /// Key points' radial displacement and the chords' closure [mm] since
  /// the support's installation (the record's figures less the history's then).
  std::map<std::string, double> since_support() const;
  /// The key points' survey readings (record/survey_reading.hpp) since then.
  std::map<std::string, double> survey_since_support() const;
  /// Adds each key point's `radial_since_support_mm` to the record's monitors.
  void add_since_support(MonitorRecord& monitors) const;
  /// Adds each key point's `radial_at_handoff_mm` (history's first row).
  void add_at_handoff(MonitorRecord& monitors) const;
  /// Adds each key point's displacement as read from the unloaded mesh.
  void add_from_unloaded(MonitorRecord& monitors) const;
  /// report.md from the record as it stands.
  void write_report() const;
  /// summary "resolution" (h / l_ch) and "broken_zone" (depth, clearance to
  /// the fracture zone's edge), with warnings when either limits the answer.
  void damage_outputs(const fdem::Engine& e, const mesh::Mesh& m);
  /// summary "joints" and joints.csv: traces meshed and joint elements by state.
  void record_joints(const fdem::Engine& e, const mesh::Mesh& m);
  /// summary "lining": the lining-rock crack elements and how many broke;
  /// returns whether the ring is installed, to report its section forces.
  bool lining_outputs(const fdem::Engine& e, const mesh::Mesh& m);
  const Scene& scene_;  ///< read by the constructor, finish() and report_failure() alone
  const RunContext& ctx_;
  RunRecord& summary_;
  // What the outputs before finish() take from the scene.
  bool vtk_ = false;                          ///< output.vtk
  bool lining_ring_ = false;                  ///< the model has a lining ring
  InsituSettings insitu_;                     ///< the in-situ stress, p0 of the curve in pressure
  std::optional<insitu::KirschCase> kirsch_;  ///< the Kirsch case the scene is, if any
  std::vector<std::uint8_t> is_cable_;        ///< per bolt segment
  std::optional<RingSections> sections_;      ///< materials.lining's (and .invert's) sections
  double invert_top_;  ///< the ring's floor part lies below [m]; -infinity: no part of its own
  const std::vector<insitu::InsituField>* fields_ = nullptr;  ///< record_insitu's
  std::optional<FaceDistanceFigures> face_;                   ///< insitu.install_at_face_distance's
  std::vector<ImplicitSample> samples_;                       ///< record_insitu's
  std::vector<ImplicitSample> curve_samples_;  ///< with face_: the curve to alpha = 0
  std::unique_ptr<History> history_;
  std::unique_ptr<Instruments> instruments_;
  std::unique_ptr<FrameOutput> frames_;  ///< from begin
  const fdem::BoltPlan* bolts_ = nullptr;
  std::unique_ptr<BoltResults> bolt_results_;  ///< with bolts in the scene
  std::unique_ptr<LiningOutput> lining_;       ///< null: no lining ring
  bool lining_installed_ = false;
  const KeyPoints* key_points_ = nullptr;  ///< the run's, from begin
  double max_rotation_deg_ = 0;            ///< largest |rotation| of the outer boundary so far
  std::vector<std::string> stage_names_;
  std::vector<std::string> stage_joint_profiles_;  ///< joint_profile_stage_<N>.csv written
  std::vector<std::string> pictures_;              ///< PNG files rendered, for report.md
  double handoff_dt_ = 0;  ///< dt of the hand-off step (0: not taken by this run's record)
  LastGoodState last_good_;
  double fdem_seconds_at_start_ = 0;
};

}  // namespace rockfdem::workflows
