// `rockfdem run` of a specimen (UCS, Brazilian disc): mesh, then the
// explicit engine loading the specimen between platens for engine.steps
// steps (or to the post-peak stop), with the stress-strain (or
// load-displacement) history, ParaView frames and a summary.
//
// Checkpoints as in tunnel runs: every output.checkpoint_every (or
// --checkpoint-every) steps at an output step, and at the step a
// SIGTERM/SIGINT stops the run. A checkpoint holds the engine's state (with
// it the step count, time and so the platen's travel) and the run's own:
// history rows, frames, the peak so far and the post-peak stop, so that
// `--restart` continues to the uninterrupted run's state and history.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands/commands.hpp"
#include "outputs/engine_report.hpp"
#include "outputs/history.hpp"
#include "outputs/run_plots.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run/checkpoint.hpp"
#include "run/interrupt.hpp"
#include "run/last_good.hpp"
#include "run/output_dir.hpp"
#include "run/phase_timer.hpp"
#include "run/progress.hpp"
#include "run/summary.hpp"
#include "stages/platen_load.hpp"
#include "stages/stage_inputs.hpp"

namespace rockfdem::workflows {
namespace {

std::vector<std::string> history_columns(bool disc) {
  std::vector<std::string> columns{
      "step",         "time",           "axial_strain", disc ? "tensile_stress" : "axial_stress",
      "platen_force", "kinetic_energy", "broken_I",     "broken_II",
      "broken_mixed"};
  for (const std::string& c : energy_columns()) columns.push_back(c);
  return columns;
}

// One specimen run from its first (or restarted) step to the end.
class SpecimenRun {
 public:
  SpecimenRun(const Scene& scene, const RunContext& ctx, const mesh::Mesh& m, fdem::Engine& e,
              RunRecord& summary, PhaseTimer& timer)
      : scene_(scene),
        ctx_(ctx),
        m_(m),
        e_(e),
        summary_(summary),
        timer_(timer),
        disc_(scene.mesh.kind == mesh::ModelKind::kBrazilian),
        load_(scene),
        history_(output_path(ctx.output_dir, "history.csv"), history_columns(disc_)),
        pvd_(output_path(ctx.output_dir, "fdem.pvd")),
        floor_(energy_floor(scene, m)),
        checkpoint_every_(ctx.checkpoint_every >= 0 ? ctx.checkpoint_every
                                                    : scene.output.checkpoint_every),
        last_checkpoint_(e.step_count()) {}

  /// A fresh run records step 0; a restart takes its checkpoint's rows,
  /// frames and peak instead.
  void begin(const Checkpoint* resume) {
    if (!resume) return guarded([&] { record(); });
    const nlohmann::json& s = resume->run.at("specimen");
    try {
      history_.restore(s.at("history").get<std::vector<std::vector<double>>>());
    } catch (const InputError& e) {
      throw InputError(ctx_.restart + ": " + e.what());
    }
    frame_ =
        restore_frames(s.at("frames"), run_dir_of(ctx_.restart), ctx_.output_dir, pvd_, summary_);
    load_.restore(s.at("load"));
    last_checkpoint_ = s.at("last_checkpoint").get<long>();
    summary_.restarted_from = CheckpointMark{ctx_.restart, e_.step_count()};
  }

  void run() {
    Progress progress(disc_ ? "brazilian" : "ucs", scene_.engine.steps, ctx_.quiet);
    while (!done()) {
      const long at = e_.step_count(), every = scene_.output.every_steps;
      // To the next output step: a restart from any step keeps the rows' steps.
      const long chunk = std::min(every - at % every, scene_.engine.steps - at);
      timer_.stamp("output");
      const bool whole = guarded([&] { return advance(chunk); });
      timer_.stamp("fdem");
      if (!whole) {
        // Checkpoint first: the extra row below is not one an uninterrupted run writes.
        save_checkpoint();
        guarded([&] { record(); });
        interrupted();
      }
      guarded([&] { record(); });
      progress.update(e_.step_count(), e_.time());
      if (interrupt_requested()) {
        save_checkpoint();
        interrupted();
      }
      if (!done() && checkpoint_every_ > 0 &&
          e_.step_count() - last_checkpoint_ >= checkpoint_every_) {
        save_checkpoint();
        timer_.stamp("checkpoint");
      }
    }
    progress.finish(e_.step_count(), e_.time());
  }

  void finish() {
    if (scene_.output.plots)
      specimen_plots(e_, history_, disc_, ctx_.output_dir, summary_, ctx_.quiet);
    timer_.stamp("output");
    summary_.status = "completed";
    report_engine(e_, timer_, summary_);
    warn_if_unbalanced(e_, floor_, ctx_.quiet, summary_);
    const nlohmann::json specimen = load_.report();
    summary_.add_figures("specimen", specimen);
    summary_.skipped.push_back("insitu: a specimen starts stress-free");
    summary_.set_timings(timer_);
    summary_.write(output_path(ctx_.output_dir, "summary.json"));
    if (!ctx_.quiet)
      std::cout << (disc_ ? "peak tensile stress " : "peak axial stress ")
                << specimen["peak_stress"].get<double>() / 1e6 << " MPa at step "
                << specimen["peak_step"].get<long>() << " (upper platen, read every step), broken "
                << e_.broken_counts().total() << " of " << e_.n_cracks()
                << " crack elements, state hash " << e_.state_hash() << '\n'
                << timer_.table();
  }

