// One explicit stage of a run, as a registered piece: each kind (the
// scene's stages[].kind; a specimen's implicit load_platens) lives in
// stage_<kind>.cpp with its scene keys (keys), its change to the model
// (apply) and its stop criterion (step), and is listed once in
// registry.cpp. StageRunner keeps the cursor, the outputs and the
// checkpoints and tells the outputs; a stage only says what it changes in
// the model and when it stops.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "run/run_context.hpp"
#include "run/run_figures.hpp"

namespace rockfdem::workflows {

class StageRunner;
class PlatenLoad;

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

/// What the stages before an entry of [[stages]] allow, as the scene
/// reader walks the list in order.
struct StageOrder {
  double alpha = 0;     ///< the core's stiffness factor (0: removed)
  bool lined = false;   ///< a lining stage came before
  bool bolted = false;  ///< a bolts stage came before
};

/// One [[stages]] entry being read: the scene read so far, the entry and
/// the order before it. Keys are the entry's own (".alpha", ".kind").
class StageCheck {
 public:
  StageCheck(const Scene& s, const StageSpec& e, StageOrder& o) : scene(s), spec(e), order(o) {}
  virtual ~StageCheck() = default;
  /// Throws the scene's InputError naming the entry's `key` and `why`.
  [[noreturn]] virtual void refuse(const std::string& key, const std::string& why) const = 0;
  /// Refuses the entry when the file does not give `key`.
  virtual void require(const std::string& key, const std::string& why) const = 0;

  const Scene& scene;
  const StageSpec& spec;
  StageOrder& order;
};

class Stage {
 public:
  virtual ~Stage() = default;
  /// What the stage does, in a few words for the scene reference ("" for
  /// a kind its name says all of).
  virtual const char* description() const { return ""; }
  /// The scene keys the stage reads beyond stages[] (scene_schema() lists
  /// them where the reference has them); none by default.
  virtual std::vector<KeySpec> keys() const { return {}; }
  /// Refuses an entry the stages before it (or the scene) do not allow,
  /// and notes in check.order what it changes; allows any by default.
  virtual void check(StageCheck&) const {}
  /// The stage's change to the model at its start; returns what changed
  /// (the summary's "changes" of the stage): nothing by default.
  virtual StageChanges apply(StageModel& model, const StageSpec& spec) const;
  /// Steps to the stage's stop criterion through `runner`; returns whether
  /// the stage converged. A stage whose changes come after its steps sets
  /// them in `changes` (apply's, copied). Default: the equilibrium
  /// criterion (ratio, settle and hold).
  virtual bool step(StageRunner& runner, const StageSpec& spec, StageChanges& changes) const;
  /// Why a run whose last stage that stepped is this one is not at
  /// equilibrium, when that is not the generic finding (a stage that stops
  /// on something else); empty: the generic one.
  virtual std::string not_at_equilibrium() const { return {}; }
  /// Whether the stage installs support: the instruments' and plots'
  /// origin of what the support measures.
  virtual bool installs_support() const { return false; }
  /// What the stage reached, in words (report.md's stage table):
  /// converged, stopped before its criteria, or for a stage that took no
  /// step what it did (installed, core removed; by default applied).
  virtual std::string outcome(const StageRecord& record) const;
};

}  // namespace rockfdem::workflows
