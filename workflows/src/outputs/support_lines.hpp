// Support characteristic lines of convergence-confinement, per metre of
// tunnel, each an elastic-perfectly plastic line in (wall displacement
// since installation, support pressure): p = K du up to p_max, then flat.
//
//  - Closed shotcrete or concrete ring of outer radius R and thickness t
//    (Hoek 1999; Carranza-Torres and Diederichs 2009, thick-walled ring
//    under external pressure, plane strain):
//      p_max = (sigma_c / 2) (1 - (R - t)^2 / R^2)
//      K     = E (R^2 - (R - t)^2) / ((1 + nu) ((1 - 2 nu) R^2 + (R - t)^2) R)
//  - A ring of parts (a horseshoe's arch and walls, its invert), each
//    part i a share s_i of the ring's length, of its own thickness t_i and
//    material: under a uniform pressure p every part carries the same
//    thrust N = p R (a ring's equilibrium, whatever the stiffnesses), so
//    the ring fails with its weakest part, p_max = min_i p_max,i (each
//    part's closed-ring p_max); its circumference shortens by the parts'
//    hoop strains over their lengths, so the compliances add by length,
//    1/K = sum_i s_i / K_i. One part: the closed ring above.
//  - Bolts on a pattern s_c (round the opening) by s_l (along it) (Hoek and
//    Brown 1980; Carranza-Torres and Fairhurst 2000):
//      p_max = T_bf / (s_c s_l),   1/K = s_c s_l (4 l / (pi d^2 E_b) + Q)
//  - Their sum (Hoek and Brown 1980; Carranza-Torres and Fairhurst 2000):
//    K = sum K_i, and the combined system fails when its first component
//    reaches its own maximum displacement: u_max = min u_max,i,
//    p_max = K u_max.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

struct SupportLine {
  std::string name;      ///< "shotcrete", "lining ring", "bolts", "cables", "combined"
  double p_max = 0;      ///< the support's largest pressure [Pa]
  double stiffness = 0;  ///< K [Pa/m]
  std::string note;      ///< how a ring of parts is taken (empty otherwise)
  /// The displacement since installation at which p_max is reached [m].
  double max_displacement() const { return p_max / stiffness; }
};

/// The closed ring (above): sigma_c its compressive strength [Pa], E [Pa],
/// nu, R its outer radius and t its thickness [m].
SupportLine shotcrete_ring_line(double sigma_c, double young, double poisson, double radius,
                                double thickness);

/// One part of the lining ring (above).
struct RingPart {
  std::string name;                            ///< "ring", "arch and walls", "invert"
  double share = 1;                            ///< of the ring's mid-line length
  double thickness = 0;                        ///< [m]
  double sigma_c = 0, young = 0, poisson = 0;  ///< [Pa], [Pa], -
};

/// The ring of `parts` (above) at outer radius R: named "shotcrete" for
/// one part, "lining ring" with a note naming the weakest part for more.
SupportLine ring_line(const std::vector<RingPart>& parts, double radius);

/// Bolts (above): T_bf the failure load of one bolt [N], s_c and s_l the
/// spacings [m], l the length [m], d the diameter [m], E_b [Pa], Q the
/// deformation-load constant of anchor and head [m/N].
SupportLine bolt_line(double failure_load, double spacing_round, double spacing_along,
                      double length, double diameter, double young, double q);

/// The sum of `parts` (above); needs at least one.
SupportLine combined_line(const std::vector<SupportLine>& parts);

/// The line's pressure at displacement du since installation [Pa]: 0
/// before, K du up to p_max, then p_max.
double line_pressure(const SupportLine& s, double du);

/// The opening as an equivalent circle: R = sqrt(A / pi), A the area of the
/// core and lining triangles (what is excavated); the ring's thickness from
/// the lining triangles' area A_l, (R - t)^2 = R^2 - A_l / pi (0: none);
/// the centre is the excavated area's centroid.
struct EquivalentOpening {
  double radius = 0, lining_thickness = 0, cx = 0, cy = 0;
};
EquivalentOpening equivalent_opening(const mesh::Mesh& m);

/// The lining ring of mesh `m` as built, for ring_line: a horseshoe's or
/// arched opening's arch and walls (tunnel.lining_thickness, materials.
/// lining) and floor part (tunnel.invert_thickness, materials.invert where
/// given, else the lining's), each part's length share its lining
/// triangles' area over its thickness; other rings one part of o's
/// thickness. None without a ring or the lining's compressive strength.
std::vector<RingPart> ring_parts(const Scene& scene, const mesh::Mesh& m,
                                 const EquivalentOpening& o);

/// The scene's support as lines on the equivalent opening: the lining ring
/// of `ring` (ring_parts; empty: one part of o's thickness and materials.
/// lining, when it has a compressive strength), the bolts and the cables (each
/// kind with s_c = R times the median angle between neighbouring heads
/// about the centre, s_l its row spacing, l its mean length, T_bf its
/// ultimate strength times pi d^2 / 4, and Q = 0: fully grouted, no
/// anchor or head slip), and their sum when there are two or more.
std::vector<SupportLine> scene_support_lines(const Scene& scene, const EquivalentOpening& o,
                                             std::vector<RingPart> ring = {});

}  // namespace rockfdem::workflows
