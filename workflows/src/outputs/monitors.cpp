#include "outputs/monitors.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>

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

// The opening's vertices (each edge's first), sorted.
std::vector<int> opening_vertices(const mesh::OpeningBoundary& b) {
  std::vector<int> on_boundary;
  for (const auto& edge : b.edges) on_boundary.push_back(edge[0]);
  std::sort(on_boundary.begin(), on_boundary.end());
  on_boundary.erase(std::unique(on_boundary.begin(), on_boundary.end()), on_boundary.end());
  return on_boundary;
}

// Each key point's nearest vertex of the boundary (ties: the lower vertex id).
std::vector<int> nearest_vertices(const std::vector<mesh::KeyPoint>& points,
                                  const mesh::OpeningBoundary& b, const mesh::Mesh& m) {
  const std::vector<int> on_boundary = opening_vertices(b);
  std::vector<int> out;
  for (const mesh::KeyPoint& p : points) {
    int nearest = on_boundary.front();
    double best = std::numeric_limits<double>::max();
    for (int v : on_boundary) {
      const double d = std::hypot(m.x[v] - p.x, m.y[v] - p.y);
      if (d < best) best = d, nearest = v;
    }
    out.push_back(nearest);
  }
  return out;
}

std::vector<mesh::KeyPoint> key_points_of(const mesh::MeshSpec& spec, const mesh::Mesh& m,
                                          const mesh::OpeningBoundary& b) {
  const bool generated = spec.kind == mesh::ModelKind::kTunnel;
  return mesh::opening_key_points(m, b, generated ? &spec.tunnel : nullptr);
}

mesh::OpeningBoundary require_opening(const mesh::MeshSpec& spec, const mesh::Mesh& m) {
  const bool generated = spec.kind == mesh::ModelKind::kTunnel;
  return require_opening(m, generated ? "the tunnel mesh" : spec.msh.path);
}

// Each key point is tied to its nearest boundary vertex and there to the
// lowest-numbered node of a rock triangle: the core goes, the lining is
// support.
std::vector<Monitor> tie_to_nodes(const std::vector<mesh::KeyPoint>& points,
                                  const mesh::OpeningBoundary& b, const mesh::Mesh& m,
                                  const fdem::Engine& e) {
  std::vector<int> node_of_vertex(m.n_vertices(), -1);
  const std::vector<int>& vertex = e.node_vertex();
  for (std::size_t tri = 0; tri < e.n_triangles(); ++tri) {
    if (m.zone[tri] != mesh::kRock) continue;
    for (int node : e.triangle_nodes(tri)) {
      int& best = node_of_vertex[vertex[node]];
      if (best < 0 || node < best) best = node;
    }
  }

  // mesh::opening_key_points gives them in the roles' order.
  constexpr KeyRole kRoles[] = {KeyRole::kVault,    KeyRole::kLeftShoulder, KeyRole::kRightShoulder,
                                KeyRole::kLeftWall, KeyRole::kRightWall,    KeyRole::kInvert};
  if (points.size() != std::size(kRoles))
    throw std::logic_error("opening_key_points gave " + std::to_string(points.size()) +
                           " key points, not 6");
  const std::vector<int> nearest = nearest_vertices(points, b, m);
  std::vector<Monitor> monitors;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const mesh::KeyPoint& p = points[i];
    Monitor mon;
    mon.name = p.name;
    mon.role = kRoles[i];
    mon.x = p.x, mon.y = p.y;
    mon.node = node_of_vertex[nearest[i]];
    mon.node_x = m.x[nearest[i]], mon.node_y = m.y[nearest[i]];
    mon.inward_x = p.inward_x, mon.inward_y = p.inward_y;
    monitors.push_back(mon);
  }
  return monitors;
}

}  // namespace

std::vector<Monitor> tunnel_monitors(const mesh::MeshSpec& spec, const mesh::Mesh& m,
                                     const fdem::Engine& e) {
  const mesh::OpeningBoundary b = require_opening(spec, m);
  return tie_to_nodes(key_points_of(spec, m, b), b, m, e);
}

