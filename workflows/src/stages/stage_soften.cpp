// soften: the core (and a ring not yet installed, still ground) down to the
// stage's stiffness factor alpha, the explicit continuation of the
// implicit stage's core softening.
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

class Soften : public Stage {
 public:
  const char* description() const override { return "core to alpha, explicit"; }

  StageChanges apply(StageModel& m, const StageSpec& spec) const override {
    // The engine's core already has alpha_h E and stress: scale relative to it.
    for (std::size_t t = 0; t < m.mesh.n_triangles(); ++t)
      if (m.mesh.zone[t] == mesh::kCore || (!m.lining_installed && m.mesh.zone[t] == mesh::kLining))
        m.engine.set_stiffness_factor(t, spec.alpha / m.handoff_alpha);
    m.alpha = spec.alpha;
    return {};
  }
};

}  // namespace

std::unique_ptr<const Stage> make_soften_stage() { return std::make_unique<Soften>(); }

}  // namespace rockfdem::workflows
