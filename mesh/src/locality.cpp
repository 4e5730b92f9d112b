// The locality order: a Hilbert curve through the triangles' centroids.
// A Hilbert rather than a Morton (Z) curve because consecutive Hilbert
// cells always touch, so a run of consecutive triangles is one compact
// patch, never two far apart; and a curve rather than reverse
// Cuthill-McKee because the engine's nodes are not one graph's: a fracture
// triangle owns its three nodes, so what matters is that triangles near in
// space are near in the arrays, which the curve gives from the centroids
// alone (a sort, no graph).
#include "rockfdem/mesh/locality.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

namespace rockfdem::mesh {
namespace {

/// Grid resolution of the curve: 2^20 cells along the bounding square's
/// side (0.1 mm on a 100 m model, far below any element size).
constexpr int kOrder = 20;

std::uint32_t cell(double v, double lo, double scale) {
  const double top = double((std::uint32_t(1) << kOrder) - 1);
  return std::uint32_t(std::clamp(std::floor((v - lo) * scale), 0.0, top));
}

}  // namespace

// The classic iterative conversion: at each level the quadrant gives two
// bits of the index, then the coordinates are turned into that quadrant's
// own frame.
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y, int order) {
  assert(order >= 1 && order <= 31);
  const std::uint32_t n = std::uint32_t(1) << order;
  std::uint64_t d = 0;
  for (std::uint32_t s = n / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = n - 1 - x;
        y = n - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

std::vector<int> locality_order(const Mesh& m) {
  const std::size_t nt = m.n_triangles();
  double xlo = std::numeric_limits<double>::infinity(), ylo = xlo;
  double xhi = -xlo, yhi = -xlo;
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    xlo = std::min(xlo, m.x[v]);
    xhi = std::max(xhi, m.x[v]);
    ylo = std::min(ylo, m.y[v]);
    yhi = std::max(yhi, m.y[v]);
  }
  const double side = std::max(xhi - xlo, yhi - ylo);
  const double scale = side > 0 ? double(std::uint32_t(1) << kOrder) / side : 0.0;
  std::vector<std::pair<std::uint64_t, int>> keyed(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto& [a, b, c] = m.triangles[t];
    const double cx = (m.x[a] + m.x[b] + m.x[c]) / 3, cy = (m.y[a] + m.y[b] + m.y[c]) / 3;
    keyed[t] = {hilbert_index(cell(cx, xlo, scale), cell(cy, ylo, scale), kOrder), int(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<int> order(nt);
  for (std::size_t t = 0; t < nt; ++t) order[t] = keyed[t].second;
  return order;
}

Mesh with_triangle_order(const Mesh& m, const std::vector<int>& order) {
  const std::size_t nt = m.n_triangles();
  assert(order.size() == nt);
  Mesh r;
  r.x = m.x;
  r.y = m.y;
  r.edges = m.edges;
  r.joint_edges = m.joint_edges;
  r.triangles.resize(nt);
  r.zone.resize(m.zone.size());
  r.fracture.resize(m.fracture.size());
  for (std::size_t t = 0; t < nt; ++t) {
    const int old = order[t];
    r.triangles[t] = m.triangles[old];
    if (!m.zone.empty()) r.zone[t] = m.zone[old];
    if (!m.fracture.empty()) r.fracture[t] = m.fracture[old];
  }
  return r;
}

}  // namespace rockfdem::mesh
