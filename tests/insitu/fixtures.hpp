// Shared inputs of the in-situ tests: the seed's rock and far field.
#pragma once

#include <algorithm>
#include <cmath>

#include "polar_mesh.hpp"
#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu::test {

constexpr double kMPa = 1e6;
constexpr double kE = 20e9, kNu = 0.25;  // rock (and core) [Pa], [-]

inline InsituSpec seed_spec(double sH = 18.2 * kMPa, double sV = 11.4 * kMPa) {
  InsituSpec spec;
  spec.far_field.sH = sH;
  spec.far_field.sV = sV;
  spec.materials.rock = ElasticMaterial{kE, kNu};
  spec.materials.core = ElasticMaterial{kE, kNu};
  spec.materials.lining = ElasticMaterial{25e9, 0.2};
  return spec;
}

inline KirschCase kirsch_case(const InsituSpec& spec, double a) {
  KirschCase k;
  k.a = a;
  k.sH = spec.far_field.sH;
  k.sV = spec.far_field.sV;
  k.angle_deg = spec.far_field.angle_deg;
  k.E = spec.materials.rock->E;
  k.nu = spec.materials.rock->nu;
  return k;
}

/// Mean radial displacement of the vertices tagged kExcavation [m].
inline double mean_wall_ur(const mesh::Mesh& m, const InsituField& f) {
  double sum = 0;
  int n = 0;
  for (const auto& e : m.edges)
    if (e.tag == mesh::kExcavation) {
      const int v = e.a;  // each ring vertex starts exactly one edge
      const double r = std::hypot(m.x[v], m.y[v]);
      sum += (f.ux[v] * m.x[v] + f.uy[v] * m.y[v]) / r;
      ++n;
    }
  return sum / n;
}

/// Largest difference of two fields over the largest value of the second
/// (displacement: vector length; stress: any component, szz included).
struct FieldDifference {
  double u = 0, s = 0;
};

inline FieldDifference field_difference(const InsituField& f, const InsituField& ref) {
  double du = 0, u_max = 0, ds = 0, s_max = 0;
  for (std::size_t v = 0; v < ref.ux.size(); ++v) {
    du = std::max(du, std::hypot(f.ux[v] - ref.ux[v], f.uy[v] - ref.uy[v]));
    u_max = std::max(u_max, std::hypot(ref.ux[v], ref.uy[v]));
  }
  for (std::size_t t = 0; t < ref.stress.size(); ++t) {
    const Stress& a = f.stress[t];
    const Stress& b = ref.stress[t];
    ds = std::max({ds, std::abs(a.sxx - b.sxx), std::abs(a.syy - b.syy), std::abs(a.sxy - b.sxy),
                   std::abs(a.szz - b.szz)});
    s_max = std::max({s_max, std::abs(b.sxx), std::abs(b.syy), std::abs(b.sxy), std::abs(b.szz)});
  }
  return {u_max > 0 ? du / u_max : du, ds / s_max};
}

}  // namespace rockfdem::insitu::test
