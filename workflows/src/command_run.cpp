// `rockfdem run [SCENE] -o DIR`: the whole pipeline. Specimens (UCS,
// Brazilian disc): mesh, then the explicit engine loading the specimen
// between platens for engine.steps steps, with the stress-strain (or
// load-displacement) history, ParaView frames and a summary.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "engine_report.hpp"
#include "history.hpp"
#include "interrupt.hpp"
#include "last_good.hpp"
#include "output_dir.hpp"
#include "phase_timer.hpp"
#include "progress.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run_plots.hpp"
#include "stage_inputs.hpp"
#include "summary.hpp"

namespace rockfdem::workflows {
namespace {

// Platens: the loaded edges move towards each other at the platen speed and
// hold the specimen's ends laterally (rough platens).
std::vector<fdem::BoundaryCondition> platens(const Scene& s) {
  const bool disc = s.mesh.kind == mesh::ModelKind::kBrazilian;
  const double v = s.engine.platen_velocity;
  fdem::BoundaryCondition lower, upper;
  lower.tag = disc ? mesh::kLoadBottom : mesh::kBottom;
  upper.tag = disc ? mesh::kLoadTop : mesh::kTop;
  lower.x = upper.x = fdem::Constraint::kFixed;
  lower.y = upper.y = fdem::Constraint::kVelocity;
  lower.vy = v;
  upper.vy = -v;
  return {lower, upper};
}

/// Specimen length along the load, and the cross-section the load is spread over.
struct SpecimenSize {
  double length, section;
};

SpecimenSize specimen_size(const Scene& s) {
  if (s.mesh.kind == mesh::ModelKind::kBrazilian) return {s.mesh.specimen.diameter, 1.0};
  return {s.mesh.specimen.height, s.mesh.specimen.width};
}

void write_frame(const fdem::Engine& e, const mesh::Mesh& m, const std::string& dir, int frame,
                 coupling::PvdCollection& pvd) {
  char name[32];
  std::snprintf(name, sizeof name, "fdem_%04d.vtu", frame);
  coupling::VtkGrid g = coupling::fdem_grid(e, m);
  coupling::add_frame_info(g, "load_platens", e.step_count(), e.time());
  coupling::write_vtu(g, output_path(dir, name));
  pvd.add(e.time(), name);
  pvd.write();
}

int run_specimen(const Scene& scene, const CommandLine& cli) {
  PhaseTimer timer;
  const int threads = active_threads();
  RunSummary summary(scene, threads);
  summary.note_turned_off(scene.output, "fdem.pvd, fdem_NNNN.vtu", true);
  mesh::MeshReport report;
  const mesh::Mesh m = mesh::build_mesh(scene.mesh, &report);
  active_threads();
  summary.record_mesh(m, report);
  timer.stamp("mesh");

  fdem::ModelInput in = coupling::model_input(
      m, engine_materials(scene), scene.plane_stress ? fdem::Plane::kStress : fdem::Plane::kStrain);
  in.boundary_conditions = platens(scene);
  in.dt = scene.engine.dt;  // checked by make_engine
  in.dt_safety = scene.engine.dt_safety;
  in.damping.local = std::max(scene.engine.local_damping, 0.0);  // -1: not given, none
  in.damping.mass_proportional = scene.engine.mass_damping;
  in.gravity_y = -scene.engine.gravity;
  in.threads = threads;
  in.mass_scaling = {scene.engine.mass_scaling, scene.engine.mass_scaling_dt};
  in.contact = contact_settings(scene);
  fdem::Engine engine = make_engine(in, scene, cli.force_dt);
  timer.stamp("fdem setup");
  // Only now, with engine.dt accepted, is anything written.
  prepare_output_dir(cli.output_dir, scene, cli.force);
  mesh::write_msh(m, output_path(cli.output_dir, "mesh.msh"));
  timer.stamp("output");

  const bool disc = scene.mesh.kind == mesh::ModelKind::kBrazilian;
  const SpecimenSize size = specimen_size(scene);
  const int upper_tag = disc ? mesh::kLoadTop : mesh::kTop;
  std::vector<std::string> columns{
      "step",         "time",           "axial_strain", disc ? "tensile_stress" : "axial_stress",
      "platen_force", "kinetic_energy", "broken_I",     "broken_II",
      "broken_mixed"};
  for (const std::string& c : energy_columns()) columns.push_back(c);
  History history(output_path(cli.output_dir, "history.csv"), columns);
  coupling::PvdCollection pvd(output_path(cli.output_dir, "fdem.pvd"));
  Progress progress(disc ? "brazilian" : "ucs", scene.engine.steps, cli.quiet);
  double peak = 0;
  int frame = 0;
  LastGoodState last_good;
  const double floor = energy_floor(scene, m);
  const auto record = [&] {
    const double force = -engine.boundary_force(upper_tag)[1];  // compression positive
    // UCS: mean axial stress; disc: the Brazilian tensile stress 2P/(pi D t).
    const double stress = disc ? 2 * force / (M_PI * size.length) : force / size.section;
    const double strain = 2 * scene.engine.platen_velocity * engine.time() / size.length;
    const fdem::BrokenCounts b = engine.broken_counts();
    peak = std::max(peak, stress);
    std::vector<double> row{double(engine.step_count()),
                            engine.time(),
                            strain,
                            stress,
                            force,
                            engine.kinetic_energy(),
                            double(b.mode_I),
                            double(b.mode_II),
                            double(b.mixed)};
    const fdem::EnergyBalance energy = engine.energy_balance();
    for (double v : energy_row(energy)) row.push_back(v);
    history.add(row);
    check_energy(energy, engine.step_count(), floor);  // before the frame: keep the last good one
    if (scene.output.vtk) write_frame(engine, m, cli.output_dir, frame++, pvd);
    last_good.take(engine, energy);
  };
  auto& j = summary.json();
  const auto stop = [&](const char* status, const std::string& why) {
    j["status"] = status;
    j["failure"] = why;
    summary.set_timings(timer);
    summary.write(output_path(cli.output_dir, "summary.json"));
  };
  record();
  while (engine.step_count() < scene.engine.steps) {
    const long chunk =
        std::min<long>(scene.output.every_steps, scene.engine.steps - engine.step_count());
    timer.stamp("output");
    try {
      for (long i = 0; i < chunk && !interrupt_requested(); ++i) engine.step();
      timer.stamp("fdem");
      record();
    } catch (const NumericalError& e) {
      last_good.report_failure(engine, timer, e.what(), summary);
      stop("failed", e.what());  // history and frames so far are the last good output
      throw;
    }
    progress.update(engine.step_count(), engine.time());
    if (const int sig = interrupt_requested()) {
      const std::string why = "interrupted by signal " + std::to_string(sig) + " at step " +
                              std::to_string(engine.step_count());
      report_engine(engine, timer, summary);
      stop("interrupted", why);
      throw Interrupted(sig, why + "; outputs are written (specimen runs keep no checkpoint)");
    }
  }
  if (scene.output.plots) specimen_plots(engine, history, disc, cli.output_dir, summary, cli.quiet);
  timer.stamp("output");
  progress.finish(engine.step_count(), engine.time());
  j["status"] = "completed";
  report_engine(engine, timer, summary);
  warn_if_unbalanced(engine, floor, cli.quiet, summary);
  j["specimen"] = {{"peak_stress", peak},
                   {"strain_rate", 2 * scene.engine.platen_velocity / size.length},
                   {"kind", disc ? "brazilian" : "ucs"}};
  summary.skipped("insitu: a specimen starts stress-free");
  summary.set_timings(timer);
  summary.write(output_path(cli.output_dir, "summary.json"));
  if (!cli.quiet)
    std::cout << (disc ? "peak tensile stress " : "peak axial stress ") << peak / 1e6
              << " MPa, broken " << engine.broken_counts().total() << " of " << engine.n_cracks()
              << " crack elements, state hash " << engine.state_hash() << '\n'
              << timer.table();
  return 0;
}

}  // namespace

int command_run(const Scene& scene, const CommandLine& cli) {
  install_interrupt_handlers();
  if (scene.mesh.kind == mesh::ModelKind::kUcs || scene.mesh.kind == mesh::ModelKind::kBrazilian) {
    if (!cli.restart.empty() || cli.checkpoint_every > 0 || scene.output.checkpoint_every > 0)
      throw InputError(scene.source +
                       ": checkpoints (--restart, --checkpoint-every, "
                       "output.checkpoint_every) apply to tunnel runs; a specimen run is "
                       "re-run from the start");
    return run_specimen(scene, cli);
  }
  return run_tunnel(scene, cli);
}

}  // namespace rockfdem::workflows
