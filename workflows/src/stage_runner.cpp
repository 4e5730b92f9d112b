#include "stage_runner.hpp"

#include <algorithm>

#include "progress.hpp"

namespace rockfdem::workflows {

StageRunner::StageRunner(fdem::Engine& engine, const mesh::Mesh& m,
                         const insitu::InsituField& handoff, const Scene& scene,
                         const CommandLine& cli, RunOutputs& out,
                         const std::vector<Monitor>& monitors)
    : engine_(engine), mesh_(m), scene_(scene), cli_(cli), out_(out), monitors_(monitors),
      handoff_alpha_(handoff.alpha), alpha_(handoff.alpha), core_present_(handoff.alpha > 0),
      lining_installed_(handoff.lining_installed) {}

void StageRunner::set_zone(int zone, bool active, fdem::ActivationReference ref) {
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t)
    if (mesh_.zone[t] == zone) engine_.set_active(t, active, ref);
}

void StageRunner::apply(const StageSpec& stage) {
  if (stage.kind == "soften") {
    // The engine's core already has alpha_h E and stress: scale relative to it.
    for (std::size_t t = 0; t < mesh_.n_triangles(); ++t)
      if (mesh_.zone[t] == mesh::kCore ||
          (!lining_installed_ && mesh_.zone[t] == mesh::kLining))
        engine_.set_stiffness_factor(t, stage.alpha / handoff_alpha_);
    alpha_ = stage.alpha;
  } else if (stage.kind == "lining") {
    // Stress-free in the deformed shape: the lining takes only later load.
    set_zone(mesh::kLining, true, fdem::ActivationReference::kCurrent);
    for (std::size_t t = 0; t < mesh_.n_triangles(); ++t)
      if (mesh_.zone[t] == mesh::kLining) engine_.set_stiffness_factor(t, 1.0);
    lining_installed_ = true;
  } else if (stage.kind == "remove_core") {
    set_zone(mesh::kCore, false, fdem::ActivationReference::kKeep);
    // A ring never installed is ground still to be excavated.
    if (!lining_installed_) set_zone(mesh::kLining, false, fdem::ActivationReference::kKeep);
    core_present_ = false;
  }
}

void StageRunner::run(const StageSpec& stage, PhaseTimer& timer) {
  apply(stage);
  const long first = engine_.step_count();
  const double t0 = engine_.time();
  Progress progress(stage.kind, stage.max_steps, cli_.quiet);
  bool converged = false;
  while (engine_.step_count() - first < stage.max_steps && !converged) {
    if (stage.time > 0 && engine_.time() - t0 >= stage.time) break;
    const long chunk = std::min<long>(stage.every_steps,
                                      stage.max_steps - (engine_.step_count() - first));
    timer.stamp("output");
    engine_.run(chunk);
    timer.stamp("fdem");
    out_.record_step(engine_, mesh_, monitors_, timer, stage.kind, support_ratio());
    converged = engine_.unbalanced_force_ratio() < stage.ratio;
    progress.update(engine_.step_count() - first, engine_.time() - t0);
  }
  progress.finish(engine_.step_count() - first, engine_.time() - t0);
  report_.push_back({{"kind", stage.kind},
                     {"steps", engine_.step_count() - first},
                     {"simulated_time", engine_.time() - t0},
                     {"unbalanced_ratio", engine_.unbalanced_force_ratio()},
                     {"converged", converged},
                     {"support_pressure_ratio", support_ratio()}});
}

}  // namespace rockfdem::workflows
