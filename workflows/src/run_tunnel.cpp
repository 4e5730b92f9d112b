// `rockfdem run` of a tunnel: the staged sequence of the seed paper.
//
//   1. mesh (gmsh)
//   2. in-situ and core softening, implicit (deal.II), one solve per alpha
//   3. hand-off: the last alpha's field becomes the engine's initial state
//      (the core keeps alpha_h E, so further factors are alpha / alpha_h)
//   4. lining installed stress-free in the deformed configuration
//   5. core removed
//   6. run to equilibrium with fracture in the fracture zone
//
// Outer boundary: rollers on the left and bottom sides, the in-situ
// traction sigma0 . n on the right and top sides, so the box is in
// equilibrium with the initial stress at step 0.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "history.hpp"
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
#include "stage_inputs.hpp"
#include "summary.hpp"

namespace rockfdem::workflows {
namespace {

// The in-situ stress tensor, tension positive: -sH along `angle`, -sV across.
std::array<double, 3> insitu_tensor(const InsituSettings& s) {
  const double a = s.angle_deg * M_PI / 180, c = std::cos(a), n = std::sin(a);
  return {-(s.sigma_h * c * c + s.sigma_v * n * n), -(s.sigma_h * n * n + s.sigma_v * c * c),
          -(s.sigma_h - s.sigma_v) * n * c};
}

std::vector<fdem::BoundaryCondition> box_conditions(const InsituSettings& s) {
  const auto sig = insitu_tensor(s);
  fdem::BoundaryCondition left, bottom, right, top;
  left.tag = mesh::kLeft;
  left.x = fdem::Constraint::kFixed;
  bottom.tag = mesh::kBottom;
  bottom.y = fdem::Constraint::kFixed;
  right.tag = mesh::kRight;  // n = (1, 0)
  right.tx = sig[0];
  right.ty = sig[2];
  top.tag = mesh::kTop;  // n = (0, 1)
  top.tx = sig[2];
  top.ty = sig[1];
  return {left, bottom, right, top};
}

fdem::ModelInput engine_input(const Scene& scene, const mesh::Mesh& m,
                              const insitu::InsituField& handoff) {
  std::map<int, fdem::Material> materials = engine_materials(scene);
  // The implicit stage left the core at alpha_h E; the engine continues from there.
  if (materials.count(mesh::kCore) && handoff.alpha > 0)
    materials[mesh::kCore].young *= handoff.alpha;
  fdem::ModelInput in = coupling::model_input(
      m, materials, scene.plane_stress ? fdem::Plane::kStress : fdem::Plane::kStrain);
  coupling::apply_insitu(handoff, in);
  in.boundary_conditions = box_conditions(scene.insitu);
  in.dt = scene.engine.dt;
  in.dt_safety = scene.engine.dt_safety;
  in.threads = active_threads();
  return in;
}

void set_zone_active(fdem::Engine& e, const mesh::Mesh& m, int zone, bool active,
                     fdem::ActivationReference ref) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == zone) e.set_active(t, active, ref);
}

}  // namespace

int run_tunnel(const Scene& scene, const CommandLine& cli) {
  if (scene.insitu.unit_weight > 0)
    throw InputError(scene.source + ": key 'insitu.unit_weight' = " +
                     std::to_string(scene.insitu.unit_weight) +
                     ": `rockfdem run` of a tunnel needs a uniform in-situ stress (0); the "
                     "gradient is supported by `rockfdem insitu`");
  PhaseTimer timer;
  prepare_output_dir(cli.output_dir, scene, cli.force);
  RunSummary summary(scene, active_threads());
  RunOutputs out(scene, cli, summary);

  mesh::MeshReport report;
  const mesh::Mesh m = mesh::build_mesh(scene.mesh, &report);
  active_threads();
  mesh::write_msh(m, output_path(cli.output_dir, "mesh.msh"));
  timer.stamp("mesh");

  const std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, insitu_spec(scene));
  active_threads();
  out.record_insitu(m, fields);
  timer.stamp("insitu");

  const insitu::InsituField& handoff = fields.back();
  fdem::Engine engine(engine_input(scene, m, handoff));
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (!handoff.active[t]) engine.set_active(t, false);
  engine.step();
  const double start_ratio = engine.unbalanced_force_ratio();
  timer.stamp("fdem setup");

  const std::vector<Monitor> monitors = tunnel_monitors(scene.mesh.tunnel, m, engine);
  if (!handoff.lining_installed && scene.materials.count("lining"))
    set_zone_active(engine, m, mesh::kLining, true, fdem::ActivationReference::kCurrent);
  set_zone_active(engine, m, mesh::kCore, false, fdem::ActivationReference::kKeep);
  engine.set_damping({scene.engine.local_damping > 0 ? scene.engine.local_damping : 0.8,
                      scene.engine.mass_damping});

  out.begin_history(monitors);
  Progress progress("equilibrium", scene.engine.steps, cli.quiet);
  out.record_step(engine, m, monitors, timer);
  bool converged = false;
  while (engine.step_count() < scene.engine.steps && !converged) {
    const long chunk =
        std::min<long>(scene.output.every_steps, scene.engine.steps - engine.step_count());
    timer.stamp("output");
    engine.run(chunk);
    timer.stamp("fdem");
    out.record_step(engine, m, monitors, timer);
    converged = engine.unbalanced_force_ratio() < 1e-3;
    progress.update(engine.step_count(), engine.time());
  }
  timer.stamp("output");
  progress.finish(engine.step_count(), engine.time());

  auto& j = summary.json();
  j["fdem"] = {{"unbalanced_ratio_at_start", start_ratio},
               {"unbalanced_ratio_at_end", engine.unbalanced_force_ratio()},
               {"equilibrium_reached", converged},
               {"handoff_alpha", handoff.alpha},
               {"stages", {"insitu (implicit)", "soften core (implicit)", "install lining",
                           "remove core", "run to equilibrium"}}};
  out.finish(engine, m, monitors, timer);
  return 0;
}

}  // namespace rockfdem::workflows
