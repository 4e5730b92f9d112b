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

/// Plane-strain P-wave speed.
inline double p_wave_speed(const Material& m) {
  const double nu = m.poisson;
  return std::sqrt(m.young * (1 - nu) / (m.density * (1 + nu) * (1 - 2 * nu)));
}

}  // namespace rockfdem::fdem::test
