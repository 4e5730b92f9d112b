// Small models shared by the engine tests.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

namespace rockfdem::fdem::test {

/// The engine holds its model constants (masses, stiffness factors,
/// initial stresses, crack offsets) in single precision: each is the given
/// value to within this fraction of itself (half a float's spacing).
constexpr double kStored = 0x1p-24;

/// The benchmark rock (structured_mesh.hpp), no damping.
inline Material rock() { return benchmark_rock(); }

/// Bolt steel of the crack-law tests: E = 200 GPa, sigma_y = 400 MPa,
/// sigma_u = 600 MPa, tau_y = 200 MPa, GfI = 20 kJ/m^2, GfII = 10 kJ/m^2.
inline Material bolt_steel() {
  Material m;
  m.young = 200e9;
  m.crack_law = CrackLaw::kBoltSteel;
  m.yield_strength = 400e6;
  m.ultimate_strength = 600e6;
  m.shear_yield_strength = 200e6;
  m.gf_I = 2e4;
  m.gf_II = 1e4;
  return m;
}

/// Total energy at x(n) from the public state, taking step n here: strain
/// and crack energy at x(n) plus the kinetic energy of the mean of the
/// half-step velocities around it.
inline double energy_around_step(Engine& e) {
  const double potential = e.strain_energy() + e.crack_energy();
  const std::vector<double> before = e.velocities();
  e.step();
  double kinetic = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n)
    for (int k = 0; k < 2; ++k) {
      const double v = 0.5 * (before[2 * n + k] + e.velocities()[2 * n + k]);
      kinetic += 0.5 * e.node_mass()[n] * v * v;
    }
  return potential + kinetic;
}

/// Contact pair of the contact tests: target T = (0,0), (L,0), (L/2, H) with
/// L = 0.1, H = 0.08; contactor C below it, its top edge from x1 = 0.03 to
/// x2 = 0.07 at y = top (top > 0: inside T), apex depth Hc = 0.05 below.
struct PressedTriangles {
  static constexpr double L = 0.1, H = 0.08, x1 = 0.03, x2 = 0.07, hc = 0.05;
  static ModelInput model(double top) {
    ModelInput in;
    in.x = {0, L, L / 2, x1, (x1 + x2) / 2, x2};
    in.y = {0, 0, H, top, top - hc, top};
    in.triangles = {{0, 1, 2}, {3, 4, 5}};
    in.material = {0, 0};
    in.materials = {rock()};
    return in;
  }
};

/// Two triangles sharing the edge A(0,0)-B(h,0), one crack element on it:
/// triangle 0 = (A, C, B) below with C(h/2, -h), triangle 1 = (A, B, D) above
/// with D(h/2, h).
inline ModelInput two_triangles(double h, const Material& m) {
  ModelInput in;
  in.x = {0, h, h / 2, h / 2};
  in.y = {0, 0, -h, h};
  in.triangles = {{0, 2, 1}, {0, 1, 3}};
  in.material = {0, 0};
  in.fracture = {1, 1};
  in.materials = {m};
  return in;
}

/// A bar along x with rollers on its long sides (1D strain, so a front
/// travels at the plane-strain P-wave speed); height length / 50, 4 cells.
inline ModelInput bar(double length, int nx, bool fracture) {
  RectangleSpec spec;
  spec.width = length;
  spec.height = length / 50;
  spec.nx = nx;
  spec.ny = 4;
  spec.fracture = fracture;
  ModelInput in = structured_rectangle(spec, rock());
  BoundaryCondition top, bottom;
  top.tag = kTagTop;
  bottom.tag = kTagBottom;
  top.y = bottom.y = Constraint::kFixed;
  in.boundary_conditions = {top, bottom};
  return in;
}

/// Appends `b` to `a` as a separate body (vertices not shared), tags + offset.
inline void append_body(ModelInput& a, const ModelInput& b, int tag_offset) {
  const int nv = static_cast<int>(a.x.size());
  a.x.insert(a.x.end(), b.x.begin(), b.x.end());
  a.y.insert(a.y.end(), b.y.begin(), b.y.end());
  for (auto t : b.triangles) a.triangles.push_back({t[0] + nv, t[1] + nv, t[2] + nv});
  a.material.insert(a.material.end(), b.material.begin(), b.material.end());
  a.fracture.insert(a.fracture.end(), b.fracture.begin(), b.fracture.end());
  for (auto e : b.edges) a.edges.push_back({e.a + nv, e.b + nv, e.tag + tag_offset});
}

/// Lower block 0.2 x 0.05 (bottom fixed), upper block 0.1 x 0.05 above it
/// with a gap; tags of the upper block are offset by 10.
inline ModelInput two_blocks(double gap, const Material& m, int nx_upper = 4) {
  RectangleSpec lower;
  lower.width = 0.2;
  lower.height = 0.05;
  lower.nx = 2 * nx_upper;
  lower.ny = 2;
  lower.fracture = false;
  ModelInput in = structured_rectangle(lower, m);
  RectangleSpec upper = lower;
  upper.width = 0.1;
  upper.nx = nx_upper;
  upper.x0 = 0.05;
  upper.y0 = 0.05 + gap;
  append_body(in, structured_rectangle(upper, m), 10);
  BoundaryCondition base;
  base.tag = kTagBottom;
  base.x = base.y = Constraint::kFixed;
  in.boundary_conditions = {base};
  return in;
}

/// Tractions sigma n, sigma = (sxx, syy, sxy), on the four sides of a
/// structured rectangle.
inline std::vector<BoundaryCondition> side_tractions(const std::array<double, 3>& s) {
  std::vector<BoundaryCondition> bcs(4);
  bcs[0].tag = kTagBottom;  // n = (0, -1)
  bcs[0].tx = -s[2];
  bcs[0].ty = -s[1];
  bcs[1].tag = kTagRight;  // n = (1, 0)
  bcs[1].tx = s[0];
  bcs[1].ty = s[2];
  bcs[2].tag = kTagTop;  // n = (0, 1)
  bcs[2].tx = s[2];
  bcs[2].ty = s[1];
  bcs[3].tag = kTagLeft;  // n = (-1, 0)
  bcs[3].tx = -s[0];
  bcs[3].ty = -s[2];
  return bcs;
}

/// Plane-strain P-wave speed.
inline double p_wave_speed(const Material& m) {
  const double nu = m.poisson;
  return std::sqrt(m.young * (1 - nu) / (m.density * (1 + nu) * (1 - 2 * nu)));
}

}  // namespace rockfdem::fdem::test
