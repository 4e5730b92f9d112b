// Monitor points on the tunnel boundary: vault (crown), shoulders,
// sidewalls and invert, each tied to the engine node of a rock triangle
// nearest to its point on the opening's outline. Displacements include the
// implicit stage's excavation-induced part (they are measured from the
// in-situ state).
#pragma once

#include <string>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::workflows {

struct Monitor {
  std::string name;   ///< vault, left_shoulder, right_shoulder, left_wall, right_wall, invert
  double x = 0, y = 0;  ///< point on the outline [m]
  int node = -1;        ///< engine node followed
};

/// The standard monitor points of the tunnel shape, tied to engine nodes.
std::vector<Monitor> tunnel_monitors(const mesh::TunnelSpec& t, const mesh::Mesh& m,
                                     const fdem::Engine& e);

/// Displacement of a monitor from the in-situ state: the implicit stage's
/// part (per mesh vertex, may be empty) plus the engine's increment [m].
std::array<double, 2> monitor_displacement(const fdem::Engine& e, const Monitor& mon,
                                           const std::vector<double>& implicit_ux,
                                           const std::vector<double>& implicit_uy);

}  // namespace rockfdem::workflows
