// `rockfdem run` of a tunnel: the staged sequence of the seed paper.
//
//   1. mesh (gmsh)
//   2. in-situ and core softening, implicit (deal.II), one solve per alpha
//   3. hand-off: the last alpha's field becomes the engine's initial state
//      (the core keeps alpha_h E, so a later factor alpha is alpha / alpha_h)
//   4. the scene's explicit stages in order (soften, lining, remove_core,
//      equilibrium), each to its own stop criterion
//
// Outer boundary: the in-situ traction sigma0 . n on all four sides, as in
// the implicit stage, so the box is in equilibrium with the initial stress
// at step 0. With insitu.rollers (the default) each side is also a roller:
// its normal displacement stays at the hand-off's, so the traction there
// becomes the roller's reaction (the same at step 0) and the model has no
// rigid-body mode left. Tractions alone leave three: the loads are
// self-equilibrated, but once a ring around the opening is broken the outer
// block can turn on it (outer_boundary.hpp guards against it). Reported
// displacements have the mean translation of the outer boundary removed, as
// the implicit stage removes its rigid motion.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "checkpoint.hpp"
#include "commands.hpp"
#include "continuum_comparison.hpp"
#include "continuum_counterpart.hpp"
#include "history.hpp"
#include "implicit_check.hpp"
#include "interrupt.hpp"
#include "monitors.hpp"
#include "output_dir.hpp"
#include "phase_timer.hpp"
#include "progress.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/coupling/plot.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run_outputs.hpp"
#include "scene_reader.hpp"
#include "stage_inputs.hpp"
#include "stage_runner.hpp"
#include "summary.hpp"

