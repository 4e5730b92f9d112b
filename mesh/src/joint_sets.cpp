// Joint sets from their statistics: parallel lines at the set's spacing,
// broken into traces and rock bridges by the persistence, with uniform
// scatter. Every draw comes from one splitmix64 stream per set, taken in a
// fixed order, so a seed gives the same traces everywhere.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rockfdem/mesh/constants.hpp"
#include "rockfdem/mesh/joints.hpp"

namespace rockfdem::mesh {
namespace {

/// splitmix64 (Steele, Lea and Flood 2014): a counter-based stream.
class Stream {
 public:
  Stream(std::uint64_t seed, int set) : state_(mix(seed) ^ mix(0x9e3779b97f4a7c15ULL + set)) {}
  /// Uniform in [0, 1) with 53 bits.
  double uniform() { return double(mix(state_ += 0x9e3779b97f4a7c15ULL) >> 11) * 0x1.0p-53; }
  /// Uniform in [-1, 1).
  double symmetric() { return 2.0 * uniform() - 1.0; }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t state_;
};

/// Liang-Barsky: clips p + t d, t in [t0, t1], to the rectangle; false when
/// nothing is left.
bool clip_to_region(const JointRegion& r, double px, double py, double dx, double dy, double& t0,
                    double& t1) {
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {px - r.xmin, r.xmax - px, py - r.ymin, r.ymax - py};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t1 > t0;
}

}  // namespace

std::vector<JointTrace> generate_joint_set(const JointSetSpec& s, const JointRegion& region,
                                           std::uint64_t seed, int set_index) {
  Stream rng(seed, set_index);
  const double cx = 0.5 * (region.xmin + region.xmax), cy = 0.5 * (region.ymin + region.ymax);
  // Lines through the region's circumcircle cover it for any dip.
  const double reach = 0.5 * std::hypot(region.xmax - region.xmin, region.ymax - region.ymin);
  const double mean = s.dip_deg * kPi / 180.0;
  const double nx = std::sin(mean), ny = std::cos(mean);  // normal of the mean dip
  std::vector<JointTrace> out;
  for (double d = -reach - rng.uniform() * s.spacing; d <= reach;
       d += s.spacing * (1.0 + s.spacing_scatter * rng.symmetric())) {
    const double dip = mean + s.dip_scatter_deg * kPi / 180.0 * rng.symmetric();
    const double dx = std::cos(dip), dy = -std::sin(dip);
    const double px = cx + d * nx, py = cy + d * ny;
    // Traces along the line: continuous, or of trace_length every
    // trace_length / persistence (a trace and its bridge).
    const double period = s.trace_length > 0 ? s.trace_length / s.persistence : 0;
    double t = s.trace_length > 0 ? -reach - rng.uniform() * period : -reach;
    while (t < reach) {
      double t0 = t, t1 = reach;
      if (s.trace_length > 0) {
        t1 = t + s.trace_length * (1.0 + s.length_scatter * rng.symmetric());
        t += period;
      } else {
        t = reach;
      }
      if (clip_to_region(region, px, py, dx, dy, t0, t1))
        out.push_back({px + t0 * dx, py + t0 * dy, px + t1 * dx, py + t1 * dy});
    }
  }
  return out;
}

double trace_length(const JointTrace& t) { return std::hypot(t.x1 - t.x0, t.y1 - t.y0); }

}  // namespace rockfdem::mesh
