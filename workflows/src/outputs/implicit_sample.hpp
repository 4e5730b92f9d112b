// What a tunnel run reads of an implicit field once the implicit stage is
// over, taken as each field is solved: the run then holds whole only the
// field it hands over (16 MB per field at 420k triangles), not every
// alpha's.
#pragma once

#include <cstddef>
#include <vector>

namespace rockfdem::workflows {

/// A key point (key_point_vertices' order) in one field.
struct KeyPointSample {
  double ux = 0, uy = 0;     ///< the displacement at its vertex [m]
  double core_pressure = 0;  ///< ground_reaction.hpp's core_pressure [Pa], 0 for none
};

struct ImplicitSample {
  double alpha = 1;
  std::vector<KeyPointSample> key_points;  ///< none when the mesh has no opening
  double strength_ratio = 0;               ///< HandoffChoice's, for this field
  long inverted = 0;                       ///< triangles the field inverts (implicit_check.hpp)
  std::size_t first_inverted = 0;
  double wall_displacement = 0;  ///< face_distance.hpp's, with install_at_face_distance only
};

}  // namespace rockfdem::workflows
