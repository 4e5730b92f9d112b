// `rockfdem run` of a tunnel as one object: the constructor takes the
// validated scene and the command line's context, run() goes through the
// phases in order (run.cpp says what each does and why in that order).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "outputs/monitors.hpp"
#include "outputs/run_outputs.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/checkpoint.hpp"
#include "run/phase_timer.hpp"
#include "run/run_context.hpp"
#include "run/stage_runner.hpp"
#include "run/summary.hpp"

namespace rockfdem::workflows {

class Run {
 public:
  Run(const Scene& scene, const RunContext& ctx);
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;
  /// Runs the phases; returns the exit code. Throws InputError (nothing
  /// written when the scene or checkpoint is refused before the engine
  /// accepts it), NumericalError or Interrupted (both after the summary).
  int run();

 private:
  // The phases, in the order run() calls them.
  void refuse_unsupported() const;
  void read_restart();
  void make_mesh();
  void solve_insitu();
  int write_implicit_results_only();
  void build_engine();
  void place_instruments();
  void write_first_outputs();
  void take_handoff_step();
  void begin_stages();
  void run_stages();
  void compare_with_references();
  void finish();

  // What the phases share.
  const insitu::InsituField& handoff() const { return fields_.back(); }
  fdem::Engine& engine() { return *engine_; }
  void stop_if_interrupted(const char* after);
  void save_checkpoint();
  /// The message of an InputError from a stage, with engine.dt named when
  /// a later stage's stability limit is below it.
  std::string stage_input_error(const InputError& e);
  /// Runs `f`; a NumericalError in it (the hand-off step or a stage) writes
  /// the failure summary first, with the likely cause when the in-situ
  /// stress is large against the rock's modulus.
  template <class F>
  void reporting_failure(F&& f);

  const Scene& scene_;
  const RunContext& ctx_;
  PhaseTimer timer_;
  const bool restart_;
  Checkpoint resume_;
  RunRecord summary_;
  RunOutputs out_;
  mesh::Mesh mesh_;
  std::vector<insitu::InsituField> fields_;
  SupportMaterials support_;
  fdem::DampingSettings stage_damping_;  ///< the stages' (after the hand-off step)
  fdem::BoltPlan bolts_;                 ///< marks bolt triangles and allows fracture there
  std::optional<fdem::Engine> engine_;
  std::vector<Monitor> monitors_;
  double start_ratio_ = 0;  ///< the hand-off step's unbalanced-force ratio
  std::unique_ptr<StageRunner> stages_;
};

/// `rockfdem run` of a tunnel: Run(scene, ctx).run().
int run_tunnel(const Scene& scene, const RunContext& ctx);
/// `rockfdem run` of a UCS or Brazilian specimen (run_specimen.cpp): the
/// same stage loop, its one stage load_platens.
int run_specimen(const Scene& scene, const RunContext& ctx);

}  // namespace rockfdem::workflows
