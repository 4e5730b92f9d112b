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

#include "outputs/specimen_outputs.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run/checkpoint.hpp"
#include "run/engine_setup.hpp"
#include "run/interrupt.hpp"
#include "run/run.hpp"
#include "run/staged_run.hpp"
#include "stages/platen_load.hpp"

namespace rockfdem::workflows {
namespace {

// One specimen run, the phases in the order run() calls them.
class SpecimenRun : StagedRun<SpecimenOutputs> {
 public:
  SpecimenRun(const Scene& scene, const RunContext& ctx) : StagedRun(scene, ctx) {}

  int run() {
    make_mesh();
    build_engine();
    try {
      write_first_outputs();
      begin_stages();
      run_stages();
      stages_->energy_check().warn_if_unbalanced(engine(), ctx().quiet, record());
      outputs().finish(engine(), timer());
    } catch (const OutputError& e) {
      output_failed(e);
    }
    return 0;
  }

 private:
  // A restart's engine state and outputs are checked against the scene
  // here, before the output folder is claimed.
  void build_engine() {
    set_engine(
        make_engine(specimen_model_input(scene(), mesh(), ctx().threads), scene(), ctx().force_dt));
    if (resumed()) {
      try {
        load_resumed_engine();
        outputs().check_fits(resumed()->run.at("outputs"));
      } catch (const InputError& e) {
        throw InputError("checkpoint " + ctx().restart + ": " + e.what());
      }
      check_run_state_against_engine(ctx().restart, resumed()->run, scene(), engine().step_count(),
                                     engine().time());
    }
    timer().stamp("fdem setup");
  }

  // Only now, with engine.dt and the checkpoint accepted, is anything written.
  void write_first_outputs() {
    claim_output_dir(scene(), ctx(), true);
    mesh::write_msh(mesh(), output_path(ctx().output_dir, "mesh.msh"));
    timer().stamp("output");
  }

  // A fresh run records step 0; a restart takes its checkpoint's rows,
  // frames, peak and stage cursor instead.
  void begin_stages() {
    stages_.emplace(engine(), mesh(), stress_free_, scene(), ctx(), outputs(), no_key_points_,
                    no_bolts_, SupportMaterials{});
    stages_->model().platens = &outputs().load();
    resume_or_record(*stages_, {scene().stages.front().kind, 0});
  }

  void run_stages() {
    try {
      reporting_failure([&] { stages_->run_all(timer()); });
    } catch (const Interrupted& e) {
      outputs().report_interrupted(engine(), timer(), e.what());
      throw;
    }
  }

  // What a tunnel's stages use and a specimen has not: an in-situ field
  // (a specimen starts stress-free, with no core: alpha 0), key points, bolts.
  insitu::InsituField stress_free_ = [] {
    insitu::InsituField f;
    f.alpha = 0;
    return f;
  }();
  KeyPoints no_key_points_;
  fdem::BoltPlan no_bolts_;
  /// The stage loop, declared last so that it is destroyed first: it refers
  /// to the three members above (and to the base's engine, mesh and
  /// outputs, which outlive every member here).
  std::optional<StageRunner> stages_;
};

}  // namespace

int run_specimen(const Scene& scene, const RunContext& ctx) {
  return SpecimenRun(scene, ctx).run();
}

}  // namespace rockfdem::workflows
