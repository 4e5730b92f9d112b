#include "outputs/support_lines.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {

SupportLine shotcrete_ring_line(double sigma_c, double young, double poisson, double radius,
                                double thickness) {
  const double r2 = radius * radius, ri2 = (radius - thickness) * (radius - thickness);
  SupportLine s{"shotcrete", 0, 0, {}};
  s.p_max = 0.5 * sigma_c * (1 - ri2 / r2);
  s.stiffness = young * (r2 - ri2) / ((1 + poisson) * ((1 - 2 * poisson) * r2 + ri2) * radius);
  return s;
}

SupportLine ring_line(const std::vector<RingPart>& parts, double radius) {
  SupportLine s{parts.size() == 1 ? "shotcrete" : "lining ring", INFINITY, 0, {}};
  double compliance = 0, shares = 0;
  std::size_t weakest = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const RingPart& p = parts[i];
    const SupportLine one = shotcrete_ring_line(p.sigma_c, p.young, p.poisson, radius, p.thickness);
    compliance += p.share / one.stiffness;
    shares += p.share;
    if (one.p_max < s.p_max) s.p_max = one.p_max, weakest = i;
  }
  s.stiffness = shares / compliance;  // the shares as given, made to sum to 1
  if (parts.size() < 2) return s;
  char text[200];
  std::snprintf(text, sizeof text,
                "p_max of the %s (%.3g m, %.3g MPa), the weakest of the parts, which carry one "
                "thrust p R; K of the parts in series by length (",
                parts[weakest].name.c_str(), parts[weakest].thickness,
                parts[weakest].sigma_c / 1e6);
  s.note = text;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::snprintf(text, sizeof text, "%s%s %.0f%%", i ? ", " : "", parts[i].name.c_str(),
                  100 * parts[i].share);
    s.note += text;
  }
  s.note += ")";
  return s;
}

SupportLine bolt_line(double failure_load, double spacing_round, double spacing_along,
                      double length, double diameter, double young, double q) {
  const double area = spacing_round * spacing_along;
  SupportLine s{"bolts", 0, 0, {}};
  s.p_max = failure_load / area;
  s.stiffness = 1 / (area * (4 * length / (M_PI * diameter * diameter * young) + q));
  return s;
}

SupportLine combined_line(const std::vector<SupportLine>& parts) {
  SupportLine s{"combined", 0, 0, {}};
  double u_max = INFINITY;
  for (const SupportLine& p : parts) {
    s.stiffness += p.stiffness;
    u_max = std::min(u_max, p.max_displacement());
  }
  s.p_max = s.stiffness * u_max;
  return s;
}

double line_pressure(const SupportLine& s, double du) {
  return du <= 0 ? 0.0 : std::min(s.p_max, s.stiffness * du);
}

EquivalentOpening equivalent_opening(const mesh::Mesh& m) {
  double area = 0, lining = 0, sx = 0, sy = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kCore && m.zone[t] != mesh::kLining) continue;
    const double a = std::abs(mesh::signed_area(m, t));
    const auto& v = m.triangles[t];
    area += a;
    if (m.zone[t] == mesh::kLining) lining += a;
    sx += a * (m.x[v[0]] + m.x[v[1]] + m.x[v[2]]) / 3;
    sy += a * (m.y[v[0]] + m.y[v[1]] + m.y[v[2]]) / 3;
  }
  EquivalentOpening o;
  if (!(area > 0)) return o;
  o.radius = std::sqrt(area / M_PI);
  o.lining_thickness = o.radius - std::sqrt((area - lining) / M_PI);
  o.cx = sx / area;
  o.cy = sy / area;
  return o;
}

