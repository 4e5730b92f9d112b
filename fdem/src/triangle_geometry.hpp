// Geometry of one triangle from its corners' positions.
#pragma once

#include <algorithm>
#include <cmath>

namespace rockfdem::fdem::detail {

/// Smallest altitude of the triangle with corners `nodes[0..2]` (positions
/// `pos[2 n]`, `pos[2 n + 1]`) and area `area`: twice the area over the
/// longest edge. The stability limit's contact term and the viscous damping
/// coefficient read it; the time step depends on these operations' bits
/// (hypot per edge, then 2 area / longest), so keep them in this order.
/// The narrow phase packs its own from the current corners
/// (contact_force.cpp).
inline double smallest_altitude(const double* pos, const int* nodes, double area) {
  double longest = 0;
  for (int k = 0; k < 3; ++k) {
    const int a = nodes[k], b = nodes[(k + 1) % 3];
    longest =
        std::max(longest, std::hypot(pos[2 * b] - pos[2 * a], pos[2 * b + 1] - pos[2 * a + 1]));
  }
  return 2.0 * area / longest;
}

}  // namespace rockfdem::fdem::detail
