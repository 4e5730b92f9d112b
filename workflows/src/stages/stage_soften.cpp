// soften: the core (and a ring not yet installed, still ground) down to the
// stage's stiffness factor alpha, the explicit continuation of the
// implicit stage's core softening.
#include <cstdio>

#include "scene/scene_reader.hpp"
#include "scene/schema_keys.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// The entry's own value, read and used here alone.
struct SoftenValues final : StageValues {
  double alpha = 0;  ///< target core stiffness factor (0: not given)
};

class Soften : public StageWithValues<SoftenValues> {
 public:
  const char* description() const override { return "core to alpha, explicit"; }

  std::vector<KeySpec> entry_keys() const override {
    using namespace schema;
    return {number("stages[].alpha", "-", "", 0, true, 1, false,
                   "soften: target core stiffness factor, below the implicit hand-off's.")};
  }

  // Required (check): 0 until then.
  SoftenValues read_values(const StageEntry& e) const override {
    SoftenValues v;
    v.alpha = e.has(".alpha") ? e.number(".alpha") : 0;
    return v;
  }

  std::string note(const StageSpec& spec) const override {
    char text[32];
    std::snprintf(text, sizeof text, "%g", values(spec).alpha);
    return std::string("to alpha ") + text;
  }

  // Softening only goes down, and only while the core is there.
  void check(StageCheck& c) const override {
    c.require(".alpha", "a soften stage needs its target alpha");
    if (!(c.order.alpha > 0)) c.refuse(".kind", "the core is already removed (or alpha = 0)");
    const double alpha = values(c.spec).alpha;
    if (!(alpha < c.order.alpha))
      c.refuse(".alpha", "softening must go down from " + detail::number_text(c.order.alpha));
    c.order.alpha = alpha;
  }

  StageChanges apply(StageModel& m, const StageSpec& spec) const override {
    // A hand-off found at run time (insitu.handoff = "first_crack") may
    // already be at or below this alpha: nothing to soften.
    const double alpha = values(spec).alpha;
    if (!(alpha < m.alpha)) {
      StageChanges skipped;
      skipped.skipped = true;
      return skipped;
    }
    // The engine's core already has alpha_h E and stress: scale relative to it.
    for (std::size_t t = 0; t < m.mesh.n_triangles(); ++t)
      if (m.mesh.zone[t] == mesh::kCore || (!m.lining_installed && m.mesh.zone[t] == mesh::kLining))
        m.engine.set_stiffness_factor(t, alpha / m.handoff_alpha);
    m.alpha = alpha;
    return {};
  }

  bool step(StageDriver& runner, const StageSpec& spec, StageChanges& changes) const override {
    return changes.skipped ? true : Stage::step(runner, spec, changes);
  }

  std::string outcome(const StageRecord& record) const override {
    if (record.changes.skipped) return "skipped (the hand-off was at or below its alpha)";
    return Stage::outcome(record);
  }
};

}  // namespace

std::unique_ptr<const Stage> make_soften_stage() { return std::make_unique<Soften>(); }

}  // namespace rockfdem::workflows
