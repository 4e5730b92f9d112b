// grout: steps until trigger_broken crack elements are broken (or the
// stage's time has passed), then re-joins the broken ones with grout and
// lists where (grouted_cracks.csv). It stops on its trigger, so a run
// ending on it is not at equilibrium.
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/fdem/bolt_grouting.hpp"
#include "run/output_dir.hpp"
#include "run/stage_runner.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// Re-joins the broken crack elements (not a bolt's steel) with grout;
// adds the count and the positions file to `done`.
void grout_broken(StageModel& m, StageChanges& done) {
  const fdem::CrackSelector select = m.bolts.specs.empty()
                                         ? fdem::CrackSelector{}
                                         : fdem::excluding_bolt_steel(m.engine, m.bolts, {});
  const fdem::GroutingResult g = fdem::grout_broken_cracks(m.engine, m.materials.grout, select);
  done.rejoined = g.count;
  done.broken_after = m.engine.broken_counts().total();
  std::string csv = "crack,x,y\n";
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    csv += std::to_string(g.cracks[i]) + ',' + std::to_string(g.midpoints[i][0]) + ',' +
           std::to_string(g.midpoints[i][1]) + '\n';
  coupling::atomic_write_text(output_path(m.ctx.output_dir, "grouted_cracks.csv"), csv);
  done.positions_file = "grouted_cracks.csv";
}

class Grout : public Stage {
 public:
  const char* description() const override {
    return "re-join broken cracks with grout, once trigger_broken is reached";
  }

  bool step(StageRunner& runner, const StageSpec& spec, StageChanges& changes) const override {
    StageModel& m = runner.model();
    bool triggered =
        spec.trigger_broken == 0 || m.engine.broken_counts().total() >= spec.trigger_broken;
    // Triggered by the broken count, or by the stage's time when one is given.
    if (!triggered)
      triggered = runner.step_until(spec, [&] {
        return m.engine.broken_counts().total() >= spec.trigger_broken;
      }) || (!runner.stopped() && spec.time > 0 && runner.stage_time() >= spec.time);
    changes = {};
    changes.triggered = triggered;
    changes.broken_before = m.engine.broken_counts().total();
    if (triggered) grout_broken(m, changes);
    return false;
  }

  std::string outcome(const StageRecord& record) const override {
    const StageChanges& c = record.changes;
    if (!c.triggered.value_or(false)) return "not triggered";
    return "grouted " + (c.rejoined ? std::to_string(*c.rejoined) : std::string("-")) + " cracks";
  }

  std::string not_at_equilibrium() const override {
    return "stops on its trigger, not on equilibrium: add an equilibrium stage after it";
  }
};

}  // namespace

std::unique_ptr<const Stage> make_grout_stage() { return std::make_unique<Grout>(); }

}  // namespace rockfdem::workflows
