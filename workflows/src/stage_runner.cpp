#include "stage_runner.hpp"

#include <algorithm>

#include "output_dir.hpp"
#include "progress.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/fdem/bolt_grouting.hpp"

namespace rockfdem::workflows {

StageRunner::StageRunner(fdem::Engine& engine, const mesh::Mesh& m,
                         const insitu::InsituField& handoff, const Scene& scene,
                         const CommandLine& cli, RunOutputs& out,
                         const std::vector<Monitor>& monitors, fdem::BoltPlan& bolts,
                         int grout_material)
    : engine_(engine), mesh_(m), scene_(scene), cli_(cli), out_(out), monitors_(monitors),
      bolts_(bolts), grout_material_(grout_material),
      handoff_alpha_(handoff.alpha), alpha_(handoff.alpha), core_present_(handoff.alpha > 0),
      lining_installed_(handoff.lining_installed) {}

void StageRunner::set_zone(int zone, bool active, fdem::ActivationReference ref) {
  for (std::size_t t = 0; t < mesh_.n_triangles(); ++t)
    if (mesh_.zone[t] == zone) engine_.set_active(t, active, ref);
}

nlohmann::json StageRunner::apply(const StageSpec& stage) {
  nlohmann::json done = nlohmann::json::object();
  if (stage.kind == "bolts") {
    const fdem::BoltInstallReport r = fdem::install_bolts(engine_, bolts_);
    done = {{"bolts", bolts_.specs.size()}, {"bolt_triangles", r.triangles},
            {"steel_cracks", r.steel_cracks}, {"grout_cracks", r.grout_cracks}};
  } else if (stage.kind == "soften") {
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
  return done;
}

bool StageRunner::step_until(const StageSpec& stage, long first, double t0, PhaseTimer& timer,
                             long broken_target) {
  Progress progress(stage.kind, stage.max_steps, cli_.quiet);
  bool done = false;
  while (engine_.step_count() - first < stage.max_steps && !done) {
    if (stage.time > 0 && engine_.time() - t0 >= stage.time) break;
    const long chunk = std::min<long>(stage.every_steps,
                                      stage.max_steps - (engine_.step_count() - first));
    timer.stamp("output");
    engine_.run(chunk);
    timer.stamp("fdem");
    out_.record_step(engine_, mesh_, monitors_, timer, stage.kind, support_ratio());
    done = broken_target > 0 ? engine_.broken_counts().total() >= broken_target
                             : engine_.unbalanced_force_ratio() < stage.ratio;
    progress.update(engine_.step_count() - first, engine_.time() - t0);
  }
  progress.finish(engine_.step_count() - first, engine_.time() - t0);
  return done;
}

nlohmann::json StageRunner::grout(const StageSpec& stage, PhaseTimer& timer) {
  const long first = engine_.step_count();
  bool triggered = stage.trigger_broken == 0 ||
                   engine_.broken_counts().total() >= stage.trigger_broken;
  // Triggered by the broken count, or by the stage's time when one is given.
  if (!triggered) {
    const double t0 = engine_.time();
    triggered = step_until(stage, first, t0, timer, stage.trigger_broken) ||
                (stage.time > 0 && engine_.time() - t0 >= stage.time);
  }
  nlohmann::json done = {{"triggered", triggered},
                         {"broken_before", engine_.broken_counts().total()}};
  if (!triggered) return done;
  const fdem::CrackSelector select =
      bolts_.specs.empty() ? fdem::CrackSelector{} : fdem::excluding_bolt_steel(engine_, bolts_, {});
  const fdem::GroutingResult g = fdem::grout_broken_cracks(engine_, grout_material_, select);
  done["rejoined"] = g.count;
  done["broken_after"] = engine_.broken_counts().total();
  std::string csv = "crack,x,y\n";
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    csv += std::to_string(g.cracks[i]) + ',' + std::to_string(g.midpoints[i][0]) + ',' +
           std::to_string(g.midpoints[i][1]) + '\n';
  coupling::atomic_write_text(output_path(cli_.output_dir, "grouted_cracks.csv"), csv);
  done["positions_file"] = "grouted_cracks.csv";
  return done;
}

void StageRunner::run(const StageSpec& stage, PhaseTimer& timer) {
  const long first = engine_.step_count();
  const double t0 = engine_.time();
  nlohmann::json done;
  bool converged = false;
  if (stage.kind == "grout") {
    done = grout(stage, timer);
  } else {
    done = apply(stage);
    converged = step_until(stage, first, t0, timer, 0);
  }
  report_.push_back({{"kind", stage.kind},
                     {"changes", done},
                     {"steps", engine_.step_count() - first},
                     {"simulated_time", engine_.time() - t0},
                     {"unbalanced_ratio", engine_.unbalanced_force_ratio()},
                     {"converged", converged},
                     {"support_pressure_ratio", support_ratio()}});
}

}  // namespace rockfdem::workflows
