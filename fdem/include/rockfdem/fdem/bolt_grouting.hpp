// Grouting (seed sec. 2.3): broken crack elements in a zone are re-joined
// with grout properties, their accumulated opening and slip becoming their
// new zero (Engine::rejoin_crack). The seed grouts every excavation-induced
// crack; a selector narrows the zone.
//
//   GroutingResult r = grout_broken_cracks(engine, grout_index);               // everywhere
//   GroutingResult r = grout_broken_cracks(engine, grout_index,
//                          cracks_touching(engine, zone_triangles));           // a zone
//   GroutingResult r = grout_broken_cracks(engine, grout_index,
//                          excluding_bolt_steel(engine, plan, selector));     // keep broken bolts
//                          broken
#pragma once

#include <functional>
#include <vector>

#include "rockfdem/fdem/bolt_install.hpp"

namespace rockfdem::fdem {

/// Chooses crack elements: index and current midpoint (mean of its four nodes).
using CrackSelector = std::function<bool(std::size_t crack, const Point2& midpoint)>;

struct GroutingResult {
  long count = 0;                 ///< crack elements re-joined
  std::vector<int> cracks;        ///< their indices, ascending
  std::vector<Point2> midpoints;  ///< their current midpoints [m]
};

/// Re-joins every broken crack element the selector accepts (all when
/// empty) with material `grout_material` (an index into the engine's
/// materials, e.g. ModelInput::materials with a grout Material appended).
GroutingResult grout_broken_cracks(Engine& engine, int grout_material,
                                   const CrackSelector& select = {});

/// Accepts crack elements with a triangle in `triangles` on either side.
CrackSelector cracks_touching(const Engine& engine, const std::vector<int>& triangles);

/// Accepts what `inner` accepts (everything when empty) except the
/// bolt-steel crack elements of the plan's bolts: grout does not mend steel.
CrackSelector excluding_bolt_steel(const Engine& engine, const BoltPlan& plan,
                                   CrackSelector inner = {});

}  // namespace rockfdem::fdem