std::vector<KeyPointVertex> key_point_vertices(const mesh::MeshSpec& spec, const mesh::Mesh& m) {
  const std::optional<mesh::OpeningBoundary> b = mesh::find_opening(m);
  if (!b) return {};
  const std::vector<mesh::KeyPoint> points = key_points_of(spec, m, *b);
  const std::vector<int> nearest = nearest_vertices(points, *b, m);
  std::vector<KeyPointVertex> out;
  for (std::size_t i = 0; i < points.size(); ++i)
    out.push_back({nearest[i], points[i].inward_x, points[i].inward_y});
  return out;
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

namespace {

double mm(double metres) { return 1000 * metres; }

}  // namespace

KeyPoints::KeyPoints(std::vector<Monitor> monitors, const mesh::Mesh& m,
                     std::vector<double> implicit_ux, std::vector<double> implicit_uy)
    : monitors_(std::move(monitors)),
      implicit_ux_(std::move(implicit_ux)),
      implicit_uy_(std::move(implicit_uy)) {
  for (const mesh::TaggedEdge& edge : m.edges)
    if (edge.tag >= mesh::kBottom && edge.tag <= mesh::kLeft) {
      boundary_vertices_.push_back(edge.a);
      boundary_vertices_.push_back(edge.b);
    }
  std::sort(boundary_vertices_.begin(), boundary_vertices_.end());
  boundary_vertices_.erase(std::unique(boundary_vertices_.begin(), boundary_vertices_.end()),
                           boundary_vertices_.end());
}

const Monitor& KeyPoints::find(KeyRole role) const {
  for (const Monitor& m : monitors_)
    if (m.role == role) return m;
  throw std::logic_error("no monitor of role " + std::to_string(int(role)));
}

double KeyPoints::span() const {
  double lo = 0, hi = 0;
  for (const Monitor& m : monitors_) {
    if (m.role == KeyRole::kLeftWall) lo = m.x;
    if (m.role == KeyRole::kRightWall) hi = m.x;
  }
  return hi - lo;
}

RigidFit KeyPoints::boundary_fit(const fdem::Engine& e) const {
  if (boundary_vertices_.empty()) return {};
  // Every monitor of a step needs the same fit: compute it once per step.
  if (fit_step_ == e.step_count()) return fit_;
  std::vector<double> x, y, ux, uy;
  const std::vector<int>& vertex = e.node_vertex();
  const std::vector<double>& pos = e.positions();
  for (std::size_t node = 0; node < e.n_nodes(); ++node) {
    if (!std::binary_search(boundary_vertices_.begin(), boundary_vertices_.end(), vertex[node]))
      continue;
    const auto d = e.displacement(node);
    x.push_back(pos[2 * node] - d[0]);
    y.push_back(pos[2 * node + 1] - d[1]);
    ux.push_back(d[0]);
    uy.push_back(d[1]);
  }
  fit_ = rigid_fit(x, y, ux, uy);
  fit_step_ = e.step_count();
  return fit_;
}

NodeDisplacement KeyPoints::node_displacements(const fdem::Engine& e) const {
  // Remove the engine's mean translation of the outer boundary (the
  // implicit part already has its rigid motion removed).
  const RigidFit fit = boundary_fit(e);
  return [&e, this, fit](int node) {
    std::array<double, 2> u = node_displacement(e, node, implicit_ux_, implicit_uy_);
    return std::array<double, 2>{u[0] - fit.tx, u[1] - fit.ty};
  };
}

std::array<double, 2> KeyPoints::displacement(const fdem::Engine& e, const Monitor& mon) const {
  return node_displacements(e)(mon.node);
}

std::array<double, 4> KeyPoints::figures(const fdem::Engine& e, const Monitor& mon) const {
  const std::array<double, 2> u = displacement(e, mon);
  return {mm(u[0]), mm(u[1]), mm(std::hypot(u[0], u[1])), mm(radial_convergence(mon, u))};
}

double KeyPoints::convergence(const fdem::Engine& e, KeyRole a, KeyRole b) const {
  const Monitor &ma = find(a), &mb = find(b);
  const auto ua = displacement(e, ma), ub = displacement(e, mb);
  const double dx = mb.x - ma.x, dy = mb.y - ma.y, len = std::hypot(dx, dy);
  return ((ua[0] - ub[0]) * dx + (ua[1] - ub[1]) * dy) / len;
}

std::array<double, 3> KeyPoints::chords_mm(const fdem::Engine& e) const {
  return {-mm(displacement(e, find(KeyRole::kVault))[1]),
          mm(convergence(e, KeyRole::kLeftWall, KeyRole::kRightWall)),
          mm(convergence(e, KeyRole::kLeftShoulder, KeyRole::kRightShoulder))};
}

std::pair<std::string, double> KeyPoints::largest(const fdem::Engine& e,
                                                  const std::vector<Monitor>& monitors) const {
  std::pair<std::string, double> most{"", 0.0};
  for (const Monitor& mon : monitors) {
    const auto u = displacement(e, mon);
    if (std::hypot(u[0], u[1]) > most.second) most = {mon.name, std::hypot(u[0], u[1])};
  }
  return most;
}

}  // namespace rockfdem::workflows
