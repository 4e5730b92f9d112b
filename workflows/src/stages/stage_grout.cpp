// grout: steps until its trigger fires (or the stage's time has passed),
// then re-joins the broken crack elements with grout and says which (the
// outputs list them in grouted_cracks.csv). One trigger per stage, N the broken count:
//   trigger_broken = n                N >= n (0, the default: at once)
//   trigger_broken_since_support = n  N - N0 >= n
//   trigger_broken_growth = g         N - N0 >= g N0 and N > N0
//   trigger_steps = k                 k steps after the stage's start
// N0 is the broken count right after the support went in: the first stage
// that installs one (lining or bolts) keeps it in its record
// (broken_at_install), which a checkpoint restores with the record. The
// trigger is tested after every step; the stage reports which fired, when
// (step, simulated time) and the count then. It stops on its trigger, so a
// run ending on it is not at equilibrium.
#include <cstdio>

#include "rockfdem/error.hpp"
#include "rockfdem/fdem/bolt_grouting.hpp"
#include "scene/schema_keys.hpp"
#include "stages/registry.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// Re-joins the broken crack elements (not a bolt's steel) with grout;
// adds the count and which cracks (with their midpoints) to `done`, for the
// outputs to list.
void grout_broken(StageModel& m, StageChanges& done) {
  const fdem::CrackSelector select = m.bolts.specs.empty()
                                         ? fdem::CrackSelector{}
                                         : fdem::excluding_bolt_steel(m.engine, m.bolts, {});
  const fdem::GroutingResult g = fdem::grout_broken_cracks(m.engine, m.materials.grout, select);
  done.rejoined = g.count;
  done.broken_after = m.engine.broken_counts().total();
  done.grouted.reserve(g.cracks.size());
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    done.grouted.push_back({std::size_t(g.cracks[i]), g.midpoints[i][0], g.midpoints[i][1]});
}

// The entry's own values, read and used here alone.
struct GroutValues final : StageValues {
  long trigger_broken = 0;  ///< broken crack elements that trigger grouting
  /// The trigger keys the entry gives ("trigger_steps", ...), in the
  /// schema's order; check allows one (none: trigger_broken's default, at once).
  std::vector<std::string> triggers;
  double trigger_value = 0;  ///< the first given trigger's value
};

enum class TriggerKind { kBroken, kSinceSupport, kGrowth, kSteps };

struct Trigger {
  TriggerKind kind = TriggerKind::kBroken;
  std::string key = "trigger_broken";
  double value = 0;
  long n0 = 0;  ///< broken count right after the support went in (since-support kinds)

  bool from_support() const {
    return kind == TriggerKind::kSinceSupport || kind == TriggerKind::kGrowth;
  }
  /// Whether it holds now (after a step, or at the stage's start).
  bool reached(const StageDriver& runner, const fdem::Engine& engine) const {
    if (kind == TriggerKind::kSteps) return double(runner.stage_steps()) >= value;
    const long n = engine.broken_counts().total();
    if (kind == TriggerKind::kSinceSupport) return double(n - n0) >= value;
    if (kind == TriggerKind::kGrowth) return n > n0 && double(n - n0) >= value * double(n0);
    return double(n) >= value;
  }
};

/// The entry's trigger without N0: the one key given, else trigger_broken.
Trigger given_trigger(const GroutValues& given) {
  Trigger t;
  if (given.triggers.empty()) {
    t.value = double(given.trigger_broken);
    return t;
  }
  t.key = given.triggers.front();
  t.value = given.trigger_value;
  if (t.key == "trigger_broken_since_support") t.kind = TriggerKind::kSinceSupport;
  if (t.key == "trigger_broken_growth") t.kind = TriggerKind::kGrowth;
  if (t.key == "trigger_steps") t.kind = TriggerKind::kSteps;
  return t;
}

/// N0: the broken count in the record of the first stage that installed support.
long broken_at_support(const StageDriver& runner) {
  for (const StageRecord& r : runner.report()) {
    if (!stage_of(r.kind).installs_support()) continue;
    if (r.changes.broken_at_install) return *r.changes.broken_at_install;
    break;
  }
  throw InputError(
      "grout: no broken count at the support's installation in the run's record (a checkpoint "
      "written before rockfdem kept it); rerun the scene from the start");
}

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

class Grout : public StageWithValues<GroutValues> {
 public:
  const char* description() const override {
    return "re-join broken cracks with grout once its trigger fires: trigger_broken, "
           "trigger_broken_since_support, trigger_broken_growth or trigger_steps";
  }

