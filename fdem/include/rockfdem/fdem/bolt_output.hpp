// What a bolt carries: axial stress and force along each bolt, and the
// state of its steel and grout crack elements.
//
// Definitions (bolt_steel.hpp: the strip's stresses are the steel's times
// f = (d / w) / s_b, w the strip width). Per strip triangle, with t the
// bolt's unit axis (A -> B) and sigma the triangle's Cauchy stress minus
// its stress at installation:
//   smeared_stress  = t . sigma . t                 [Pa]  (in the model)
//   steel_stress    = smeared_stress / f            [Pa]  (compare with sigma_y, sigma_u)
//   force_per_metre = smeared_stress * w            [N/m] (per metre of tunnel)
//   force_per_bolt  = force_per_metre * s_b         [N]   (= steel_stress * d * 1 m)
// Yielding and broken counts come from the bolt-steel crack elements
// inside each strip (Engine::crack_state).
#pragma once

#include <vector>

#include "rockfdem/fdem/bolt_install.hpp"

namespace rockfdem::fdem {

struct BoltSample {
  int triangle = 0;
  double position = 0;  ///< centroid's distance from the head A along the axis [m] (current)
  double smeared_stress = 0;
  double steel_stress = 0;
  double force_per_metre = 0;
  double force_per_bolt = 0;
};

/// Bolt b's strip triangles head to end (only those it owns).
std::vector<BoltSample> bolt_axial_profile(const Engine& engine, const BoltPlan& plan, int b);

struct BoltCounts {
  long steel_cracks = 0, yielding = 0, broken = 0;  ///< bolt-steel crack elements
  long grout_cracks = 0, grout_broken = 0;          ///< bolt-rock interface
};

/// Counts for bolt b, or summed over all installed bolts when b < 0.
BoltCounts bolt_counts(const Engine& engine, const BoltPlan& plan, int b = -1);

}  // namespace rockfdem::fdem
