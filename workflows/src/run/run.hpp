// `rockfdem run` of a tunnel as one object: the constructor takes the
// validated scene and the command line's context, run() goes through the
// phases in order (run.cpp says what each does and why in that order).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "outputs/monitors.hpp"
#include "outputs/run_outputs.hpp"
#include "record/run_context.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/continuum_solve.hpp"
#include "run/field_sampler.hpp"
#include "run/stage_runner.hpp"
#include "run/staged_run.hpp"

namespace rockfdem::workflows {

class Run : StagedRun<RunOutputs> {
 public:
  Run(const Scene& scene, const RunContext& ctx);
  /// Runs the phases; returns the exit code. Throws InputError (nothing
  /// written when the scene or checkpoint is refused before the engine
  /// accepts it), NumericalError or Interrupted (both after the summary).
  int run();

 private:
  /// The implicit solve of `spec` on the run's threads, each field's code
  /// pages given back once it is out (returning_code_pages).
  std::vector<insitu::InsituField> solve_fields(const insitu::InsituSpec& spec);
  // The phases, in the order run() calls them.
  void solve_insitu();
  std::optional<ContinuumStates> solve_with_counterpart(FieldSampler& sampler,
                                                        FieldSampler::Hold hold);
  void install_at_face_distance(FieldSampler& sampler);
  void choose_handoff_field();
  int write_implicit_results_only();
  void solve_references();
  void build_engine();
  void place_instruments();
  void write_first_outputs();
  void take_handoff_step();
  void begin_stages();
  void run_stages();
  void compare_with_references();
  void finish();
  void finish_outputs();

  // What the phases share.
  const insitu::InsituField& handoff() const { return fields_.back(); }
  Scene solved_sequence() const;
  void stop_if_interrupted(const char* after);
  /// The bolts and the hand-off's ratio, beyond the stages' and outputs'.
  void add_run_state(nlohmann::json& run) const override;
  /// With the likely cause when the in-situ stress is large against the
  /// rock's modulus.
  std::string failure_message(const std::string& what) const override;
  /// The message of an InputError from a stage, with engine.dt named when
  /// a later stage's stability limit is below it.
  std::string stage_input_error(const InputError& e);

  /// Up to the one handed over, which alone keeps its arrays.
  std::vector<insitu::InsituField> fields_;
  std::vector<ImplicitSample> samples_;         ///< fields_'s samples
  HandoffFigures handoff_figures_;              ///< the hand-off rule over all solved fields
  std::optional<ContinuumStates> counterpart_;  ///< solved with the implicit stage's fields
  ContinuumReferences references_;              ///< what the end state is compared with
  SupportMaterials support_;
  fdem::DampingSettings stage_damping_;  ///< the stages' (after the hand-off step)
  fdem::BoltPlan bolts_;                 ///< marks bolt triangles and allows fracture there
  KeyPoints key_points_;                 ///< the tunnel's key points and the scene's monitors
  double start_ratio_ = 0;               ///< the hand-off step's unbalanced-force ratio
  /// The stage loop, declared last so that it is destroyed first: it refers
  /// to the key points, hand-off field and bolts above (and to the base's
  /// engine, mesh and outputs, which outlive every member here).
  std::optional<StageRunner> stages_;
};

/// `rockfdem run` of a tunnel: Run(scene, ctx).run().
int run_tunnel(const Scene& scene, const RunContext& ctx);
/// `rockfdem run` of a UCS or Brazilian specimen (run_specimen.cpp): the
/// same stage loop, its one stage load_platens.
int run_specimen(const Scene& scene, const RunContext& ctx);

}  // namespace rockfdem::workflows
