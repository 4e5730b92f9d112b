// Measures of a Mohr-Coulomb continuum's field shared by its tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "rockfdem/insitu/constants.hpp"
#include "rockfdem/insitu/plastic.hpp"

namespace rockfdem::insitu::test {

/// Mean over rays of the yielded-to-elastic transition radius [m].
inline double plastic_radius_along_rays(const mesh::Mesh& m, const PlasticField& f, int n_rays) {
  const double window = kPi / n_rays;
  double sum = 0;
  for (int j = 0; j < n_rays; ++j) {
    const double theta = 2 * kPi * j / n_rays;
    double r_yield = 0;
    std::vector<std::pair<double, bool>> cells;  // centroid radius, yielded
    for (std::size_t t = 0; t < m.n_triangles(); ++t) {
      if (!f.active[t]) continue;
      const auto& tri = m.triangles[t];
      const double x = (m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3;
      const double y = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
      const double d = std::remainder(std::atan2(y, x) - theta, 2 * kPi);
      if (std::abs(d) > window) continue;
      cells.emplace_back(std::hypot(x, y), f.yielded[t] != 0);
      if (f.yielded[t]) r_yield = std::max(r_yield, std::hypot(x, y));
    }
    double r_next = 1e300;
    for (const auto& [r, yielded] : cells)
      if (!yielded && r > r_yield) r_next = std::min(r_next, r);
    sum += 0.5 * (r_yield + r_next);
  }
  return sum / n_rays;
}

}  // namespace rockfdem::insitu::test
