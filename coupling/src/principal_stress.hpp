// In-plane principal stresses of (sxx, syy, sxy): (s1, s2) with s1 >= s2
// (tension positive: s1 is the most tensile).
#pragma once

#include <array>
#include <cmath>

namespace rockfdem::coupling {

inline std::array<double, 2> principal_stresses(double sxx, double syy, double sxy) {
  const double mean = 0.5 * (sxx + syy);
  const double radius = std::hypot(0.5 * (sxx - syy), sxy);
  return {mean + radius, mean - radius};
}

}  // namespace rockfdem::coupling
