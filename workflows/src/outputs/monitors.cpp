#include "outputs/monitors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/opening.hpp"

namespace rockfdem::workflows {
namespace {

mesh::OpeningBoundary require_opening(const mesh::Mesh& m, const std::string& source) {
  std::optional<mesh::OpeningBoundary> b = mesh::find_opening(m);
  if (!b)
    throw InputError(source +
                     ": no excavation boundary was found (no rock triangle edge faces "
                     "a core or lining triangle or an inner hole), so there is nowhere to put "
                     "the tunnel monitors; give the rock a hole or mark the opening's triangles "
                     "with a core zone group (see msh.zones)");
  return *b;
}

// Each key point is tied to the nearest vertex of the boundary (ties: the
// lower vertex id) and there to the lowest-numbered node of a rock
// triangle: the core goes, the lining is support.
std::vector<Monitor> tie_to_nodes(const std::vector<mesh::KeyPoint>& points,
                                  const mesh::OpeningBoundary& b, const mesh::Mesh& m,
                                  const fdem::Engine& e) {
  std::vector<int> on_boundary;
  for (const auto& edge : b.edges) on_boundary.push_back(edge[0]);
  std::sort(on_boundary.begin(), on_boundary.end());
  on_boundary.erase(std::unique(on_boundary.begin(), on_boundary.end()), on_boundary.end());

  std::vector<int> node_of_vertex(m.n_vertices(), -1);
  const std::vector<int>& vertex = e.node_vertex();
  for (std::size_t tri = 0; tri < e.n_triangles(); ++tri) {
    if (m.zone[tri] != mesh::kRock) continue;
    for (int node : e.triangle_nodes(tri)) {
      int& best = node_of_vertex[vertex[node]];
      if (best < 0 || node < best) best = node;
    }
  }

  std::vector<Monitor> monitors;
  for (const mesh::KeyPoint& p : points) {
    int nearest = on_boundary.front();
    double best = std::numeric_limits<double>::max();
    for (int v : on_boundary) {
      const double d = std::hypot(m.x[v] - p.x, m.y[v] - p.y);
      if (d < best) best = d, nearest = v;
    }
    Monitor mon;
    mon.name = p.name;
    mon.x = p.x, mon.y = p.y;
    mon.node = node_of_vertex[nearest];
    mon.node_x = m.x[nearest], mon.node_y = m.y[nearest];
    mon.inward_x = p.inward_x, mon.inward_y = p.inward_y;
    monitors.push_back(mon);
  }
  return monitors;
}

}  // namespace

std::vector<Monitor> tunnel_monitors(const mesh::MeshSpec& spec, const mesh::Mesh& m,
                                     const fdem::Engine& e) {
  const bool generated = spec.kind == mesh::ModelKind::kTunnel;
  const mesh::OpeningBoundary b = require_opening(m, generated ? "the tunnel mesh" : spec.msh.path);
  return tie_to_nodes(mesh::opening_key_points(m, b, generated ? &spec.tunnel : nullptr), b, m, e);
}

double radial_convergence(const Monitor& mon, const std::array<double, 2>& u) {
  return u[0] * mon.inward_x + u[1] * mon.inward_y;
}

std::array<double, 2> monitor_displacement(const fdem::Engine& e, const Monitor& mon,
                                           const std::vector<double>& implicit_ux,
                                           const std::vector<double>& implicit_uy) {
  return node_displacement(e, mon.node, implicit_ux, implicit_uy);
}

std::array<double, 2> node_displacement(const fdem::Engine& e, int node,
                                        const std::vector<double>& implicit_ux,
                                        const std::vector<double>& implicit_uy) {
  std::array<double, 2> u = e.displacement(node);
  const int v = e.node_vertex()[node];
  if (!implicit_ux.empty()) {
    u[0] += implicit_ux[v];
    u[1] += implicit_uy[v];
  }
  return u;
}

}  // namespace rockfdem::workflows
