// Small models shared by the engine tests.
#pragma once

#include <cmath>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/structured_mesh.hpp"

namespace rockfdem::fdem::test {

/// The benchmark rock (structured_mesh.hpp), no damping.
inline Material rock() { return benchmark_rock(); }

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

/// Plane-strain P-wave speed.
inline double p_wave_speed(const Material& m) {
  const double nu = m.poisson;
  return std::sqrt(m.young * (1 - nu) / (m.density * (1 + nu) * (1 - 2 * nu)));
}

}  // namespace rockfdem::fdem::test
