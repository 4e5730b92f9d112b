// How convergence monitoring reads a key point: the vault's settlement and
// the invert's heave are vertical, the shoulders' and walls' convergence
// horizontal (a survey line across the opening, each point's share of its
// closure). The direction is the point's role, not its ray: a shoulder's
// ray at 45 deg mixes both.
#pragma once

#include <string>

#include "record/run_figures.hpp"

namespace rockfdem::workflows {

/// "vertical" for the vault and the invert, "horizontal" for the others.
inline const char* survey_direction(const std::string& key_point) {
  return key_point == "vault" || key_point == "invert" ? "vertical" : "horizontal";
}

/// The component of (ux, uy) that monitoring reads at a key point whose
/// inward direction is (inward_x, inward_y), towards the opening positive.
inline double survey_reading(const std::string& key_point, double ux, double uy, double inward_x,
                             double inward_y) {
  if (survey_direction(key_point)[0] == 'v') return inward_y < 0 ? -uy : uy;
  return inward_x < 0 ? -ux : ux;
}

/// A key point's reading at the end [mm].
inline double survey_reading(const std::string& key_point, const KeyPointFigures& k) {
  return survey_reading(key_point, k.ux_mm, k.uy_mm, k.inward_x, k.inward_y);
}

}  // namespace rockfdem::workflows
