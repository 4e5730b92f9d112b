// The explicit construction stages of a tunnel run, in the scene's order.
// Each stage changes the model (soften the core, install the lining, remove
// the core) and then steps to its own stop criterion (unbalanced-force
// ratio, step cap, simulated time), writing history rows and frames.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "monitors.hpp"
#include "phase_timer.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run_outputs.hpp"

namespace rockfdem::workflows {

class StageRunner {
 public:
  StageRunner(fdem::Engine& engine, const mesh::Mesh& m, const insitu::InsituField& handoff,
              const Scene& scene, const CommandLine& cli, RunOutputs& out,
              const std::vector<Monitor>& monitors, fdem::BoltPlan& bolts, int grout_material);
  void run(const StageSpec& stage, PhaseTimer& timer);
  /// One entry per stage run: kind, steps, simulated time, final ratio, converged.
  const nlohmann::json& report() const { return report_; }
  bool core_present() const { return core_present_; }

 private:
  nlohmann::json apply(const StageSpec& stage);
  /// grout: steps until `trigger` crack elements are broken (within the
  /// stage's step cap), then re-joins the broken ones with grout.
  nlohmann::json grout(const StageSpec& stage, PhaseTimer& timer);
  /// Steps in output chunks until the stage's criterion; returns converged.
  bool step_until(const StageSpec& stage, long first, double t0, PhaseTimer& timer,
                  long broken_target);
  void set_zone(int zone, bool active, fdem::ActivationReference ref);
  /// Core stiffness factor relative to the full rock (0 once removed).
  double support_ratio() const { return core_present_ ? alpha_ : 0.0; }

  fdem::Engine& engine_;
  const mesh::Mesh& mesh_;
  const Scene& scene_;
  const CommandLine& cli_;
  RunOutputs& out_;
  const std::vector<Monitor>& monitors_;
  fdem::BoltPlan& bolts_;
  int grout_material_;
  double handoff_alpha_;
  double alpha_;
  bool core_present_;
  bool lining_installed_;
  nlohmann::json report_ = nlohmann::json::array();
};

}  // namespace rockfdem::workflows
