// `rockfdem run` of a tunnel: the staged sequence of the seed paper.
//
//   1. mesh (gmsh)
//   2. in-situ and core softening, implicit (deal.II), one solve per alpha
//   3. the continuum solves the end state is compared with (before the
//      engine exists, so that their memory and the engine's are not held
//      at once: the run's peak is the larger of the two)
//   4. hand-off: the last alpha's field becomes the engine's initial state
//      (the core keeps alpha_h E, so a later factor alpha is alpha / alpha_h)
//   5. the scene's explicit stages in order (soften, lining, remove_core,
//      equilibrium), each to its own stop criterion
//
// Nothing is written until the engine has accepted the scene (engine.dt
// included) and a restart's checkpoint fits it: a refused run leaves OUTDIR
// as it found it.
#include "run/run.hpp"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "outputs/broken_zone.hpp"
#include "outputs/continuum_comparison.hpp"
#include "outputs/face_distance.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run/continuum_solve.hpp"
#include "run/engine_setup.hpp"
#include "run/handoff_choice.hpp"
#include "run/implicit_check.hpp"
#include "run/interrupt.hpp"
#include "run/process_memory.hpp"
#include "scene/scene_reader.hpp"

namespace rockfdem::workflows {
namespace {

// Bolt installation is state a restart needs: which bolts and their stress then.
nlohmann::json bolt_state(const fdem::BoltPlan& bolts) {
  return {{"installed", bolts.installed}, {"installed_stress", bolts.installed_stress}};
}

void restore_bolts(const nlohmann::json& s, fdem::BoltPlan& bolts, const std::string& file) {
  std::vector<char> installed = s.at("installed").get<std::vector<char>>();
  auto stress = s.at("installed_stress").get<std::vector<std::vector<std::array<double, 3>>>>();
  // The plan comes from the scene: a checkpoint of another plan would be
  // indexed out of its bounds.
  if (installed.size() != bolts.specs.size() || stress.size() != bolts.specs.size())
    throw InputError(file + ": corrupt run state: field 'bolts' holds " +
                     std::to_string(installed.size()) + " bolts; the scene has " +
                     std::to_string(bolts.specs.size()));
  for (std::size_t b = 0; b < stress.size(); ++b)
    if (!stress[b].empty() && stress[b].size() != bolts.owned[b].size())
      throw InputError(file + ": corrupt run state: field 'bolts.installed_stress' of bolt " +
                       std::to_string(b) + " has " + std::to_string(stress[b].size()) +
                       " triangles; the bolt owns " + std::to_string(bolts.owned[b].size()));
  bolts.installed = std::move(installed);
  bolts.installed_stress = std::move(stress);
}

// The run state's fields sized by the key points: history rows (one value
// per history.csv column) and the stage's monitor displacements (a pair per
// key point). Checked here as the restore would, before anything is written.
void check_key_point_fields(const nlohmann::json& run, const std::vector<Monitor>& monitors,
                            const RunOutputs& out, const std::string& file) {
  const std::size_t width = out.history_columns(monitors).size();
  for (const auto& row : run.at("outputs").at("history"))
    if (row.size() != width)
      throw InputError(file + ": corrupt run state: a history row has " +
                       std::to_string(row.size()) + " values; history.csv has " +
                       std::to_string(width) + " columns");
  check_stage_monitor_u(run.at("stages").at("stage_monitor_u").size(), monitors.size(),
                        file + ": ");
}

/// A restart's bolts put back, and the run state checked against the
/// scene, mesh and the loaded engine, before the output folder is claimed:
/// a checkpoint that does not fit leaves OUTDIR as it found it. Returns the
/// hand-off's unbalanced-force ratio.
double restore_before_writing(const Checkpoint& resume, const std::string& file, const Scene& scene,
                              const std::vector<Monitor>& monitors, const RunOutputs& out,
                              const fdem::Engine& engine, fdem::BoltPlan& bolts) {
  check_run_state_against_engine(file, resume.run, scene, engine.step_count(), engine.time());
  restore_bolts(resume.run.at("bolts"), bolts, file);
  fdem::index_bolt_cracks(engine, bolts);
  check_key_point_fields(resume.run, monitors, out, file);
  return resume.run.at("start_ratio").get<double>();
}

// The record's "fdem" of a run the stages left early: their reports alone.
FdemRecord stages_only(const StageRunner& stages) {
  FdemRecord f;
  f.stages = stages.report();
  return f;
}

// What a tunnel run does not support, refused before the checkpoint is read:
// a stress gradient with no weight to hold it would set the box moving.
void refuse_unsupported(const Scene& scene) {
  if (scene.insitu.unit_weight > 0 && !(scene.engine.gravity > 0))
    throw InputError(
        scene.source +
        ": key 'insitu.unit_weight' = " + detail::number_text(scene.insitu.unit_weight) +
        ": the explicit stages need the weight this gradient holds; allowed: 0, or "
        "set engine.gravity (unit_weight / materials.rock.density = " +
        detail::number_text(scene.insitu.unit_weight / scene.materials.at(mesh::kRock).density) +
        " m/s^2), which then takes the gradient from the density");
}

}  // namespace

Run::Run(const Scene& scene, const RunContext& ctx) : StagedRun(scene, ctx) {}

std::vector<insitu::InsituField> Run::solve_fields(const insitu::InsituSpec& spec) {
  return keeping_threads(ctx(),
                         [&] { return insitu::solve_insitu(mesh(), returning_code_pages(spec)); });
}

int Run::run() {
  make_mesh();
  stop_if_interrupted("meshing");
  solve_insitu();
  try {
    if (scene().stages.empty()) return write_implicit_results_only();
    solve_references();
    release_phase_memory();  // deal.II's and PETSc's: the engine is built into it
    build_engine();
    place_instruments();
    write_first_outputs();
    take_handoff_step();
    begin_stages();
    run_stages();
    compare_with_references();
    finish();
  } catch (const OutputError& e) {
    output_failed(e);
  }
  return 0;
}

void Run::solve_insitu() {
  // The face distance reads the whole list's fields again: all are held.
  const bool face = scene().insitu.install_at_face_distance.has_value();
  const auto hold = face ? FieldSampler::Hold::kAll : FieldSampler::Hold::kHandoff;
  std::optional<FieldSampler> sampler;
  if (!face) {  // the face distance changes the sequence the counterpart solves
    sampler.emplace(scene(), mesh());
    try {
      counterpart_ = solve_with_counterpart(*sampler, hold);
    } catch (const InputError&) {
      // Solved again alone below: a failing implicit stage fails there
      // again, and the counterpart, solved apart later, says why it fails.
      counterpart_.reset();
    } catch (const NumericalError&) {
      counterpart_.reset();
    }
  }
  if (!counterpart_) {
    sampler.emplace(scene(), mesh());
    const insitu::InsituSpec spec = sampler->attach(insitu_spec(scene()), hold);
    fields_ = solve_fields(spec);
  }
  samples_ = sampler->take(fields_);
  if (face) install_at_face_distance(*sampler);
  for (const ImplicitSample& s : samples_)
    check_implicit_field(scene(), mesh(), s.alpha, {s.inverted, s.first_inverted});
  choose_handoff_field();
  timer().stamp("insitu");
  stop_if_interrupted("the implicit stage");
}

// The elastic counterpart's construction sequence begins with this stage's
// alphas: the solve goes on to the counterpart's end (CounterpartTail)
// instead of the counterpart solving those alphas again (13 to 16 s of a
// 420k-triangle run). The implicit stage's fields are the first ones, the
// same as alone. None (nothing solved) where the counterpart cannot
// continue.
std::optional<ContinuumStates> Run::solve_with_counterpart(FieldSampler& sampler,
                                                           FieldSampler::Hold hold) {
  insitu::InsituSpec spec = sampler.attach(insitu_spec(scene()), hold);
  std::optional<CounterpartTail> tail = counterpart_tail(scene(), spec);
  if (!tail) return std::nullopt;
  spec.on_field = [&t = *tail, own = spec.on_field](insitu::InsituField& f) {
    const bool implicit = t.seen < t.implicit_alphas;
    t.take(f);
    if (implicit) own(f);
  };
  fields_ = solve_fields(spec);
  fields_.resize(tail->implicit_alphas);
  return std::move(tail->states);
}

// insitu.install_at_face_distance: the ground reaction curve down to the
// open hole (alpha = 0 added when the list lacks it) gives the alpha where
// the wall has made the profile's share of its final displacement; the
// fields above it stay, one solved there is handed over, and the support
// stages install on it. Each elastic alpha is a solve of its own (no ring
// carries load in the implicit stage here), so the fields above are those
// a list ending at that alpha gives.
void Run::install_at_face_distance(FieldSampler& sampler) {
  insitu::InsituSpec spec = insitu_spec(scene());
  std::vector<ImplicitSample> curve = samples_;
  if (curve.back().alpha > 0) {
    spec.alphas = {0.0};
    std::vector<insitu::InsituField> open =
        solve_fields(sampler.attach(spec, FieldSampler::Hold::kNone));
    curve.push_back(sampler.take(open)[0]);
  }
  const FaceDistanceFigures f = face_distance_installation(scene(), mesh(), curve);
  const auto below = [&](double alpha) { return alpha <= f.alpha; };
  fields_.erase(std::remove_if(fields_.begin(), fields_.end(),
                               [&](const insitu::InsituField& x) { return below(x.alpha); }),
                fields_.end());
  samples_.erase(std::remove_if(samples_.begin(), samples_.end(),
                                [&](const ImplicitSample& x) { return below(x.alpha); }),
                 samples_.end());
  spec.alphas = {f.alpha};
  std::vector<insitu::InsituField> at =
      solve_fields(sampler.attach(spec, FieldSampler::Hold::kAll));
  samples_.push_back(sampler.take(at)[0]);
  fields_.push_back(std::move(at[0]));
  outputs().record_face_distance(f, std::move(curve));
}

// The field handed over (insitu.handoff): the fields after it were solved to
// find it and are not part of the run; those before it are read through
// their samples alone, so their arrays go.
void Run::choose_handoff_field() {
  std::vector<double> ratios;
  for (const ImplicitSample& s : samples_) ratios.push_back(s.strength_ratio);
  const HandoffChoice c = choose_handoff(scene(), std::move(ratios));
  handoff_figures_.rule = scene().insitu.handoff_first_crack ? "first_crack" : "last";
  for (const insitu::InsituField& f : fields_) handoff_figures_.alphas.push_back(f.alpha);
  handoff_figures_.strength_ratio = c.strength_ratio;
  fields_.erase(fields_.begin() + long(c.index) + 1, fields_.end());
  samples_.erase(samples_.begin() + long(c.index) + 1, samples_.end());
  for (std::size_t i = 0; i + 1 < fields_.size(); ++i) release_arrays(fields_[i]);
  if (handoff().ux.size() != mesh().n_vertices())
    throw std::logic_error("the hand-off field was not held whole");
}

// [[stages]] holds only "insitu": the scene asks for the elastic implicit
// results alone.
int Run::write_implicit_results_only() {
  write_first_outputs();
  record().skipped.push_back("fdem: the scene's only stage is the implicit in-situ stage");
  write_summary("completed");
  return 0;
}

void Run::build_engine() {
  EngineSetup setup = setup_engine(scene(), mesh(), handoff(), ctx().threads, ctx().force_dt);
  support_ = setup.support;
  stage_damping_ = setup.stage_damping;
  bolts_ = std::move(setup.bolts);
  set_engine(std::move(setup.engine));
}

// Key points, instruments and the outputs observing them before anything
// is written: a point in no triangle or in the core is refused first, as
// is a restart's run state that does not fit them.
void Run::place_instruments() {
  key_points_ = KeyPoints(tunnel_monitors(scene().mesh, mesh(), engine()), mesh(), handoff().ux,
                          handoff().uy);
  const std::vector<Monitor>& monitors = key_points_.monitors();
  outputs().begin(mesh(), key_points_, bolts_,
                  std::make_unique<Instruments>(scene(), mesh(), engine(), monitors, bolts_));
  if (resumed()) {
    try {
      load_resumed_engine();
    } catch (const InputError& e) {
      throw InputError("checkpoint " + ctx().restart + ": its engine state: " + e.what());
    }
    start_ratio_ = restore_before_writing(*resumed(), ctx().restart, scene(), monitors, outputs(),
                                          engine(), bolts_);
  }
  timer().stamp("fdem setup");
}

// The scene is accepted: make (or claim) OUTDIR and write what the mesh and
// the implicit stage give.
void Run::write_first_outputs() {
  claim_output_dir(scene(), ctx(), true);
  mesh::write_msh(mesh(), output_path(ctx().output_dir, "mesh.msh"));
  outputs().record_insitu(mesh(), fields_, samples_);
  timer().stamp("output");
}

// The first explicit step, with the hand-off's damping: its unbalanced
// force ratio is the start's. A restart has it from its checkpoint.
void Run::take_handoff_step() {
  if (!resumed()) {
    for (std::size_t t = 0; t < mesh().n_triangles(); ++t)
      if (!handoff().active[t]) engine().set_active(t, false);
    outputs().keep_start(engine());
    reporting_failure([&] { engine().step(); });
    release_free_heap();  // the set-up's scratch and the first stability limit's
    start_ratio_ = engine().unbalanced_force_ratio();
    engine().set_damping(stage_damping_);
  }
  timer().stamp("fdem setup");
}

void Run::begin_stages() {
  stages_.emplace(engine(), mesh(), handoff(), scene(), ctx(), outputs(), key_points_, bolts_,
                  support_);
  resume_or_record(*stages_, {"handoff", 0});
}

void Run::run_stages() {
  try {
    stages_->run_all(timer());
  } catch (const Interrupted&) {
    record().status = "interrupted";
    record().fdem = stages_only(*stages_);
    finish_outputs();
    throw;
  } catch (const NumericalError& e) {
    // The frames and history rows written so far are the last good output.
    record().fdem = stages_only(*stages_);
    fail(e.what());
  } catch (const InputError& e) {
    const std::string why = stage_input_error(e);
    record().fdem = stages_only(*stages_);
    outputs().report_failure(engine(), timer(), why);
    throw InputError(why);
  }
}

// The sequence the counterpart solves: the face distance moved the
// hand-off, and the support with it.
Scene Run::solved_sequence() const {
  Scene solved = scene();
  if (scene().insitu.install_at_face_distance) solved.insitu.alpha = handoff_figures_.alphas;
  return solved;
}

void Run::solve_references() {
  references_ = solve_continuum_references(solved_sequence(), ctx(), mesh(),
                                           std::exchange(counterpart_, std::nullopt));
  timer().stamp("continuum counterpart");
  stop_if_interrupted("the continuum counterpart");
}

// With the core removed: the relaxed state against the continuum's open
// excavation and the counterpart solved before the engine was built.
void Run::compare_with_references() {
  if (stages_->core_present()) return;
  if (references_.open_hole)
    record().comparison =
        compare_with_continuum(scene(), mesh(), engine(), *references_.open_hole,
                               output_path(ctx().output_dir, "fdem_vs_continuum.csv"));
  compare_with_continuum_counterpart(solved_sequence(), ctx(), mesh(), engine(), handoff(),
                                     references_, key_points_.monitors(),
                                     bolt_triangles(&bolts_, mesh().n_triangles()), record());
  timer().stamp("continuum counterpart");
}

// The run's closing checks, then the outputs' last files: the energy
// warning is the run's judgement, the outputs only write it down.
void Run::finish_outputs() {
  stages_->energy_check().warn_if_unbalanced(engine(), ctx().quiet, record());
  outputs().finish(engine(), mesh(), timer(), bolts_);
}

// The verdict of the stages, the run's figures and the last outputs.
void Run::finish() {
  const RunVerdict verdict = stages_->verdict();
  record().status = verdict.status;
  if (!verdict.message.empty()) {
    record().status_reason = verdict.message;
    record().warnings.push_back(verdict.status + ": " + verdict.message);
    std::cerr << "warning: " << verdict.status << ": " << verdict.message << '\n';
  }
  record().damping = DampingFigures{stage_damping_.local, stage_damping_.mass_proportional,
                                    stage_damping_.kinetic, scene().engine.local_damping >= 0};
  record().fdem = stages_only(*stages_);
  record().fdem->unbalanced_ratio_at_start = start_ratio_;
  record().fdem->unbalanced_ratio_at_end = engine().unbalanced_force_ratio();
  record().fdem->handoff_alpha = handoff().alpha;
  handoff_figures_.crack_points_over_strength = engine().crack_prestress_clipped();
  record().fdem->handoff = handoff_figures_;
  finish_outputs();
  if (!ctx().quiet)
    std::cout << "status: " << verdict.status
              << (verdict.message.empty() ? " (every stage met its criteria)"
                                          : " (" + verdict.message + ")")
              << (record().support ? "; " + record().support->line() : "") << '\n';
}

// A signal between the implicit phases: nothing to checkpoint yet. The
// scene is valid, so the output directory may be made for the summary.
void Run::stop_if_interrupted(const char* after) {
  const int sig = interrupt_requested();
  if (!sig) return;
  claim_output_dir(scene(), ctx(), false);
  write_summary("interrupted");
  throw Interrupted(sig, "interrupted by " + signal_text(sig) + " after " + after +
                             "; summary.json is written (no explicit step yet, so no checkpoint)");
}

void Run::add_run_state(nlohmann::json& run) const {
  run["bolts"] = bolt_state(bolts_);
  run["start_ratio"] = start_ratio_;
}

std::string Run::failure_message(const std::string& what) const {
  return with_likely_cause(scene(), what);
}

// An explicit dt above the limit a later stage brings (lining, bolts, grout
// stiffen the model) is found only there, after outputs exist.
std::string Run::stage_input_error(const InputError& e) {
  const bool dt = scene().engine.dt > 0 && engine().critical_dt() < scene().engine.dt;
  if (!dt) return scene().source + ": " + e.what();
  return scene().source + ": key 'engine.dt' = " + detail::number_text(scene().engine.dt) +
         " s: " + e.what() + " (engine.dt = 0 follows the limit through every stage)";
}

int run_tunnel(const Scene& scene, const RunContext& ctx) {
  refuse_unsupported(scene);
  return Run(scene, ctx).run();
}

}  // namespace rockfdem::workflows
