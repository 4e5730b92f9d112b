// A bolt's axial force as a beam section force: the strip is cut normal to
// its axis and the axial stress integrated over the cut, so bending (one
// side of the strip in tension, the other in compression) and the noise of
// single triangles cancel where per-triangle stresses flip sign.
//
// With t the unit axis A -> B, s the distance from the head A along it and
// sigma_aa = t . sigma . t (sigma minus its stress at installation), the
// force the strip carries across the cut at s, per metre of tunnel, is
//   N(s) = integral over the cut of sigma_aa dn                    [N/m]
// Station i is the slab s_i +- Delta/2 (n equal slabs over [0, L]); its
// force is N's mean over the slab, exactly the slab's volume integral
//   N_i = (1 / Delta) sum_t sigma_aa,t |T_t cut to the slab|         [N/m]
// (constant-stress triangles clipped to the slab in the current shape).
// The strip's stresses are the steel's times f = (d / w) / s_b
// (bolt_steel.hpp), so f w = d / s_b and
//   steel stress  sigma_i = N_i / (f w) = N_i s_b / d                [Pa]
//   bar force     F_i = sigma_i pi d^2 / 4                           [N per bar]
// F is the force in one round bar of diameter d at that steel stress (the
// steel law yields at sigma_y: F = fy pi d^2 / 4 there). The model itself
// transfers N_i s_b per bolt row, the force of a strip d wide and 1 m deep
// (the seed's plane idealisation): F_i = N_i s_b (pi d / 4) / (1 m).
// The yield state of a station is the worst of the bolt-steel crack
// elements whose midpoint lies in its slab (ends clamped to the first and
// last slab): 0 elastic, 1 yielding, 2 broken.
#pragma once

#include <vector>

#include "rockfdem/fdem/bolt_install.hpp"

namespace rockfdem::fdem {

struct BoltStation {
  double station = 0;          ///< slab centre's distance from the head A along the axis [m]
  double x = 0, y = 0;         ///< area centroid of the strip inside the slab, current [m]
  double force_per_metre = 0;  ///< N_i [N per m of tunnel]
  double steel_stress = 0;     ///< N_i s_b / d [Pa]
  double bar_force = 0;        ///< steel stress x pi d^2 / 4 [N per bar]
  int state = 0;               ///< 0 elastic, 1 yielding, 2 broken
};

/// Number of stations of bolt b: the bolt length over the mean length of
/// its owned triangles along the axis (mesh shape), at least 2.
int bolt_station_count(const Engine& engine, const BoltPlan& plan, int b);

/// Bolt b's stations head to end (bolt_station_count of them).
std::vector<BoltStation> bolt_sections(const Engine& engine, const BoltPlan& plan, int b);

}  // namespace rockfdem::fdem
