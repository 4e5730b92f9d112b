// Section forces of the lining ring: thrust N, bending moment M and shear V
// per metre of tunnel, per segment of the ring, from the lining triangles'
// stresses integrated through the thickness (docs/support.md, "Lining
// forces"), and the plain-shotcrete capacity check of each segment.
//
//          rock                 n: outward (towards the rock), from the mid-line
//     ~~~~~~~~~~~~~~~ outer     t: counter-clockwise around the opening
//       |  |  |  |   lining     a segment: the lining between the normals at
//     ~~~~~~~~~~~~~~~ inner        the ends of one outer boundary edge
//        opening
//
// Pure geometry and arithmetic on the mesh and per-triangle stresses (no
// engine), so an analytic stress field can be integrated in a test.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

/// One segment of the ring, laid on the mesh as built.
struct LiningSegment {
  double angle_deg = 0;   ///< of the mid-line point about the opening's centroid, from +x, ccw
  double arc_m = 0;       ///< along the mid-line from the first segment (the one nearest 0 deg)
  double x = 0, y = 0;    ///< mid-line point [m]
  double thickness = 0;   ///< outer to inner boundary, normal to the outer edge [m]
  double tx = 0, ty = 0;  ///< unit tangent, counter-clockwise
  double nx = 0, ny = 0;  ///< unit normal, outward (towards the rock)
  /// The ring turns by more than kCornerTurnDeg to a neighbouring segment (a
  /// horseshoe's floor corner): the cut is no beam section there.
  bool corner = false;
  std::vector<int> triangles;  ///< lining triangles nearest this segment's outer edge
  std::vector<double> area;    ///< their areas [m^2]
  std::vector<double> offset;  ///< their centroids' n from the mid-line, outward [m]
};

constexpr double kCornerTurnDeg = 20;

struct LiningGeometry {
  std::vector<LiningSegment> segments;  ///< counter-clockwise from 0 deg
  double cx = 0, cy = 0;                ///< centroid of the opening (the angle's origin) [m]
};

/// The ring's segments, one per edge of the lining-rock interface, or
/// nothing when the mesh has no lining triangles around an opening.
std::optional<LiningGeometry> lining_geometry(const mesh::Mesh& m);

/// Section forces per metre of tunnel, from the compression-positive
/// stress s = -sigma in the segment's (t, n) frame.
struct SectionForces {
  double thrust = 0;  ///< N = int s_tt dn [N/m], compression positive
  double moment = 0;  ///< M = int s_tt n dn [N m/m], > 0: the rock side more compressed
  double shear = 0;   ///< V = int s_nt dn [N/m]
};

/// `stress`: per mesh triangle (sxx, syy, sxy) [Pa], tension positive (the
/// engine's). N and V: the thickness times the area-weighted mean of s_tt
/// and s_nt over the segment's triangles (the mean over the segment of the
/// cut integrals); M = t^3 / 12 times the slope of the area-weighted least
/// squares line s_tt(n) through the centroids of the triangles of the
/// segment and its two neighbours (Navier's linear distribution through
/// the thickness).
std::vector<SectionForces> lining_forces(const LiningGeometry& g,
                                         const std::vector<std::array<double, 3>>& stress);

/// Strengths of the plain shotcrete section [Pa] (tensile 0: no tension).
struct ShotcreteStrength {
  double compressive = 0;
  double tensile = 0;
};

/// Factor by which N and M together (a ray from the origin of the M-N
/// diagram) reach the elastic capacity of a plain rectangular section of
/// thickness t: an extreme fibre stress N/t +- 6M/t^2 at the compressive
/// strength or at minus the tensile strength. Infinite when unloaded.
double safety_factor(const SectionForces& f, double thickness, const ShotcreteStrength& s);

/// The capacity envelope for safety factor `fs` in the M-N diagram: the
/// closed polygon of (M [N m/m], N [N/m]) points.
std::vector<std::array<double, 2>> capacity_envelope(double thickness, const ShotcreteStrength& s,
                                                     double fs);

/// lining.csv's text: a header and one row per segment, forces in kN/m and
/// kNm/m; `safety_factors` (one per segment, of its section) null: no
/// utilisation or safety factor (empty cells).
std::string lining_csv(long step, const LiningGeometry& g, const std::vector<SectionForces>& f,
                       const std::vector<double>* safety_factors);

}  // namespace rockfdem::workflows