 private:
  bool done() const { return load_.stopped() || e_.step_count() >= scene_.engine.steps; }

  // Steps until `n` are done, the post-peak stop or a signal (false).
  bool advance(long n) {
    for (long i = 0; i < n; ++i) {
      if (interrupt_requested()) return false;
      e_.step();
      if (load_.after_step(e_)) return true;
    }
    return true;
  }

  void record() {
    const PlatenReading r = load_.read(e_);
    const fdem::BrokenCounts b = e_.broken_counts();
    std::vector<double> row{
        double(e_.step_count()), e_.time(),        r.strain,          r.stress,       r.force,
        e_.kinetic_energy(),     double(b.mode_I), double(b.mode_II), double(b.mixed)};
    const fdem::EnergyBalance energy = e_.energy_balance();
    for (double v : energy_row(energy)) row.push_back(v);
    history_.add(row);
    check_energy(energy, e_.step_count(), floor_);  // before the frame: keep the last good one
    if (scene_.output.vtk) write_frame();
    last_good_.take(e_, energy);
  }

  void write_frame() {
    char name[32];
    std::snprintf(name, sizeof name, "fdem_%04d.vtu", frame_++);
    coupling::VtkGrid g = coupling::fdem_grid(e_, m_);
    coupling::add_frame_info(g.field, "load_platens", e_.step_count(), e_.time());
    coupling::write_vtu(g, output_path(ctx_.output_dir, name));
    pvd_.add(e_.time(), name);
    pvd_.write();
  }

  void save_checkpoint() {
    Checkpoint c;
    c.run = {{"specimen",
              {{"history", history_.rows()},
               {"frames", frames_state(pvd_)},
               {"load", load_.state()},
               {"last_checkpoint", e_.step_count()}}}};
    std::ostringstream bytes;
    e_.save_state(bytes);
    c.engine_state = bytes.str();
    const std::string path = write_checkpoint(ctx_.output_dir, e_.step_count(), scene_, c);
    summary_.checkpoint = CheckpointMark{path, e_.step_count()};
    last_checkpoint_ = e_.step_count();
  }

  [[noreturn]] void interrupted() {
    const int sig = interrupt_requested();
    const std::string why = "interrupted by signal " + std::to_string(sig) + " at step " +
                            std::to_string(e_.step_count());
    report_engine(e_, timer_, summary_);
    summary_.add_figures("specimen", load_.report());
    write_summary("interrupted", why);
    throw Interrupted(sig, why + "; outputs and a checkpoint are written");
  }

  void write_summary(const char* status, const std::string& why) {
    summary_.status = status;
    summary_.failure = why;
    summary_.set_timings(timer_);
    summary_.write(output_path(ctx_.output_dir, "summary.json"));
  }

  // Runs `f`; a NumericalError in it (a diverged step, a broken energy
  // balance) leaves the history and frames so far as the last good output.
  template <class F>
  auto guarded(F&& f) -> decltype(f()) {
    try {
      return f();
    } catch (const NumericalError& err) {
      last_good_.report_failure(e_, timer_, err.what(), summary_);
      write_summary("failed", err.what());
      throw;
    }
  }

  const Scene& scene_;
  const RunContext& ctx_;
  const mesh::Mesh& m_;
  fdem::Engine& e_;
  RunRecord& summary_;
  PhaseTimer& timer_;
  bool disc_;
  PlatenLoad load_;
  History history_;
  coupling::PvdCollection pvd_;
  double floor_;
  long checkpoint_every_, last_checkpoint_;
  int frame_ = 0;
  LastGoodState last_good_;
};

}  // namespace

int run_specimen(const Scene& scene, const RunContext& ctx) {
  PhaseTimer timer;
  // A bad checkpoint is refused before anything is written.
  const bool restart = !ctx.restart.empty();
  const Checkpoint resume = restart ? read_checkpoint(ctx.restart, scene) : Checkpoint{};
  RunRecord summary(scene, ctx.threads);
  summary.note_turned_off(scene.output, "fdem.pvd, fdem_NNNN.vtu", true);
  mesh::MeshReport report;
  const mesh::Mesh m = keeping_threads(ctx, [&] { return mesh::build_mesh(scene.mesh, &report); });
  summary.record_mesh(m, report);
  timer.stamp("mesh");

  fdem::Engine engine =
      make_engine(specimen_model_input(scene, m, ctx.threads), scene, ctx.force_dt);
  timer.stamp("fdem setup");
  // Only now, with engine.dt accepted, is anything written.
  if (claim_output_dir(scene, ctx) && !restart) remove_checkpoints(ctx.output_dir);
  mesh::write_msh(m, output_path(ctx.output_dir, "mesh.msh"));
  if (restart) {
    std::istringstream state(resume.engine_state);
    engine.load_state(state);
  }
  timer.stamp("output");

  SpecimenRun run(scene, ctx, m, engine, summary, timer);
  run.begin(restart ? &resume : nullptr);
  run.run();
  run.finish();
  return 0;
}

}  // namespace rockfdem::workflows
