// The fracturing UCS benchmark model shared by the bench programs: a 50 x
// 100 mm specimen of a hard rock, crack elements on every interior edge,
// rough platens moving towards each other.
#pragma once

#include "rockfdem/fdem/structured_mesh.hpp"

namespace rockfdem::bench {

/// Rock of the benchmark (fdem::benchmark_rock) with 10% of critical
/// viscous damping in the triangles, as FDEM codes run fracture tests.
inline fdem::Material ucs_rock() {
  fdem::Material m = fdem::benchmark_rock();
  m.damping_ratio = 0.1;
  return m;
}

}  // namespace rockfdem::bench
