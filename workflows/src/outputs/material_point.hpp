// A material point of the rock followed through a run: the point (x, y)
// of the reference (mesh) configuration, found once in the triangle that
// contains it; its displacement is the constant-strain triangle's linear
// interpolation of that triangle's own three engine nodes. Each triangle
// has its own nodes in the engine (crack elements join them), so the point
// moves with the block it belongs to, across broken cracks too.
#pragma once

#include <array>
#include <functional>
#include <optional>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

/// Displacement of an engine node from the in-situ state [m].
using NodeDisplacement = std::function<std::array<double, 2>(int node)>;

struct MaterialPoint {
  int triangle = -1;                ///< mesh (and engine) triangle containing the point
  int zone = 0;                     ///< its mesh::Zone
  std::array<int, 3> nodes{};       ///< the triangle's engine nodes, in its vertex order
  std::array<double, 3> weights{};  ///< CST shape functions at the point (sum 1)
  double x = 0, y = 0;              ///< the point in the reference configuration [m]
};

/// The triangle containing (x, y) in the mesh, with the point's shape
/// function values. A point on an edge or vertex shared by several
/// triangles takes the rock's (then the lining's, then the core's), the
/// lowest triangle id among equals. Nothing when no triangle contains it
/// (outside the domain, or in a hole of a user's mesh).
std::optional<MaterialPoint> locate(const mesh::Mesh& m, const fdem::Engine& e, double x, double y);

/// The point's displacement: sum of N_i u_i over its triangle's nodes [m].
std::array<double, 2> interpolate(const MaterialPoint& p, const NodeDisplacement& u);

}  // namespace rockfdem::workflows
