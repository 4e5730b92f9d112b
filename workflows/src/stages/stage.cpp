#include "stages/stage.hpp"

namespace rockfdem::workflows {

void StageModel::set_zone(int zone, bool active, fdem::ActivationReference ref) {
  for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
    if (mesh.zone[t] == zone) engine.set_active(t, active, ref);
}

StageChanges Stage::apply(StageModel&, const StageSpec&) const { return {}; }

bool Stage::step(StageDriver& runner, const StageSpec& spec, StageChanges&) const {
  return runner.step_until(spec, {});
}

std::string Stage::outcome(const StageRecord& record) const {
  if (!record.converged) return installs_support() ? "installed" : "applied (no steps)";
  return *record.converged ? "converged" : "stopped before its criteria";
}

}  // namespace rockfdem::workflows
