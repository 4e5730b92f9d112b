// The explicit stages of a run, in the scene's order: a tunnel's
// construction stages, a specimen's load_platens. Each stage changes the
// model (soften the core, install the lining or the bolts, remove the core,
// grout) and then steps to its own stop criterion (unbalanced-force ratio,
// step cap, simulated time, a test after every step), telling the outputs
// (StepOutputs) at each output step.
//
// Checkpoints: a cursor (stage index, the stage's first step and time, the
// changes it made) and the runner's flags make its state(); restore() puts
// them back, and run_all() then continues the stage where it stopped.
// Output chunks end on multiples of the stage's every_steps counted from
// the stage's first step, so a restarted run outputs at the same steps as
// an uninterrupted one.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "outputs/monitors.hpp"
#include "outputs/step_outputs.hpp"
#include "record/phase_timer.hpp"
#include "record/run_context.hpp"
#include "record/run_figures.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/energy_check.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {

/// Where a run stands once its stages end (summary.json "status"):
/// completed (the last stage that stepped met its equilibrium criteria),
/// not_at_equilibrium (it stopped at its cap or time first), unstable (a
/// key point moved beyond the stage's fraction of the span, or accelerated:
/// the opening is closing, an engineering answer rather than a failure).
struct RunVerdict {
  std::string status = "completed";
  std::string message;  ///< what a not-completed status rests on; empty when completed
};

/// Throws InputError ("corrupt run state: ...", after `where`) unless a run
/// state's stage_monitor_u holds a pair (ux, uy) per key point.
void check_stage_monitor_u(std::size_t n_values, std::size_t n_key_points,
                           const std::string& where);

class StageRunner : public StageDriver {
 public:
  StageRunner(fdem::Engine& engine, const mesh::Mesh& m, const insitu::InsituField& handoff,
              const Scene& scene, const RunContext& ctx, StepOutputs& out,
              const KeyPoints& key_points, fdem::BoltPlan& bolts, SupportMaterials materials);
  /// Called to write a checkpoint: every `every` steps (at the next output
  /// step; 0: never) and when a signal interrupts the run.
  void set_checkpoint(long every, std::function<void()> save);
  /// The energy balance's check at every output step (and its end warning).
  const EnergyCheck& energy_check() const { return energy_; }
  /// Runs the stages from the cursor to the end. Throws Interrupted (after
  /// a checkpoint and a last history row) when SIGINT or SIGTERM arrives.
  void run_all(PhaseTimer& timer);
  /// One entry per stage run: kind, steps, simulated time, dt, final ratio, converged.
  const std::vector<StageRecord>& report() const override { return report_; }
  bool core_present() const { return model_.core_present; }
  /// The run's status from the stages run so far.
  RunVerdict verdict() const;
  nlohmann::json state() const;
  void restore(const nlohmann::json& state);

  // What the stages (stages/stage_<kind>.cpp) drive: StageDriver.
  StageModel& model() override { return model_; }
  bool step_until(const StageSpec& stage, const StopTest& stop) override;
  bool stopped() const override { return stopped_; }
  /// One output step of `stage` (a kind, or "handoff" numbered 0): history
  /// row, the energy balance's check, then the frame (RunOutputs).
  void record_output(const StageTag& stage, PhaseTimer& timer);
  double stage_time() const override { return model_.engine.time() - cursor_.t0; }
  long stage_steps() const override { return model_.engine.step_count() - cursor_.first; }

 private:
  struct Cursor {
    std::size_t index = 0;  ///< stage in scene.stages
    bool started = false;   ///< the stage's changes are made; it is stepping
    long first = 0;         ///< the stage's first step
    double t0 = 0;          ///< the simulated time at its start
    StageChanges changes;
    std::vector<double> monitor_u;  ///< monitors' (ux, uy) at the last output [m]
    int held = 0;                   ///< consecutive outputs meeting the stage's criteria
    std::vector<double> rates;      ///< largest monitor move per 1000 steps, per output [m]
    long broken = -1;               ///< broken crack elements at the last output; -1: none
  };
  /// Stops the run as unstable when a key point passed the stage's fraction
  /// of the span, has been accelerating, or (for a stage that stops on its
  /// `criteria`) keeps moving as fast with the forces balanced; true when it did.
  bool unstable(const StageSpec& stage, bool criteria);
  void run(const StageSpec& stage);
  /// Writes a checkpoint and a last history row, then throws Interrupted.
  [[noreturn]] void interrupted(const StageSpec& stage);
  /// One output step of the stage (record_output).
  void record_step(const StageSpec& stage) { record_output({stage.kind, number()}, *timer_); }
  /// The current stage's number (StageTag): after the implicit stage's 0
  /// where the run has one (tunnels), from 0 where not (specimens).
  int number() const;
  /// Whether the stage's stop criterion holds at this output: `reached`
  /// with a stop test, else ratio and settle held `hold` times.
  bool criterion_met(const StageSpec& stage, bool tested, bool reached);
  /// A checkpoint when checkpoint_every steps have passed since the last.
  void checkpoint_if_due();
  const std::vector<Monitor>& monitors() const { return key_points_.monitors(); }
  /// Monitors' displacements (ux, uy per monitor) [m].
  std::vector<double> monitor_displacements() const;
  /// The settle measure of the last output interval of `steps` steps: the
  /// largest monitor displacement change per 1000 steps over the largest
  /// monitor displacement (0 when nothing moved); updates cursor_.monitor_u.
  double settle_measure(long steps);
  /// The broken count's growth over the last `steps`, per 1000 steps, as a
  /// fraction of the count now (0 with none broken); none before a first output.
  std::optional<double> broken_growth(long steps);
  /// Steps `n` times unless a signal arrives (false) or the `stop` test
  /// holds after a step (*reached set).
  bool advance(long n, const StopTest& stop, bool* reached);
  /// The stage's report entry (what report() lists).
  StageRecord report_entry(const StageSpec& stage, const StageChanges& changes,
                           bool converged) const;

  StageModel model_;
  fdem::Engine& engine_;  ///< model_.engine
  StepOutputs& out_;
  const Scene& scene_;
  const KeyPoints& key_points_;  ///< displacements from the in-situ state
  PhaseTimer* timer_ = nullptr;  ///< run_all()'s
  Cursor cursor_;
  long checkpoint_every_ = 0;
  double last_settle_ = -1;  ///< settle_measure() of the stage's last interval; -1: none
  std::optional<double> last_broken_growth_;  ///< broken_growth() of that interval
  double last_rate_ = 0;                      ///< the largest monitor move per 1000 steps then [m]
  std::string moving_most_;                   ///< the monitor that moved most then
  RunVerdict unstable_;                       ///< the first finding that the opening is unstable
  bool stopped_ = false;                      ///< an unstable opening ended the stages
  double stage_dt_ = 0;                       ///< the dt of the stage's steps (one limit per stage)
  long last_checkpoint_ = 0;                  ///< step of the last checkpoint (or of the start)
  std::function<void()> save_checkpoint_;
  std::vector<StageRecord> report_;
  EnergyCheck energy_;
};

}  // namespace rockfdem::workflows
