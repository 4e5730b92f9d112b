// `rockfdem run` of a specimen (UCS, Brazilian disc): mesh, the explicit
// engine with its platens, then the stage loop (StageRunner) over the
// scene's stages, [load_platens]: the specimen loaded for engine.steps
// steps or to the post-peak stop, with the stress-strain (or
// load-displacement) history, ParaView frames and a summary
// (SpecimenOutputs).
//
// Checkpoints as in tunnel runs: every output.checkpoint_every (or
// --checkpoint-every) steps at an output step, and at the step a
// SIGTERM/SIGINT stops the run. A checkpoint holds the engine's state (with
// it the step count, time and so the platen's travel), the stage loop's
// cursor and the outputs' rows, frames, peak and post-peak stop, so that
// `--restart` continues to the uninterrupted run's state and history.
#include <optional>
#include <sstream>

#include "outputs/specimen_outputs.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run/checkpoint.hpp"
#include "run/interrupt.hpp"
#include "run/output_dir.hpp"
#include "run/phase_timer.hpp"
#include "run/run.hpp"
#include "run/stage_runner.hpp"
#include "run/summary.hpp"
#include "stages/platen_load.hpp"
#include "stages/stage_inputs.hpp"

namespace rockfdem::workflows {
namespace {

// One specimen run, the phases in the order run() calls them.
class SpecimenRun {
 public:
  SpecimenRun(const Scene& scene, const RunContext& ctx)
      : scene_(scene),
        ctx_(ctx),
        restart_(!ctx.restart.empty()),
        summary_(scene, ctx.threads),
        out_(scene, ctx, summary_) {}

  int run() {
    read_restart();
    make_mesh();
    build_engine();
    write_first_outputs();
    begin_stages();
    run_stages();
    out_.finish(*engine_, timer_, stages_->energy_check());
    return 0;
  }

 private:
  // A bad checkpoint is refused before anything is written.
  void read_restart() {
    if (restart_) resume_ = read_checkpoint(ctx_.restart, scene_);
  }

  void make_mesh() {
    mesh::MeshReport report;
    mesh_ = keeping_threads(ctx_, [&] { return mesh::build_mesh(scene_.mesh, &report); });
    summary_.record_mesh(mesh_, report);
    timer_.stamp("mesh");
  }

  // A restart's engine state and outputs are checked against the scene
  // here, before the output folder is claimed.
  void build_engine() {
    engine_.emplace(
        make_engine(specimen_model_input(scene_, mesh_, ctx_.threads), scene_, ctx_.force_dt));
    if (restart_) {
      try {
        std::istringstream state(resume_.engine_state);
        engine_->load_state(state);
        out_.check_fits(resume_.run.at("outputs"));
      } catch (const InputError& e) {
        throw InputError("checkpoint " + ctx_.restart + ": " + e.what());
      }
    }
    timer_.stamp("fdem setup");
  }

  // Only now, with engine.dt and the checkpoint accepted, is anything written.
  void write_first_outputs() {
    claim_output_dir(scene_, ctx_, true);
    mesh::write_msh(mesh_, output_path(ctx_.output_dir, "mesh.msh"));
    timer_.stamp("output");
  }

  // A fresh run records step 0; a restart takes its checkpoint's rows,
  // frames, peak and stage cursor instead.
  void begin_stages() {
    stages_.emplace(*engine_, mesh_, stress_free_, scene_, ctx_, out_, no_key_points_, no_bolts_,
                    SupportMaterials{});
    stages_->model().platens = &out_.load();
    if (restart_) {
      try {
        out_.restore(resume_.run.at("outputs"), run_dir_of(ctx_.restart));
        stages_->restore(resume_.run.at("stages"));
      } catch (const InputError& e) {
        throw InputError(ctx_.restart + ": " + e.what());
      }
      summary_.restarted_from = CheckpointMark{ctx_.restart, engine_->step_count()};
    } else {
      reporting_failure([&] { stages_->record_output(scene_.stages.front().kind, timer_); });
    }
    stages_->set_checkpoint(
        ctx_.checkpoint_every >= 0 ? ctx_.checkpoint_every : scene_.output.checkpoint_every,
        [this] { save_checkpoint(); });
  }

  void run_stages() {
    try {
      reporting_failure([&] { stages_->run_all(timer_); });
    } catch (const Interrupted& e) {
      out_.report_interrupted(*engine_, timer_, e.what());
      throw;
    }
  }

  void save_checkpoint() {
    Checkpoint c;
    c.run = {{"stages", stages_->state()}, {"outputs", out_.state()}};
    std::ostringstream bytes;
    engine_->save_state(bytes);
    c.engine_state = bytes.str();
    const std::string path = write_checkpoint(ctx_.output_dir, engine_->step_count(), scene_, c);
    summary_.checkpoint = CheckpointMark{path, engine_->step_count()};
  }

  // Runs `f`; a NumericalError in it (a diverged step, a broken energy
  // balance) leaves the history and frames so far as the last good output.
  template <class F>
  void reporting_failure(F&& f) {
    try {
      f();
    } catch (const NumericalError& err) {
      out_.report_failure(*engine_, timer_, err.what());
      throw;
    }
  }

  const Scene& scene_;
  const RunContext& ctx_;
  PhaseTimer timer_;
  const bool restart_;
  Checkpoint resume_;
  RunRecord summary_;
  SpecimenOutputs out_;
  mesh::Mesh mesh_;
  std::optional<fdem::Engine> engine_;
  std::optional<StageRunner> stages_;
  // What a tunnel's stages use and a specimen has not: an in-situ field
  // (a specimen starts stress-free, with no core: alpha 0), key points, bolts.
  insitu::InsituField stress_free_ = [] {
    insitu::InsituField f;
    f.alpha = 0;
    return f;
  }();
  std::vector<Monitor> no_key_points_;
  fdem::BoltPlan no_bolts_;
};

}  // namespace

int run_specimen(const Scene& scene, const RunContext& ctx) {
  return SpecimenRun(scene, ctx).run();
}

}  // namespace rockfdem::workflows
