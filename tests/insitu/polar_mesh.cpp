#include "polar_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "rockfdem/insitu/constants.hpp"

namespace rockfdem::insitu::test {

namespace {

int add_vertex(mesh::Mesh& m, double x, double y) {
  m.x.push_back(x);
  m.y.push_back(y);
  return static_cast<int>(m.x.size()) - 1;
}

void add_triangle(mesh::Mesh& m, int a, int b, int c, int zone) {
  m.triangles.push_back({a, b, c});
  m.zone.push_back(zone);
  m.fracture.push_back(zone == mesh::kRock ? 1 : 0);
}

/// Band between an inner ring (n nodes) and an outer ring (n or 2n nodes),
/// both starting at angle 0.
void connect_rings(mesh::Mesh& m, const std::vector<int>& inner, const std::vector<int>& outer,
                   int zone) {
  const int n = static_cast<int>(inner.size());
  if (outer.size() == inner.size()) {
    for (int j = 0; j < n; ++j) {
      const int j1 = (j + 1) % n;
      // Alternate the diagonal so the mesh has no preferred direction.
      if (j % 2 == 0) {
        add_triangle(m, inner[j], outer[j], outer[j1], zone);
        add_triangle(m, inner[j], outer[j1], inner[j1], zone);
      } else {
        add_triangle(m, inner[j], outer[j], inner[j1], zone);
        add_triangle(m, outer[j], outer[j1], inner[j1], zone);
      }
    }
  } else {
    for (int i = 0; i < n; ++i) {
      const int i1 = (i + 1) % n;
      const int o0 = outer[2 * i], o1 = outer[2 * i + 1], o2 = outer[(2 * i + 2) % (2 * n)];
      add_triangle(m, inner[i], o0, o1, zone);
      add_triangle(m, inner[i], o1, inner[i1], zone);
      add_triangle(m, inner[i1], o1, o2, zone);
    }
  }
}

std::vector<int> circle_ring(mesh::Mesh& m, double r, int n) {
  std::vector<int> ring(n);
  for (int j = 0; j < n; ++j) {
    const double t = 2 * kPi * j / n;
    ring[j] = add_vertex(m, r * std::cos(t), r * std::sin(t));
  }
  return ring;
}

void tag_ring(mesh::Mesh& m, const std::vector<int>& ring, int tag) {
  const int n = static_cast<int>(ring.size());
  for (int j = 0; j < n; ++j) m.edges.push_back({ring[j], ring[(j + 1) % n], tag});
}

}  // namespace

mesh::Mesh polar_box_mesh(const PolarMeshSpec& s) {
  if (s.n_theta % 8 != 0 || s.n_theta < 8) throw std::invalid_argument("n_theta % 8 != 0");
  if (!(s.half_width > s.a)) throw std::invalid_argument("box smaller than the opening");
  mesh::Mesh m;
  const int n = s.n_theta;
  const double L = s.half_width;

  // 1. Rock: rings from the circle to the square. Radius parameter rho grows
  //    geometrically by (1 + 2 pi / n) so cells stay roughly square; ring k
  //    sits at the fraction f_k = (rho_k - a) / (rho_N - a) of each ray.
  std::vector<double> rho{s.a};
  const double growth = 1 + 2 * kPi / n;
  while (rho.back() * growth < L) rho.push_back(rho.back() * growth);
  if (rho.size() < 2) rho.push_back(L);
  rho.back() = L;  // the last ring is the square itself
  const int n_rings = static_cast<int>(rho.size());
  std::vector<std::vector<int>> rings(n_rings, std::vector<int>(n));
  for (int k = 0; k < n_rings; ++k) {
    const double f = (rho[k] - s.a) / (L - s.a);
    for (int j = 0; j < n; ++j) {
      const double t = 2 * kPi * j / n;
      const double c = std::cos(t), sn = std::sin(t);
      const double R = L / std::max(std::abs(c), std::abs(sn));  // ray meets the square
      const double r = s.a + (R - s.a) * f;
      double x = r * c, y = r * sn;
      if (k == n_rings - 1) {  // snap onto the box exactly
        if (std::abs(c) >= std::abs(sn)) x = std::copysign(L, c);
        if (std::abs(sn) >= std::abs(c)) y = std::copysign(L, sn);
      }
      rings[k][j] = add_vertex(m, x, y);
    }
  }
  for (int k = 0; k + 1 < n_rings; ++k) connect_rings(m, rings[k], rings[k + 1], mesh::kRock);

  // Outer edges, tagged by side.
  const auto& outer = rings.back();
  for (int j = 0; j < n; ++j) {
    const int a = outer[j], b = outer[(j + 1) % n];
    const double mx = 0.5 * (m.x[a] + m.x[b]), my = 0.5 * (m.y[a] + m.y[b]);
    int tag = mesh::kBottom;
    if (std::abs(mx - L) < 1e-12 * L)
      tag = mesh::kRight;
    else if (std::abs(my - L) < 1e-12 * L)
      tag = mesh::kTop;
    else if (std::abs(mx + L) < 1e-12 * L)
      tag = mesh::kLeft;
    m.edges.push_back({a, b, tag});
  }
  tag_ring(m, rings.front(), mesh::kExcavation);
  if (!s.core) return m;

  // 2. The opening: a lining ring (constant node count), then the core with
  //    cells about the size of the wall's, halving the node count inwards.
  const double h = 2 * kPi * s.a / n;
  std::vector<int> ring = rings.front();
  double r = s.a;
  int count = n;
  if (s.lining_thickness > 0) {
    const int layers = std::max(2, static_cast<int>(std::lround(s.lining_thickness / h)));
    for (int i = 1; i <= layers; ++i) {
      const double ri = s.a - s.lining_thickness * i / layers;
      std::vector<int> inner = circle_ring(m, ri, count);
      connect_rings(m, inner, ring, mesh::kLining);
      ring = std::move(inner);
    }
    r = s.a - s.lining_thickness;
    tag_ring(m, ring, mesh::kLiningInner);
  }
  while (r > 1.5 * h) {
    const double ri = r - h;
    int inner_count = count;
    if (count % 2 == 0 && count >= 8 && 2 * kPi * ri / count < 0.7 * h) inner_count = count / 2;
    std::vector<int> inner = circle_ring(m, ri, inner_count);
    connect_rings(m, inner, ring, mesh::kCore);
    ring = std::move(inner);
    r = ri;
    count = inner_count;
  }
  const int centre = add_vertex(m, 0, 0);
  for (int j = 0; j < count; ++j)
    add_triangle(m, centre, ring[j], ring[(j + 1) % count], mesh::kCore);
  return m;
}

}  // namespace rockfdem::insitu::test
