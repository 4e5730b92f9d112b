// What a tunnel run (Run) and a specimen run share: the scene, a restart's
// checkpoint, the record, the outputs, the mesh and the engine, and the
// phases that treat them alike. `Outputs` is RunOutputs or SpecimenOutputs
// (both instantiated in staged_run.cpp). The stage loop is not here: it
// refers to the run's own members (a tunnel's key points, hand-off and
// bolts) as well as to these, so each run declares it as its last member,
// destroyed before everything it refers to.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "record/phase_timer.hpp"
#include "record/run_context.hpp"
#include "record/summary.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/checkpoint.hpp"
#include "run/stage_runner.hpp"

namespace rockfdem::workflows {

template <class Outputs>
class StagedRun {
 public:
  StagedRun(const StagedRun&) = delete;
  StagedRun& operator=(const StagedRun&) = delete;
  virtual ~StagedRun() = default;

 protected:
  /// Reads a restart's checkpoint: a bad one is refused before anything
  /// is written.
  StagedRun(const Scene& scene, const RunContext& ctx);

  // What a run reads and fills; the base keeps them and their lifetimes.
  const Scene& scene() const { return scene_; }
  const RunContext& ctx() const { return ctx_; }
  const mesh::Mesh& mesh() const { return mesh_; }
  PhaseTimer& timer() { return timer_; }
  RunRecord& record() { return record_; }
  Outputs& outputs() { return out_; }
  /// The engine, once set_engine has given it.
  fdem::Engine& engine() { return *engine_; }
  /// A restart's checkpoint; null for a fresh run. Its engine state is
  /// empty once load_resumed_engine has read it.
  const Checkpoint* resumed() const { return restart_ ? &resume_ : nullptr; }
  /// Reads a restart's engine state into the engine (throws InputError as
  /// Engine::load_state does), then lets its bytes go: kept, they would
  /// hold most of the engine's size again until the run ends.
  void load_resumed_engine();

  void make_mesh();
  /// The run's engine, built from the scene and mesh; given once.
  void set_engine(fdem::Engine&& engine);
  /// With the run's stage loop made: a restart takes its checkpoint's
  /// outputs and stage cursor, a fresh run records its first output step
  /// (stage `first`); then the checkpoints are armed.
  void resume_or_record(StageRunner& stages, const StageTag& first);
  /// summary.json alone, with `status` and the timings so far: a run
  /// that ends before its outputs' own summary (or writes none).
  void write_summary(const std::string& status);
  /// Runs `f`; a NumericalError in it is reported (fail).
  void reporting_failure(const std::function<void()>& f);
  /// summary.json of a run a NumericalError stopped, then the error again
  /// with failure_message(what): the history and frames so far are the
  /// last good output.
  [[noreturn]] void fail(const std::string& what);
  /// An output that could not be written (disk full): summary.json of
  /// the failed run where it can still be written, then the error again,
  /// its message saying that summary.json records the failure or why it
  /// could not be written either.
  [[noreturn]] void output_failed(const OutputError& e);

 private:
  /// The run state a restart needs beyond the stages' and outputs'.
  virtual void add_run_state(nlohmann::json& /*run*/) const {}
  /// The message of a NumericalError as the run reports it.
  virtual std::string failure_message(const std::string& what) const { return what; }
  void save_checkpoint(const StageRunner& stages);

  const Scene& scene_;
  const RunContext& ctx_;
  PhaseTimer timer_;
  const bool restart_;
  Checkpoint resume_;            ///< a restart's checkpoint
  const long checkpoint_every_;  ///< steps between checkpoints (0: none)
  RunRecord record_;
  Outputs out_;
  mesh::Mesh mesh_;
  std::optional<fdem::Engine> engine_;
};

}  // namespace rockfdem::workflows
