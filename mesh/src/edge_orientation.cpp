// Edge orientation and node valence inside a band of triangles (see
// rockfdem/mesh/edge_orientation.hpp for what the figures mean).
#include "rockfdem/mesh/edge_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <utility>

#include "rockfdem/mesh/constants.hpp"

namespace rockfdem::mesh {
namespace {

// Edges shared by two of the band's triangles, as (low, high) pairs: where
// crack elements can sit. The band's rims are left out: the excavation
// boundary is tangential by construction (it would add about 1.5 x 12 = 18%
// to the tangential bin of the default tunnel) and the outer rim is a
// zig-zag of edges no crack joins on both sides.
std::vector<std::pair<int, int>> band_edges(const Mesh& m,
                                            const std::vector<std::uint8_t>& in_band) {
  std::vector<std::pair<int, int>> all, edges;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (!in_band[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      all.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i + 1 < all.size(); ++i)
    if (all[i] == all[i + 1]) edges.push_back(all[i]);
  return edges;
}

// Valence over the whole mesh, counted only at nodes whose every triangle
// lies in the band (nodes on the band's rim see a cut fan).
void count_valence(const Mesh& m, const std::vector<std::uint8_t>& in_band, EdgeOrientation& out) {
  const std::size_t n = m.n_vertices();
  std::vector<std::uint8_t> touched(n, 0), outside(n, 0);
  std::vector<std::pair<int, int>> all;
  all.reserve(3 * m.n_triangles());
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      (in_band[t] ? touched : outside)[a] = 1;
      all.emplace_back(std::min(a, b), std::max(a, b));
    }
  // Nodes on a boundary or interface edge (one triangle) are not interior.
  std::sort(all.begin(), all.end());
  std::vector<int> valence(n, 0);
  std::vector<std::uint8_t> on_rim(n, 0);
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    while (j < all.size() && all[j] == all[i]) ++j;
    ++valence[all[i].first], ++valence[all[i].second];
    if (j - i == 1) on_rim[all[i].first] = on_rim[all[i].second] = 1;
    i = j;
  }
  std::size_t n_six = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (!touched[v] || outside[v] || on_rim[v]) continue;
    ++out.n_interior_nodes;
    if (valence[v] == 6) ++n_six;
  }
  out.valence6_fraction = out.n_interior_nodes ? double(n_six) / out.n_interior_nodes : 0;
}

void band_quality(const Mesh& m, const std::vector<std::uint8_t>& in_band, EdgeOrientation& out) {
  out.min_altitude = out.min_angle_deg = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (!in_band[t]) continue;
    Mesh one;  // measure_quality on a single triangle keeps one definition
    for (int k = 0; k < 3; ++k) {
      one.x.push_back(m.x[m.triangles[t][k]]);
      one.y.push_back(m.y[m.triangles[t][k]]);
    }
    one.triangles = {{0, 1, 2}};
    const MeshQuality q = measure_quality(one);
    out.min_altitude = std::min(out.min_altitude, q.min_altitude);
    out.min_angle_deg = std::min(out.min_angle_deg, q.min_angle_deg);
  }
}

}  // namespace

EdgeOrientation measure_edge_orientation(const Mesh& m, const std::vector<std::uint8_t>& in_band,
                                         double cx, double cy, int n_bins) {
  if (in_band.size() != m.n_triangles() || n_bins < 2)
    throw std::invalid_argument("measure_edge_orientation: one flag per triangle, >= 2 bins");
  EdgeOrientation out;
  out.histogram.assign(n_bins, 0.0);
  const std::vector<std::pair<int, int>> edges = band_edges(m, in_band);
  out.n_edges = edges.size();
  double total = 0;
  std::complex<double> m2, m6;
  for (const auto& [a, b] : edges) {
    const double dx = m.x[b] - m.x[a], dy = m.y[b] - m.y[a];
    const double len = std::hypot(dx, dy);
    const double rx = (m.x[a] + m.x[b]) / 2 - cx, ry = (m.y[a] + m.y[b]) / 2 - cy;
    // Angle from the radial direction to the edge, modulo pi (edges have no sense).
    double phi = std::atan2(dy, dx) - std::atan2(ry, rx);
    phi = std::fmod(phi, kPi);
    if (phi < 0) phi += kPi;
    const int bin = static_cast<int>(std::floor(phi / kPi * n_bins + 0.5)) % n_bins;
    out.histogram[bin] += len;
    m2 += len * std::polar(1.0, 2 * phi);
    m6 += len * std::polar(1.0, 6 * phi);
    total += len;
  }
  if (total > 0) {
    for (double& h : out.histogram) {
      h /= total;
      out.max_deviation = std::max(out.max_deviation, std::abs(h * n_bins - 1));
    }
    out.directional_bias = std::abs(m2) / total;
    out.hexatic_order = std::abs(m6) / total;
  }
  count_valence(m, in_band, out);
  band_quality(m, in_band, out);
  return out;
}

}  // namespace rockfdem::mesh
