// Bolt outputs (bolt_output.hpp).
#include "rockfdem/fdem/bolt_output.hpp"

#include <cmath>

namespace rockfdem::fdem {

std::vector<BoltSample> bolt_axial_profile(const Engine& engine, const BoltPlan& plan, int b) {
  const BoltSpec& spec = plan.specs[b];
  const double len = plan.strips[b].length;
  const double ux = (spec.bolt.b[0] - spec.bolt.a[0]) / len;
  const double uy = (spec.bolt.b[1] - spec.bolt.a[1]) / len;
  const double f = plan.steel[b].scale, w = plan.strips[b].width;
  const auto& pos = engine.positions();
  std::vector<BoltSample> out;
  for (std::size_t i = 0; i < plan.owned[b].size(); ++i) {
    BoltSample s;
    s.triangle = plan.owned[b][i];
    double cx = 0, cy = 0;
    for (int n : engine.triangle_nodes(s.triangle)) {
      cx += pos[2 * n] / 3;
      cy += pos[2 * n + 1] / 3;
    }
    s.position = (cx - spec.bolt.a[0]) * ux + (cy - spec.bolt.a[1]) * uy;
    const auto now = engine.triangle_stress(s.triangle);
    const auto& at_install = plan.installed_stress[b][i];
    const double sxx = now[0] - at_install[0], syy = now[1] - at_install[1];
    const double sxy = now[2] - at_install[2];
    s.smeared_stress = ux * ux * sxx + uy * uy * syy + 2 * ux * uy * sxy;
    s.steel_stress = s.smeared_stress / f;
    s.force_per_metre = s.smeared_stress * w;
    s.force_per_bolt = s.force_per_metre * spec.row_spacing;
    out.push_back(s);
  }
  return out;
}

BoltCounts bolt_counts(const Engine& engine, const BoltPlan& plan, int b) {
  BoltCounts total;
  for (std::size_t k = 0; k < plan.specs.size(); ++k) {
    if ((b >= 0 && int(k) != b) || (b < 0 && !plan.installed[k])) continue;
    const BoltCracks cracks = bolt_cracks(engine, plan, int(k));
    total.steel_cracks += long(cracks.steel.size());
    total.grout_cracks += long(cracks.grout.size());
    for (int c : cracks.steel) {
      const CrackState s = engine.crack_state(c);
      total.yielding += s == CrackState::kYielding;
      total.broken += s == CrackState::kBroken;
    }
    for (int c : cracks.grout) total.grout_broken += engine.crack_state(c) == CrackState::kBroken;
  }
  return total;
}

}  // namespace rockfdem::fdem