namespace rockfdem::workflows {
namespace {

// The in-situ stress tensor, tension positive: -sH along `angle`, -sV across.
std::array<double, 3> insitu_tensor(const InsituSettings& s) {
  const double a = s.angle_deg * M_PI / 180, c = std::cos(a), n = std::sin(a);
  return {-(s.sigma_h * c * c + s.sigma_v * n * n), -(s.sigma_h * n * n + s.sigma_v * c * c),
          -(s.sigma_h - s.sigma_v) * n * c};
}

// Traction sigma0 . n on each side of the box (outward normals); with
// rollers, the normal velocity held at zero too.
std::vector<fdem::BoundaryCondition> box_conditions(const InsituSettings& s) {
  const auto sig = insitu_tensor(s);
  const std::pair<int, std::array<double, 2>> sides[] = {{mesh::kLeft, {-1, 0}},
                                                         {mesh::kRight, {1, 0}},
                                                         {mesh::kBottom, {0, -1}},
                                                         {mesh::kTop, {0, 1}}};
  std::vector<fdem::BoundaryCondition> bcs;
  for (const auto& [tag, n] : sides) {
    fdem::BoundaryCondition bc;
    bc.tag = tag;
    bc.tx = sig[0] * n[0] + sig[2] * n[1];
    bc.ty = sig[2] * n[0] + sig[1] * n[1];
    if (s.rollers) (n[0] != 0 ? bc.x : bc.y) = fdem::Constraint::kFixed;
    bcs.push_back(bc);
  }
  return bcs;
}

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
  const std::size_t n_u = run.at("stages").at("stage_monitor_u").size();
  if (n_u != 2 * monitors.size())
    throw InputError(file + ": corrupt run state: field 'stages.stage_monitor_u' holds " +
                     std::to_string(n_u) + " values; the model's " +
                     std::to_string(monitors.size()) + " key points need " +
                     std::to_string(2 * monitors.size()));
}

/// A restart's engine state and bolts put back, and the run state checked
/// against the scene and mesh, before the output folder is claimed: a
/// checkpoint that does not fit leaves OUTDIR as it found it. Returns the
/// hand-off's unbalanced-force ratio.
double restore_before_writing(const Checkpoint& resume, const std::string& file,
                              const std::vector<Monitor>& monitors, const RunOutputs& out,
                              fdem::Engine& engine, fdem::BoltPlan& bolts) {
  try {
    std::istringstream state(resume.engine_state);
    engine.load_state(state);
  } catch (const InputError& e) {
    throw InputError("checkpoint " + file + ": its engine state: " + e.what());
  }
  restore_bolts(resume.run.at("bolts"), bolts, file);
  check_key_point_fields(resume.run, monitors, out, file);
  return resume.run.at("start_ratio").get<double>();
}

// A signal between the implicit phases: nothing to checkpoint yet. The
// scene is valid, so the output directory may be made for the summary.
void stop_if_interrupted(const Scene& scene, RunRecord& summary, const RunContext& ctx,
                         const PhaseTimer& timer, const char* after) {
  const int sig = interrupt_requested();
  if (!sig) return;
  claim_output_dir(scene, ctx);
  summary.status = "interrupted";
  summary.set_timings(timer);
  summary.write(output_path(ctx.output_dir, "summary.json"));
  throw Interrupted(sig, std::string("interrupted by signal ") + std::to_string(sig) + " after " +
                             after +
                             "; summary.json is written (no explicit step yet, so no checkpoint)");
}

// The scene is accepted: make (or claim) OUTDIR and write what the mesh and
// the implicit stage give.
void write_first_outputs(const Scene& scene, const RunContext& ctx, bool restart,
                         const mesh::Mesh& m, const std::vector<insitu::InsituField>& fields,
                         RunOutputs& out) {
  const bool claimed = claim_output_dir(scene, ctx);
  // A fresh run's checkpoints must not mix with an earlier run's (and a
  // folder no run claimed keeps whatever it holds).
  if (!restart && claimed) remove_checkpoints(ctx.output_dir);
  mesh::write_msh(m, output_path(ctx.output_dir, "mesh.msh"));
  out.record_insitu(m, fields);
}

/// The bolts marked on the mesh and their steel models. The engine's
/// refusals (a strip too stiff or too soft for the rock around it, a bolt
/// crossing no triangle edge) arise from the design and the mesh together;
/// they get the scene and its keys here, before anything is written.
fdem::BoltPlan planned_bolts(const Scene& scene, fdem::ModelInput& in) {
  try {
    return fdem::plan_bolts(in, bolt_specs(scene));
  } catch (const InputError& e) {
    throw InputError(scene.source + ": the bolt design cannot be modelled on this mesh (" +
                     e.what() +
                     "); adjust [bolts] / [cables] (young, diameter, row_spacing, "
                     "strengths), materials.rock.young or mesh.size_near");
  }
}

/// Runs `f`; a NumericalError in it (the hand-off step or a stage) writes
/// the failure summary first, with the likely cause when the in-situ stress
/// is large against the rock's modulus.
template <class F>
void reporting_failure(const Scene& scene, RunOutputs& out, const fdem::Engine& e,
                       PhaseTimer& timer, F&& f) {
  try {
    f();
  } catch (const NumericalError& err) {
    const std::string why = with_likely_cause(scene, err.what());
    out.report_failure(e, timer, why);
    throw NumericalError(why);
  }
}

}  // namespace

fdem::ModelInput engine_input(const Scene& scene, const mesh::Mesh& m,
                              const insitu::InsituField& handoff, int threads) {
  std::map<mesh::Zone, fdem::Material> materials = engine_materials(scene);
  // The implicit stage left the core at alpha_h E; the engine continues from there.
  if (materials.count(mesh::kCore) && handoff.alpha > 0)
    materials[mesh::kCore].young *= handoff.alpha;
  fdem::ModelInput in = coupling::model_input(
      m, materials, scene.plane_stress ? fdem::Plane::kStress : fdem::Plane::kStrain);
  coupling::apply_insitu(handoff, in);
  in.boundary_conditions = box_conditions(scene.insitu);
  in.dt = scene.engine.dt;  // checked by make_engine
  in.dt_safety = scene.engine.dt_safety;
  in.threads = threads;
  in.mass_scaling = {scene.engine.mass_scaling, scene.engine.mass_scaling_dt};
  in.contact = contact_settings(scene);
  return in;
}

