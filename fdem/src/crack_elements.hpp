// Four-node crack elements (reference sec. 2): geometry, Simpson integration
// of the crack law along the element, damage history and breakage.
#pragma once

#include <cmath>

#include "engine_data.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::fdem::detail {

/// Writes every live crack element's four nodal forces into its slots,
/// advances damage and marks breakage (state, mode, step). A broken or
/// inactive element's slots are zero. Returns the number broken this step.
long crack_forces(EngineData& d);

/// Stored energy of crack element c: the Simpson-integrated potential of
/// its law at its current damage (crack_point_potential), at `at` or at the
/// current positions; 0 for a broken or inactive element.
double crack_element_energy(const EngineData& d, std::size_t c, const Placement& at);
double crack_element_energy(const EngineData& d, std::size_t c);

/// Current (opening, slip) at end 0 and end 1 of element c, without
/// offsets; returns the element length h.
double crack_end_openings(const EngineData& d, std::size_t c, double out[4]);
double crack_end_openings(const EngineData& d, std::size_t c, const Placement& at, double out[4]);

/// Current (opening, slip) at end 0, the midpoint and end 1 of element c
/// (the three integration points), without offsets; returns h.
double crack_point_openings(const EngineData& d, std::size_t c, double out[6]);
double crack_point_openings(const EngineData& d, std::size_t c, const Placement& at, double out[6]);

/// Subtracts element c's stored offsets (re-joined or pre-stressed points)
/// from its point openings `os` (crack_point_openings' layout): what its
/// law sees.
void subtract_offsets(const EngineData& d, std::size_t c, double os[6]);

/// crack_point_openings less the offsets; returns h.
double law_openings(const EngineData& d, std::size_t c, const Placement& at, double os[6]);
double law_openings(const EngineData& d, std::size_t c, double os[6]);

/// Normal and shear stress (sigma, tau) at end 0, the midpoint and end 1
/// of element c that its law gives at the current positions and damage
/// (the damage history is not raised); zeros for a broken or inactive element.
void crack_point_stresses(const EngineData& d, std::size_t c, double out[6]);

/// Unit tangent e (mid-line from end 0-3 to end 1-2) and normal n of
/// element c at the current positions, as the crack kernel sees it; returns
/// the mid-line's length.
inline double crack_frame(const EngineData& d, std::size_t c, double e[2], double n[2]) {
  const int* nd = &d.cracks.nodes[4 * c];
  const double* p = d.nodes.pos.data();
  const double tx = 0.5 * (p[2 * nd[1]] + p[2 * nd[2]] - p[2 * nd[0]] - p[2 * nd[3]]);
  const double ty =
      0.5 * (p[2 * nd[1] + 1] + p[2 * nd[2] + 1] - p[2 * nd[0] + 1] - p[2 * nd[3] + 1]);
  const double h = std::sqrt(tx * tx + ty * ty);
  e[0] = tx / h;
  e[1] = ty / h;
  n[0] = -e[1];
  n[1] = e[0];
  return h;
}

/// Failure mode from the summed squared excursions at breakage: mode I when
/// opening carries at least 90% of a^2 + b^2, mode II when slip does, else
/// mixed.
FailureMode classify_failure(double sum_a2, double sum_b2);

}  // namespace rockfdem::fdem::detail
