// Section forces along a bolt (bolt_sections.hpp).
#include "rockfdem/fdem/bolt_sections.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "rockfdem/fdem/constants.hpp"

namespace rockfdem::fdem {
namespace {

/// The bolt's frame: head A, unit axis t, normal n (t turned 90 deg ccw).
struct Axis {
  double ax, ay, tx, ty, length;
  double s(double x, double y) const { return (x - ax) * tx + (y - ay) * ty; }
  double n(double x, double y) const { return -(x - ax) * ty + (y - ay) * tx; }
};

Axis axis_of(const Bolt& bolt) {
  const double len = std::hypot(bolt.b[0] - bolt.a[0], bolt.b[1] - bolt.a[1]);
  return {bolt.a[0], bolt.a[1], (bolt.b[0] - bolt.a[0]) / len, (bolt.b[1] - bolt.a[1]) / len, len};
}

/// A convex polygon in (s, n), at most 5 vertices after two half-planes.
struct Polygon {
  std::array<std::array<double, 2>, 8> p{};
  int size = 0;
};

/// Keeps the part of `in` with sign * (s - cut) <= 0 (Sutherland-Hodgman).
Polygon clip(const Polygon& in, double cut, double sign) {
  Polygon out;
  for (int i = 0; i < in.size; ++i) {
    const auto& a = in.p[i];
    const auto& b = in.p[(i + 1) % in.size];
    const double da = sign * (a[0] - cut), db = sign * (b[0] - cut);
    if (da <= 0) out.p[out.size++] = a;
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      const double w = da / (da - db);
      out.p[out.size++] = {cut, a[1] + w * (b[1] - a[1])};
    }
  }
  return out;
}

/// Area and area-weighted centroid sums (shoelace) of a polygon.
std::array<double, 3> area_moments(const Polygon& poly) {
  double a = 0, ms = 0, mn = 0;
  for (int i = 0; i < poly.size; ++i) {
    const auto& p = poly.p[i];
    const auto& q = poly.p[(i + 1) % poly.size];
    const double c = p[0] * q[1] - q[0] * p[1];
    a += c / 2;
    ms += (p[0] + q[0]) * c / 6;
    mn += (p[1] + q[1]) * c / 6;
  }
  if (a < 0) return {-a, -ms, -mn};  // clockwise corners
  return {a, ms, mn};
}

/// Triangle t's corners in the bolt frame, current or mesh (reference) shape.
Polygon triangle_in_frame(const Engine& e, int t, const Axis& ax, bool reference) {
  Polygon poly;
  const auto& pos = e.positions();
  for (int node : e.triangle_nodes(t)) {
    double x = pos[2 * node], y = pos[2 * node + 1];
    if (reference) {
      const auto d = e.displacement(node);
      x -= d[0];
      y -= d[1];
    }
    poly.p[poly.size++] = {ax.s(x, y), ax.n(x, y)};
  }
  return poly;
}

/// sigma_aa of owned triangle i of bolt b, minus its stress at installation.
double axial_stress(const Engine& e, const BoltPlan& plan, int b, std::size_t i, const Axis& ax) {
  const auto now = e.triangle_stress(plan.owned[b][i]);
  const auto& at_install = plan.installed_stress[b][i];
  const double sxx = now[0] - at_install[0], syy = now[1] - at_install[1];
  const double sxy = now[2] - at_install[2];
  return ax.tx * ax.tx * sxx + ax.ty * ax.ty * syy + 2 * ax.tx * ax.ty * sxy;
}

/// Worst bolt-steel crack state per slab (crack midpoints, current).
void mark_states(const Engine& e, const BoltPlan& plan, int b, const Axis& ax, double delta,
                 std::vector<BoltStation>& out) {
  const auto& pos = e.positions();
  const int n = int(out.size());
  for (int c : bolt_cracks(e, plan, b).steel) {
    const CrackState cs = e.crack_state(c);
    const int state = cs == CrackState::kBroken ? 2 : cs == CrackState::kYielding ? 1 : 0;
    if (state == 0) continue;
    double x = 0, y = 0;
    for (int node : e.crack_nodes(c)) {
      x += pos[2 * node] / 4;
      y += pos[2 * node + 1] / 4;
    }
    const int i = std::clamp(int(std::floor(ax.s(x, y) / delta)), 0, n - 1);
    out[i].state = std::max(out[i].state, state);
  }
}

}  // namespace

int bolt_station_count(const Engine& engine, const BoltPlan& plan, int b) {
  const Axis ax = axis_of(plan.specs[b].bolt);
  double extent = 0;
  for (int t : plan.owned[b]) {
    const Polygon p = triangle_in_frame(engine, t, ax, true);
    const double lo = std::min({p.p[0][0], p.p[1][0], p.p[2][0]});
    const double hi = std::max({p.p[0][0], p.p[1][0], p.p[2][0]});
    extent += hi - lo;
  }
  if (plan.owned[b].empty() || !(extent > 0)) return 2;
  return std::max(2, int(std::lround(ax.length / (extent / double(plan.owned[b].size())))));
}

std::vector<BoltStation> bolt_sections(const Engine& engine, const BoltPlan& plan, int b) {
  const Axis ax = axis_of(plan.specs[b].bolt);
  const int n = bolt_station_count(engine, plan, b);
  const double delta = ax.length / n, d = plan.specs[b].bolt.diameter;
  const double s_b = plan.specs[b].row_spacing;
  std::vector<BoltStation> out(static_cast<std::size_t>(n));
  std::vector<std::array<double, 4>> sums(static_cast<std::size_t>(n),
                                          {0, 0, 0, 0});  // force, area, ms, mn
  for (std::size_t i = 0; i < plan.owned[b].size(); ++i) {
    const Polygon tri = triangle_in_frame(engine, plan.owned[b][i], ax, false);
    const double sigma = axial_stress(engine, plan, b, i, ax);
    for (int k = 0; k < n; ++k) {
      const Polygon part = clip(clip(tri, k * delta, -1), (k + 1) * delta, 1);
      if (part.size < 3) continue;
      const auto m = area_moments(part);
      sums[k][0] += sigma * m[0];
      sums[k][1] += m[0];
      sums[k][2] += m[1];
      sums[k][3] += m[2];
    }
  }
  for (int k = 0; k < n; ++k) {
    BoltStation& st = out[k];
    st.station = (k + 0.5) * delta;
    const double sc = sums[k][1] != 0 ? sums[k][2] / sums[k][1] : st.station;
    const double nc = sums[k][1] != 0 ? sums[k][3] / sums[k][1] : 0.0;
    st.x = ax.ax + sc * ax.tx - nc * ax.ty;
    st.y = ax.ay + sc * ax.ty + nc * ax.tx;
    st.force_per_metre = sums[k][0] / delta;
    st.steel_stress = st.force_per_metre * s_b / d;
    st.bar_force = st.steel_stress * kPi * d * d / 4;
  }
  mark_states(engine, plan, b, ax, delta, out);
  return out;
}

}  // namespace rockfdem::fdem