  // Its triggers, one per stage.
  std::vector<KeySpec> entry_keys() const override {
    using namespace schema;
    std::vector<KeySpec> s;
    s.push_back(integer("stages[].trigger_broken", "0", 0, 1e12,
                        "grout: step until this many crack elements are broken in all (or the "
                        "stage's time has passed), then grout; 0: at once. One trigger per grout "
                        "stage: this, trigger_broken_since_support, trigger_broken_growth or "
                        "trigger_steps."));
    KeySpec since = integer("stages[].trigger_broken_since_support", "", 1, 1e12,
                            "grout: step until this many more crack elements are broken than "
                            "right after the support went in (the first `lining` or `bolts` "
                            "stage, which must come before), then grout.");
    since.default_doc = "none";
    s.push_back(since);
    KeySpec growth =
        schema::number("stages[].trigger_broken_growth", "-", "", 0, true, 1e3, false,
                       "grout: step until the broken count has grown by this fraction of "
                       "its value right after the support went in, and by at least one "
                       "crack element (N - N0 >= g N0 and N > N0), then grout: 0.5 fires "
                       "at half as many again; needs a `lining` or `bolts` stage before.");
    growth.default_doc = "none";
    s.push_back(growth);
    KeySpec steps = integer("stages[].trigger_steps", "", 1, 1e12,
                            "grout: step this many explicit steps from the stage's start, then "
                            "grout (at most the stage's max_steps).");
    steps.default_doc = "none";
    s.push_back(steps);
    return s;
  }

  // trigger_broken with its default; the triggers given, in the schema's order.
  GroutValues read_values(const StageEntry& e) const override {
    GroutValues v;
    v.trigger_broken = long(e.number(".trigger_broken"));
    for (const char* key : {"trigger_broken", "trigger_broken_since_support",
                            "trigger_broken_growth", "trigger_steps"})
      if (e.has(std::string(".") + key)) {
        if (v.triggers.empty()) v.trigger_value = e.number(std::string(".") + key);
        v.triggers.push_back(key);
      }
    return v;
  }

  // The trigger given, as the mesh preview notes it; none: fires at once.
  std::string note(const StageSpec& spec) const override {
    const GroutValues& v = values(spec);
    if (v.triggers.empty()) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%g", v.trigger_value);
    return "(" + v.triggers.front() + " " + text + ")";
  }

  void check(StageCheck& c) const override {
    const std::vector<std::string>& given = values(c.spec).triggers;
    if (given.size() > 1)
      c.refuse("." + given[1], "one trigger per grout stage; " + given[0] + " and " + given[1] +
                                   " are both given: keep one");
    const Trigger t = given_trigger(values(c.spec));
    if (t.from_support() && !c.order.lined && !c.order.bolted)
      c.refuse("." + t.key,
               "counts from the support's installation: needs a `lining` or `bolts` stage "
               "before this one");
    if (t.kind == TriggerKind::kSteps && t.value > double(c.spec.max_steps))
      c.refuse("." + t.key, "the stage stops at its max_steps = " +
                                std::to_string(c.spec.max_steps) + " before; raise max_steps");
  }

  bool step(StageDriver& runner, const StageSpec& spec, StageChanges& changes) const override {
    StageModel& m = runner.model();
    Trigger t = given_trigger(values(spec));
    if (t.from_support()) t.n0 = broken_at_support(runner);
    const auto reached = [&] { return t.reached(runner, m.engine); };
    std::string fired = t.key;
    double value = t.value;
    bool triggered = reached();
    // Triggered by its trigger, or by the stage's time when one is given.
    if (!triggered) {
      triggered = runner.step_until(spec, reached);
      if (!triggered && !runner.stopped() && spec.time > 0 && runner.stage_time() >= spec.time) {
        triggered = true;
        fired = "time";
        value = spec.time;
      }
    }
    changes = {};
    changes.triggered = triggered;
    changes.trigger = fired;
    changes.trigger_value = value;
    if (t.from_support()) changes.broken_at_support = t.n0;
    changes.broken_before = m.engine.broken_counts().total();
    if (!triggered) return false;
    changes.trigger_step = m.engine.step_count();
    changes.trigger_time = m.engine.time();
    grout_broken(m, changes);
    return false;
  }

  std::string outcome(const StageRecord& record) const override {
    const StageChanges& c = record.changes;
    const std::string trigger =
        c.trigger ? *c.trigger + " = " + number(c.trigger_value.value_or(0)) : "";
    if (!c.triggered.value_or(false))
      return trigger.empty() ? "not triggered" : "not triggered (" + trigger + ")";
    std::string s =
        "grouted " + (c.rejoined ? std::to_string(*c.rejoined) : std::string("-")) + " cracks";
    if (!c.trigger_step) return s;  // a record from before the trigger's moment was kept
    s += ", " +
         (*c.trigger == "time" ? "the stage's time " + number(*c.trigger_value) + " s" : trigger) +
         " at step " + std::to_string(*c.trigger_step) +
         " (t = " + number(c.trigger_time.value_or(0)) + " s), " +
         std::to_string(c.broken_before.value_or(0)) + " broken";
    if (c.broken_at_support)
      s += " (" + std::to_string(*c.broken_at_support) + " when the support went in)";
    return s;
  }

  std::string not_at_equilibrium() const override {
    return "stops on its trigger, not on equilibrium: add an equilibrium stage after it";
  }
};

}  // namespace

std::unique_ptr<const Stage> make_grout_stage() { return std::make_unique<Grout>(); }

}  // namespace rockfdem::workflows