int run_tunnel(const Scene& scene, const RunContext& ctx) {
  if (scene.insitu.unit_weight > 0)
    throw InputError(scene.source + ": key 'insitu.unit_weight' = " +
                     detail::number_text(scene.insitu.unit_weight) +
                     ": `rockfdem run` of a tunnel needs a uniform in-situ stress (0); the "
                     "gradient is supported by `rockfdem insitu`");
  PhaseTimer timer;
  // A bad checkpoint is refused before anything is written.
  const bool restart = !ctx.restart.empty();
  const Checkpoint resume = restart ? read_checkpoint(ctx.restart, scene) : Checkpoint{};
  RunRecord summary(scene, ctx.threads);
  RunOutputs out(scene, ctx, summary);

  // Nothing is written until the engine has accepted the scene (engine.dt
  // included): a refused run leaves OUTDIR as it found it.
  mesh::MeshReport report;
  const mesh::Mesh m = keeping_threads(ctx, [&] { return mesh::build_mesh(scene.mesh, &report); });
  summary.record_mesh(m, report);
  timer.stamp("mesh");
  stop_if_interrupted(scene, summary, ctx, timer, "meshing");

  const std::vector<insitu::InsituField> fields =
      keeping_threads(ctx, [&] { return insitu::solve_insitu(m, insitu_spec(scene)); });
  check_implicit_field(scene, m, fields);
  timer.stamp("insitu");
  stop_if_interrupted(scene, summary, ctx, timer, "the implicit stage");

  if (scene.stages.empty()) {
    // [[stages]] holds only "insitu": the scene asks for the elastic
    // implicit results alone.
    write_first_outputs(scene, ctx, restart, m, fields, out);
    timer.stamp("output");
    summary.skipped.push_back("fdem: the scene's only stage is the implicit in-situ stage");
    summary.status = "completed";
    summary.set_timings(timer);
    summary.write(output_path(ctx.output_dir, "summary.json"));
    return 0;
  }
  const insitu::InsituField& handoff = fields.back();
  fdem::ModelInput in = engine_input(scene, m, handoff, ctx.threads);
  SupportMaterials support;
  support.grout = int(in.materials.size());
  in.materials.push_back(grout_material(scene));
  if (scene.materials.count(mesh::kLining)) {
    support.lining_interface = int(in.materials.size());
    in.materials.push_back(lining_interface_material(scene));
  }
  fdem::BoltPlan bolts;  // marks bolt triangles and allows fracture there
  if (!scene.bolts.segments.empty()) bolts = planned_bolts(scene, in);
  fdem::Engine engine = make_engine(in, scene, ctx.force_dt);
  if (scene.engine.dt > 0 && !ctx.force_dt) {
    // The stages' local damping lowers the limit by sqrt(1 + alpha): an
    // explicit dt must hold then too, and is refused before anything is written.
    engine.set_damping(stage_damping(scene));
    refuse_dt_above(scene, scene.engine.dt, engine.critical_dt(),
                    "this mesh and its penalties with the stages' damping");
    engine.set_damping(in.damping);
  }
  // Key points and instruments before anything is written: a point in
  // no triangle or in the core is refused first.
  const std::vector<Monitor> monitors = tunnel_monitors(scene.mesh, m, engine);
  out.set_instruments(std::make_unique<Instruments>(scene, m, engine, monitors, bolts));
  out.set_bolts(&bolts);
  double start_ratio = 0;
  if (restart)
    start_ratio = restore_before_writing(resume, ctx.restart, monitors, out, engine, bolts);
  timer.stamp("fdem setup");
  write_first_outputs(scene, ctx, restart, m, fields, out);
  timer.stamp("output");
  if (!restart) {
    for (std::size_t t = 0; t < m.n_triangles(); ++t)
      if (!handoff.active[t]) engine.set_active(t, false);
    out.keep_start(engine);
    reporting_failure(scene, out, engine, timer, [&] { engine.step(); });
    start_ratio = engine.unbalanced_force_ratio();
    engine.set_damping(stage_damping(scene));
  }
  timer.stamp("fdem setup");

  out.begin_history(monitors, m);
  StageRunner stages(engine, m, handoff, scene, ctx, out, monitors, bolts, support);
  if (restart) {
    try {
      out.restore(resume.run.at("outputs"), run_dir_of(ctx.restart));
      stages.restore(resume.run.at("stages"));
    } catch (const InputError& e) {
      throw InputError(ctx.restart + ": " + e.what());
    }
    summary.restarted_from = CheckpointMark{ctx.restart, engine.step_count()};
  } else {
    reporting_failure(scene, out, engine, timer, [&] {
      out.record_step(engine, m, monitors, timer, "handoff", handoff.alpha);
    });
  }
  stages.set_checkpoint(
      ctx.checkpoint_every >= 0 ? ctx.checkpoint_every : scene.output.checkpoint_every, [&] {
        Checkpoint c;
        c.run = {{"stages", stages.state()},
                 {"outputs", out.state()},
                 {"bolts", bolt_state(bolts)},
                 {"start_ratio", start_ratio}};
        std::ostringstream bytes;
        engine.save_state(bytes);
        c.engine_state = bytes.str();
        const std::string path = write_checkpoint(ctx.output_dir, engine.step_count(), scene, c);
        summary.checkpoint = CheckpointMark{path, engine.step_count()};
      });
  try {
    stages.run_all(timer);
  } catch (const Interrupted&) {
    summary.status = "interrupted";
    summary.figures()["fdem"] = {{"stages", stages.report()}};
    out.finish(engine, m, monitors, timer, bolts);
    throw;
  } catch (const NumericalError& e) {
    // The frames and history rows written so far are the last good output.
    summary.figures()["fdem"] = {{"stages", stages.report()}};
    const std::string why = with_likely_cause(scene, e.what());
    out.report_failure(engine, timer, why);
    throw NumericalError(why);
  } catch (const InputError& e) {
    // An explicit dt above the limit a later stage brings (lining, bolts,
    // grout stiffen the model): found only there, after outputs exist.
    const bool dt = scene.engine.dt > 0 && engine.critical_dt() < scene.engine.dt;
    const std::string why =
        dt ? scene.source + ": key 'engine.dt' = " + detail::number_text(scene.engine.dt) +
                 " s: " + e.what() + " (engine.dt = 0 follows the limit through every stage)"
           : scene.source + ": " + e.what();
    summary.figures()["fdem"] = {{"stages", stages.report()}};
    out.report_failure(engine, timer, why);
    throw InputError(why);
  }

  if (!stages.core_present()) {
    // The continuum reference of the relaxed state: the open excavation.
    insitu::InsituSpec open = insitu_spec(scene);
    open.alphas = {0.0};
    open.lining.active = false;
    if (!has_lining_ring(scene)) {
      const insitu::InsituField reference =
          keeping_threads(ctx, [&] { return insitu::solve_insitu(m, open).back(); });
      summary.figures()["comparison"] = compare_with_continuum(
          scene, m, engine, reference, output_path(ctx.output_dir, "fdem_vs_continuum.csv"));
    }
    compare_with_continuum_counterpart(scene, ctx, m, engine, handoff, monitors, summary);
    timer.stamp("insitu");
  }
  const RunVerdict verdict = stages.verdict();
  summary.status = verdict.status;
  if (!verdict.message.empty()) {
    summary.status_reason = verdict.message;
    summary.warnings.push_back(verdict.status + ": " + verdict.message);
    std::cerr << "warning: " << verdict.status << ": " << verdict.message << '\n';
  }
  summary.figures()["damping"] = {{"local", stage_damping(scene).local},
                                  {"mass_proportional", scene.engine.mass_damping},
                                  {"kinetic", scene.engine.kinetic_damping},
                                  {"local_given", scene.engine.local_damping >= 0}};
  summary.figures()["fdem"] = {{"unbalanced_ratio_at_start", start_ratio},
                               {"unbalanced_ratio_at_end", engine.unbalanced_force_ratio()},
                               {"handoff_alpha", handoff.alpha},
                               {"stages", stages.report()}};
  out.finish(engine, m, monitors, timer, bolts);
  if (!ctx.quiet)
    std::cout << "status: " << verdict.status
              << (verdict.message.empty() ? " (every stage met its criteria)"
                                          : " (" + verdict.message + ")")
              << '\n';
  return 0;
}

}  // namespace rockfdem::workflows
