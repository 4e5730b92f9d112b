#include "outputs/lining_extremes.hpp"

#include <cmath>

namespace rockfdem::workflows {
namespace {

// The extremes of the segments i with keep(i); the first segment kept wins
// a tie.
template <class Keep>
ForceExtremes extremes_of(const std::vector<SectionForces>& f, Keep keep) {
  ForceExtremes e;
  bool first = true;
  const auto better = [&](SegmentExtreme& x, double v, std::size_t i) {
    if (first || v > x.value) x = {v, i};
  };
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (!keep(i)) continue;
    better(e.max_thrust, f[i].thrust, i);
    better(e.min_thrust, -f[i].thrust, i);
    better(e.max_abs_moment, std::abs(f[i].moment), i);
    better(e.max_abs_shear, std::abs(f[i].shear), i);
    first = false;
  }
  e.min_thrust.value = -e.min_thrust.value;
  return e;
}

}  // namespace

LiningExtremes lining_extremes(const LiningGeometry& g, const std::vector<SectionForces>& f) {
  const auto corner = [&](std::size_t i) { return i < g.segments.size() && g.segments[i].corner; };
  std::size_t n_corners = 0;
  for (std::size_t i = 0; i < f.size(); ++i) n_corners += corner(i);
  LiningExtremes x;
  if (n_corners == 0 || n_corners == f.size()) {
    x.sections = extremes_of(f, [](std::size_t) { return true; });
    return x;
  }
  x.sections = extremes_of(f, [&](std::size_t i) { return !corner(i); });
  x.corners = extremes_of(f, corner);
  const ForceExtremes &s = x.sections, &c = *x.corners;
  x.corners_exceed = c.max_thrust.value > s.max_thrust.value ||
                     c.max_abs_moment.value > s.max_abs_moment.value ||
                     (c.min_thrust.value < 0 && c.min_thrust.value < s.min_thrust.value);
  return x;
}

}  // namespace rockfdem::workflows
