// The capacity of a lining section per metre of tunnel in the M-N plane
// (the support capacity diagram) and a segment's safety factor against it,
// for the three kinds of section a ring part may have (docs/support.md,
// "Section types"):
//
//   plain       shotcrete: the elastic limit of the extreme fibre stresses
//   reinforced  two symmetric layers of bars: EN 1992-1-1's rectangular
//               stress block, steel elastic-perfectly plastic, the neutral
//               axis swept from pure tension to pure compression
//   steel_sets  sets embedded in the shotcrete: N and M shared by axial and
//               flexural stiffness, each part within its own elastic limit
//               (Carranza-Torres and Diederichs 2009)
//
// The safety factor is radial: the factor by which (N, M) scaled along the
// ray from the origin reaches the diagram's boundary.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "outputs/lining_forces.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

enum class SectionKind { kPlain, kReinforced, kSteelSets };

/// A ring part's section, all but its thickness (measured per segment).
struct LiningSection {
  SectionKind kind = SectionKind::kPlain;
  ShotcreteStrength concrete;  ///< fc (fck for reinforced) and ft (plain and steel_sets)
  double concrete_young = 0;   ///< Pa: the shotcrete's share of the steel sets' composite
  double steel_young = 0, steel_yield = 0;  ///< Pa, bars or sets
  double bar_area = 0, bar_cover = 0;       ///< reinforced: m^2/m each face, m to its centroid
  double set_area = 0, set_inertia = 0, set_depth = 0, set_spacing = 0;  ///< steel_sets, one set
};

/// "plain", "reinforced", "steel_sets" (the scene's words).
std::string section_name(SectionKind kind);

/// The section of a ring part's material (materials.lining or .invert).
LiningSection lining_section(const MaterialSpec& m);

/// A point of the M-N diagram: (M [N m/m], N [N/m], compression positive).
using MNPoint = std::array<double, 2>;

/// The section's capacity diagram at `thickness` [m]: a closed polygon
/// (last point = first), counter-clockwise in (M, N), around the origin.
std::vector<MNPoint> capacity_diagram(const LiningSection& s, double thickness);

/// The reinforced section's diagram: from pure tension (0, -2 As fy) up the
/// M > 0 side to pure compression (0, Nc), down the mirrored M < 0 side.
std::vector<MNPoint> reinforced_diagram(const LiningSection& s, double thickness);

/// The steel sets' shares of the composite's thrust and moment: EA and EI
/// of the sets per metre over the sum with the shotcrete's (t, t^3/12).
struct CompositeShares {
  double thrust = 0, moment = 0;
};
CompositeShares steel_set_shares(const LiningSection& s, double thickness);

/// The factor by which (N, M) along the ray from the origin reaches the
/// closed polygon `diagram` (the origin inside); infinite when unloaded or
/// when the ray never leaves it.
double radial_safety_factor(const std::vector<MNPoint>& diagram, const SectionForces& f);

/// A segment's safety factor: plain, the closed form of lining_forces.hpp
/// (unchanged); reinforced, radial to the diagram; steel sets, the smaller
/// of the shotcrete's and the sets' factors for their shares.
double section_safety_factor(const SectionForces& f, double thickness, const LiningSection& s);

}  // namespace rockfdem::workflows
