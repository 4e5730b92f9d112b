// Shared inputs of the in-situ tests: the seed's rock and far field.
#pragma once

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

}  // namespace rockfdem::insitu::test
