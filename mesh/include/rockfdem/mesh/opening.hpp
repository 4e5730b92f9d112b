// The excavation boundary as the mesh itself has it, and the key points on
// it where monitors go (crown, shoulders, walls, invert). Found from the
// zones alone, so it serves generated tunnels and a user's .msh alike: the
// boundary of the rock region (rock triangle edges with no rock triangle on
// the other side: against core or lining, or free) splits into closed
// loops; running each with the rock on its left, the outer boundary turns
// counter-clockwise (positive area) and every opening clockwise (negative
// area). The opening is the loop enclosing the largest area.
//
//        crown (on the vertical axis, highest)
//          .--*--.
//   left  /   |   \  right shoulder: 45 deg from the arch centre
// shoulder*   +   *                  (springing, corner: per shape)
//        |    |    |
//  wall  *----+----*  wall: outermost at the wall height of the shape
//        |____*____|
//           invert (lowest on the axis)
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh {

struct OpeningBoundary {
  /// Boundary edges (vertex ids), each running with the rock on its left:
  /// clockwise around the opening.
  std::vector<std::array<int, 2>> edges;
  double area = 0;                                ///< area enclosed [m^2] (> 0)
  double cx = 0, cy = 0;                          ///< centroid of the enclosed area [m]
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;  ///< bounding box of the boundary [m]
};

/// The largest opening in the rock zone, or nothing when the rock has no
/// inner boundary (a specimen, a .msh without a hole or core).
std::optional<OpeningBoundary> find_opening(const Mesh& m);

/// A point on the opening's boundary with the unit vector from it towards
/// the opening's centre it was found from (see opening_key_points):
/// u . inward > 0 is convergence (the rock moving into the opening).
struct KeyPoint {
  std::string name;  ///< vault, left_shoulder, right_shoulder, left_wall, right_wall, invert
  double x = 0, y = 0;
  double inward_x = 0, inward_y = 0;
};

/// The six key points on `b`, in the order vault, left_shoulder,
/// right_shoulder, left_wall, right_wall, invert. Each is where a ray from a
/// centre point meets the boundary farthest out, and `inward` points back
/// along that ray:
/// - vault / invert: the vertical axis through the centre, highest / lowest;
/// - walls: the horizontal at the wall height, outermost left / right;
/// - shoulders: rays up-left and up-right from the shoulder centre.
/// With `shape` (the boundary was built from it; sizes are taken from the
/// boundary's bounding box, the arch radius or rise from the spec):
/// | shape | axis x | wall height | shoulder rays |
/// | circular | box centre | centre | 45 deg from the centre |
/// | horseshoe | box centre | midway springline (ymax - span/2) - wall foot | 45 deg from the arch
/// centre | | arched | box centre | midway springing (ymax - rise) - wall foot | from the arch
/// centre through the springing points | | rectangular | box centre | mid-height | from the centre
/// through the top corners | Without `shape` (a user's mesh): everything from the area centroid,
/// walls at its height, shoulders at 45 deg.
std::vector<KeyPoint> opening_key_points(const Mesh& m, const OpeningBoundary& b,
                                         const TunnelSpec* shape);

/// True when every vertex of `b` lies within `tolerance` [m] of the exact
/// outline of `t` (the opening centred on the origin, as build_mesh makes it).
bool boundary_matches(const Mesh& m, const OpeningBoundary& b, const TunnelSpec& t,
                      double tolerance);

}  // namespace rockfdem::mesh
