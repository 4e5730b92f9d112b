// One explicit stage of a run, as a registered piece: each kind (the
// scene's stages[].kind; a specimen's implicit load_platens) lives in
// stage_<kind>.cpp with its scene keys (keys), its change to the model
// (apply) and its stop criterion (step), and is listed once in
// registry.cpp. The run's stage loop (run/stage_runner.hpp) keeps the
// cursor, the outputs and the checkpoints; it drives a stage through the
// StageDriver below, so a stage only says what it changes in the model and
// when it stops, and knows nothing of the run above it.
#pragma once

#include <cassert>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "record/run_context.hpp"
#include "record/run_figures.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "scene/stage_kind.hpp"

namespace rockfdem::workflows {

class PlatenLoad;
struct StageModel;

/// What a stage may ask of the stage loop that runs it: the model, stepping
/// to a criterion, and where the stage and the run stand.
class StageDriver {
 public:
  /// A stop test run after every step: true stops the stage there.
  using StopTest = std::function<bool()>;
  virtual StageModel& model() = 0;
  /// Steps in output chunks until the stage's criterion; returns converged.
  /// With a `stop` test, until it holds (checked after every step, so the
  /// trigger does not depend on the output interval or the mesh).
  virtual bool step_until(const StageSpec& stage, const StopTest& stop) = 0;
  /// Whether an unstable opening ended the stages.
  virtual bool stopped() const = 0;
  /// Simulated time since the stage began [s].
  virtual double stage_time() const = 0;
  /// Explicit steps since the stage began.
  virtual long stage_steps() const = 0;
  /// One entry per stage run so far.
  virtual const std::vector<StageRecord>& report() const = 0;

 protected:
  ~StageDriver() = default;
};

/// Engine materials the support stages assign to crack elements.
struct SupportMaterials {
  int grout = -1;             ///< re-joins broken cracks (grout stage)
  int lining_interface = -1;  ///< lining-rock crack elements at installation
};

/// What the stages change: the engine, and the construction state a
/// checkpoint keeps (core stiffness, core and lining present).
struct StageModel {
  fdem::Engine& engine;
  const mesh::Mesh& mesh;
  const RunContext& ctx;
  const Scene& scene;
  fdem::BoltPlan& bolts;
  SupportMaterials materials;
  double handoff_alpha;   ///< the core's stiffness factor in the engine at the hand-off
  double alpha;           ///< the core's stiffness factor now
  bool core_present;      ///< the core is not removed yet
  bool lining_installed;  ///< the lining ring carries load as lining
  /// A specimen's platens, read after every step by load_platens; null for tunnels.
  PlatenLoad* platens = nullptr;

  /// (De)activates every triangle of `zone`.
  void set_zone(int zone, bool active, fdem::ActivationReference ref);
  /// Core stiffness factor relative to the full rock (0 once removed).
  double support_ratio() const { return core_present ? alpha : 0.0; }
};

/// A stage kind as the run drives it: what the scene reads and checks of it
/// (StageKind), its change to the model and its stop criterion.
class Stage : public StageKind {
 public:
  /// The stage's change to the model at its start; returns what changed
  /// (the summary's "changes" of the stage): nothing by default.
  virtual StageChanges apply(StageModel& model, const StageSpec& spec) const;
  /// Steps to the stage's stop criterion through `driver`; returns whether
  /// the stage converged. A stage whose changes come after its steps sets
  /// them in `changes` (apply's, copied). Default: the equilibrium
  /// criterion (ratio, settle and hold).
  virtual bool step(StageDriver& driver, const StageSpec& spec, StageChanges& changes) const;
  /// Why a run whose last stage that stepped is this one is not at
  /// equilibrium, when that is not the generic finding (a stage that stops
  /// on something else); empty: the generic one.
  virtual std::string not_at_equilibrium() const { return {}; }
  /// What the stage reached, in words (report.md's stage table):
  /// converged, stopped before its criteria, or for a stage that took no
  /// step what it did (installed, core removed; by default applied).
  virtual std::string outcome(const StageRecord& record) const;
};

/// A stage kind with entry keys of its own, read into `Values` (a struct of
/// its stage file's, derived from StageValues): read_values fills them and
/// values(spec) gives them back. The type is settled where the scene is
/// read: each entry's `own` is its own kind's read (read_stage in
/// scene_build.cpp), and a kind is only ever handed entries of its kind
/// (the registry finds it by StageSpec::kind), so no later use tests it.
template <class Values>
class StageWithValues : public Stage {
  static_assert(std::is_base_of_v<StageValues, Values>, "a kind's values are StageValues");

 public:
  std::shared_ptr<const StageValues> read(const StageEntry& e) const final {
    return std::make_shared<const Values>(read_values(e));
  }

 protected:
  /// The entry's own keys (entry_keys) as the kind's values.
  virtual Values read_values(const StageEntry& e) const = 0;
  /// The values read_values made of `spec`, an entry of this kind.
  static const Values& values(const StageSpec& spec) {
    assert(spec.own);
    return static_cast<const Values&>(*spec.own);
  }
};

}  // namespace rockfdem::workflows
