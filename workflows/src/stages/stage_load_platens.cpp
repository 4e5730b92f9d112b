// load_platens: a specimen (UCS, Brazilian disc) loaded between its
// platens, which move towards each other at loading.platen_velocity from
// the first step (their prescribed velocities are the engine's boundary
// conditions: specimen_platens). The platen's reaction is read after every
// step (PlatenLoad::after_step), so the peak and the post-peak stop do not
// depend on the output interval; the stage ends at that stop or after its
// max_steps (engine.steps). A specimen's implicit stage list is this one
// stage.
#include "scene/schema_keys.hpp"
#include "stages/platen_load.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class LoadPlatens : public Stage {
 public:
  const char* description() const override {
    return "specimens: platens load the specimen to engine.steps or the post-peak stop";
  }

  void check(StageCheck& c) const override {
    c.refuse(".kind", "loads a UCS or Brazilian specimen (model.kind), not a tunnel");
  }

  std::vector<KeySpec> keys() const override {
    using namespace schema;
    return {positive("loading.platen_velocity", "m/s", "0.5",
                     "UCS and Brazilian tests: speed of each platen towards the other. At "
                     "most a tenth of the rock's P-wave speed (from its young, poisson and "
                     "density; `rockfdem check` prints it): faster, the platens strike the "
                     "specimen instead of loading it."),
            choice("loading.platen_friction", "rough", {"rough", "frictionless"},
                   "UCS and Brazilian tests: rough platens hold the loaded ends laterally "
                   "(both velocity components prescribed); frictionless ones prescribe only "
                   "the loading-direction velocity (rollers), so the ends spread freely."),
            number("loading.stop_after_peak", "-", "0", 0, false, 1, true,
                   "UCS and Brazilian tests: the run ends at the first step whose platen "
                   "stress has fallen to this fraction of the peak so far, once a crack "
                   "element has broken (post-peak stop); 0: runs all engine.steps.")};
  }

  // Ends on its own criterion, the post-peak stop or the step count: a
  // specimen has no equilibrium to reach.
  bool step(StageDriver& runner, const StageSpec& spec, StageChanges&) const override {
    PlatenLoad& load = *runner.model().platens;
    const fdem::Engine& e = runner.model().engine;
    runner.step_until(spec, [&] { return load.after_step(e); });
    return true;
  }
};

}  // namespace

std::unique_ptr<const Stage> make_load_platens_stage() { return std::make_unique<LoadPlatens>(); }

}  // namespace rockfdem::workflows
