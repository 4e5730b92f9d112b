// Grouting of broken crack elements (bolt_grouting.hpp).
#include "rockfdem/fdem/bolt_grouting.hpp"

#include <memory>

namespace rockfdem::fdem {

GroutingResult grout_broken_cracks(Engine& engine, int grout_material,
                                   const CrackSelector& select) {
  GroutingResult r;
  const auto& pos = engine.positions();
  for (std::size_t c = 0; c < engine.n_cracks(); ++c) {
    if (engine.crack_state(c) != CrackState::kBroken) continue;
    Point2 mid{0, 0};
    for (int n : engine.crack_nodes(c)) {
      mid[0] += 0.25 * pos[2 * n];
      mid[1] += 0.25 * pos[2 * n + 1];
    }
    if (select && !select(c, mid)) continue;
    engine.rejoin_crack(c, grout_material);
    r.cracks.push_back(int(c));
    r.midpoints.push_back(mid);
  }
  r.count = long(r.cracks.size());
  return r;
}

CrackSelector cracks_touching(const Engine& engine, const std::vector<int>& triangles) {
  auto in_zone = std::make_shared<std::vector<char>>(engine.n_triangles(), 0);
  for (int t : triangles) (*in_zone)[t] = 1;
  const Engine* e = &engine;
  return [in_zone, e](std::size_t c, const Point2&) {
    const auto tri = e->crack_triangles(c);
    return (*in_zone)[tri[0]] || (*in_zone)[tri[1]];
  };
}

CrackSelector excluding_bolt_steel(const Engine& engine, const BoltPlan& plan,
                                   CrackSelector inner) {
  auto steel = std::make_shared<std::vector<char>>(engine.n_cracks(), 0);
  for (std::size_t b = 0; b < plan.specs.size(); ++b)
    for (int c : bolt_cracks(engine, plan, int(b)).steel) (*steel)[c] = 1;
  return [steel, inner](std::size_t c, const Point2& mid) {
    return !(*steel)[c] && (!inner || inner(c, mid));
  };
}

}  // namespace rockfdem::fdem