namespace {

/// The bolts of one kind (cables or not) as a line; none without bolts.
std::vector<SupportLine> bolt_kind_line(const Scene& scene, const EquivalentOpening& o,
                                        bool cables) {
  const BoltSettings& b = scene.bolts;
  const SteelSettings& steel = cables ? b.cable : b.bolt;
  std::vector<double> angles;
  double length = 0;
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    if (bool(b.is_cable[i]) != cables) continue;
    const auto& s = b.segments[i];
    angles.push_back(std::atan2(s[1] - o.cy, s[0] - o.cx));
    length += std::hypot(s[2] - s[0], s[3] - s[1]);
  }
  if (angles.empty()) return {};
  length /= double(angles.size());
  std::sort(angles.begin(), angles.end());
  // Neighbours round the opening; one bolt alone stands for the whole round.
  std::vector<double> gaps;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * M_PI;
    gaps.push_back(next - angles[i]);
  }
  // The largest gap is where a pattern over the arch is open; for a pattern
  // all round, leaving one gap out hardly moves the median.
  if (gaps.size() > 1) gaps.erase(std::max_element(gaps.begin(), gaps.end()));
  std::nth_element(gaps.begin(), gaps.begin() + long(gaps.size() / 2), gaps.end());
  const double gap = gaps[gaps.size() / 2];
  const double d = steel.diameter;
  SupportLine s = bolt_line(steel.ultimate_strength * M_PI * d * d / 4, o.radius * gap,
                            steel.row_spacing, length, d, steel.young, 0.0);
  s.name = cables ? "cables" : "bolts";
  return {s};
}

}  // namespace

std::vector<RingPart> ring_parts(const Scene& scene, const mesh::Mesh& m,
                                 const EquivalentOpening& o) {
  const auto lining = scene.materials.find(mesh::kLining);
  if (!(o.lining_thickness > 0) || lining == scene.materials.end() ||
      !(lining->second.compressive_strength > 0))
    return {};
  const MaterialSpec& arch = lining->second;
  const mesh::TunnelSpec& t = scene.mesh.tunnel;
  const double top = scene.mesh.kind == mesh::ModelKind::kTunnel && t.lining_thickness > 0
                         ? mesh::invert_part_top(t)
                         : -INFINITY;
  // The lining triangles' areas above and below the floor part's top.
  double area[2] = {0, 0};
  for (std::size_t i = 0; i < m.n_triangles() && std::isfinite(top); ++i) {
    if (m.zone[i] != mesh::kLining) continue;
    const auto& v = m.triangles[i];
    const double yc =
        (m.y[std::size_t(v[0])] + m.y[std::size_t(v[1])] + m.y[std::size_t(v[2])]) / 3;
    area[yc < top] += std::abs(mesh::signed_area(m, i));
  }
  const auto part = [](std::string name, double share, double thickness, const MaterialSpec& s) {
    return RingPart{std::move(name), share, thickness, s.compressive_strength, s.young, s.poisson};
  };
  if (!(area[0] > 0) || !(area[1] > 0)) return {part("ring", 1, o.lining_thickness, arch)};
  const double t_floor = t.invert_thickness > 0 ? t.invert_thickness : t.lining_thickness;
  const double length[2] = {area[0] / t.lining_thickness, area[1] / t_floor};
  const double total = length[0] + length[1];
  return {part("arch and walls", length[0] / total, t.lining_thickness, arch),
          part("invert", length[1] / total, t_floor, scene.invert ? *scene.invert : arch)};
}

std::vector<SupportLine> scene_support_lines(const Scene& scene, const EquivalentOpening& o,
                                             std::vector<RingPart> ring) {
  std::vector<SupportLine> lines;
  const auto lining = scene.materials.find(mesh::kLining);
  if (ring.empty() && o.lining_thickness > 0 && lining != scene.materials.end() &&
      lining->second.compressive_strength > 0)
    ring.push_back({"ring", 1, o.lining_thickness, lining->second.compressive_strength,
                    lining->second.young, lining->second.poisson});
  if (!ring.empty()) lines.push_back(ring_line(ring, o.radius));
  for (const bool cables : {false, true})
    for (const SupportLine& s : bolt_kind_line(scene, o, cables)) lines.push_back(s);
  if (lines.size() > 1) lines.push_back(combined_line(lines));
  return lines;
}

}  // namespace rockfdem::workflows
