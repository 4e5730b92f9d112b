// Capacity diagrams of lining sections (see lining_sections.hpp and
// docs/support.md, "Section types").
#include "outputs/lining_sections.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockfdem::workflows {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Points per branch of the reinforced diagram's sweep: the boundary between
// them is a chord, within 0.1% of the curve's moment (4.6e-4 at the balance
// point of the tests' section, where the far bars' yield kinks the curve).
constexpr int kSweepPoints = 400;

double cross(const MNPoint& a, const MNPoint& b) { return a[0] * b[1] - a[1] * b[0]; }
MNPoint minus(const MNPoint& a, const MNPoint& b) { return {a[0] - b[0], a[1] - b[1]}; }

// EN 1992-1-1 Table 3.1 and 3.1.7(3) for fck [Pa]: the rectangular block's
// depth factor lambda and strength factor eta, the ultimate strain eps_cu3
// and the strain eps_c3 of a section wholly in compression (the pivot).
struct StressBlock {
  double lambda = 0.8, eta = 1.0, eps_cu3 = 3.5e-3, eps_c3 = 1.75e-3;
};

StressBlock stress_block(double fck) {
  const double f = std::min(fck / 1e6, 90.0);  // MPa; the code stops at C90/105
  StressBlock b;
  if (f <= 50) return b;
  b.lambda = 0.8 - (f - 50) / 400;
  b.eta = 1.0 - (f - 50) / 200;
  b.eps_cu3 = (2.6 + 35 * std::pow((90 - f) / 100, 4)) * 1e-3;
  b.eps_c3 = (1.75 + 0.55 * (f - 50) / 40) * 1e-3;
  return b;
}

// N and M about the mid-line of the reinforced section of thickness h for a
// linear strain profile, eps_top at the compressed face (taken as the
// extrados: M > 0) and eps_bottom at the other, compression positive.
MNPoint reinforced_resultant(const LiningSection& s, const StressBlock& b, double h, double eps_top,
                             double eps_bottom) {
  double n = 0, m = 0;
  if (eps_top > 0) {
    // Neutral axis depth x; a uniform strain has none (the whole section).
    const double x = eps_bottom < eps_top ? h * eps_top / (eps_top - eps_bottom) : kInf;
    const double depth = std::min(b.lambda * x, h);
    const double c = b.eta * s.concrete.compressive * depth;
    n += c;
    m += c * (h / 2 - depth / 2);
  }
  for (const double z : {s.bar_cover, h - s.bar_cover}) {  // depth of each layer
    const double eps = eps_top + (eps_bottom - eps_top) * z / h;
    const double f = s.bar_area * std::clamp(s.steel_young * eps, -s.steel_yield, s.steel_yield);
    n += f;
    m += f * (h / 2 - z);
  }
  return {m, n};
}

// The elastic limit of a rectangle of area a and modulus w = I / y_max per
// metre: compression c and tension t of its extreme fibres, the quadrilateral
// of the plain section (lining_forces.cpp's capacity_envelope, general in w).
std::vector<MNPoint> elastic_diagram(double a, double w, double c, double t) {
  return {{0, -t * a},
          {(c + t) * w / 2, (c - t) * a / 2},
          {0, c * a},
          {-(c + t) * w / 2, (c - t) * a / 2},
          {0, -t * a}};
}

// Counter-clockwise, open (the closing point dropped).
std::vector<MNPoint> open_ccw(std::vector<MNPoint> p) {
  if (p.size() > 1 && p.front() == p.back()) p.pop_back();
  double area = 0;
  for (std::size_t i = 0; i < p.size(); ++i) area += cross(p[i], p[(i + 1) % p.size()]);
  if (area < 0) std::reverse(p.begin(), p.end());
  return p;
}

// Sutherland-Hodgman: the part of polygon `subject` inside the convex
// polygon `clip`, both open and counter-clockwise.
std::vector<MNPoint> clip_convex(std::vector<MNPoint> subject, const std::vector<MNPoint>& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const MNPoint a = clip[e], d = minus(clip[(e + 1) % clip.size()], a);
    const auto side = [&](const MNPoint& p) { return cross(d, minus(p, a)); };
    std::vector<MNPoint> out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const MNPoint p = subject[i], q = subject[(i + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) {
        const double u = sp / (sp - sq);
        out.push_back({p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1])});
      }
    }
    subject = std::move(out);
  }
  return subject;
}

// A diagram in the part's own forces seen in the composite's: the part
// carries `share` of N and `moment_share` of M.
std::vector<MNPoint> in_composite_forces(std::vector<MNPoint> p, double share,
                                         double moment_share) {
  for (MNPoint& q : p) q = {q[0] / moment_share, q[1] / share};
  return p;
}

// The sets' diagram per metre: area A / s, modulus I / (s d / 2), +-fy.
std::vector<MNPoint> steel_set_diagram(const LiningSection& s) {
  const double a = s.set_area / s.set_spacing;
  const double w = s.set_inertia / (s.set_spacing * s.set_depth / 2);
  return elastic_diagram(a, w, s.steel_yield, s.steel_yield);
}

double steel_set_safety_factor(const SectionForces& f, double t, const LiningSection& s) {
  const CompositeShares k = steel_set_shares(s, t);
  const SectionForces shotcrete{f.thrust * (1 - k.thrust), f.moment * (1 - k.moment), 0};
  const SectionForces sets{f.thrust * k.thrust, f.moment * k.moment, 0};
  const double a = s.set_area / s.set_spacing, i = s.set_inertia / s.set_spacing;
  // The sets yield at either extreme fibre, in tension as in compression.
  const double stress = std::abs(sets.thrust) / a + std::abs(sets.moment) * s.set_depth / (2 * i);
  const double steel = stress > 0 ? s.steel_yield / stress : kInf;
  return std::min(safety_factor(shotcrete, t, s.concrete), steel);
}

}  // namespace

std::string section_name(SectionKind kind) {
  switch (kind) {
    case SectionKind::kPlain:
      return "plain";
    case SectionKind::kReinforced:
      return "reinforced";
    case SectionKind::kSteelSets:
      return "steel_sets";
  }
  return "?";
}

LiningSection lining_section(const MaterialSpec& m) {
  const LiningSectionSpec& g = m.section;
  LiningSection s;
  s.kind = g.kind == "reinforced"   ? SectionKind::kReinforced
           : g.kind == "steel_sets" ? SectionKind::kSteelSets
                                    : SectionKind::kPlain;
  s.concrete = {m.compressive_strength, m.tensile_strength};
  s.concrete_young = m.young;
  s.steel_young = g.steel_young;
  s.steel_yield = g.steel_yield_strength;
  s.bar_area = g.bar_area;
  s.bar_cover = g.bar_cover;
  s.set_area = g.set_area;
  s.set_inertia = g.set_inertia;
  s.set_depth = g.set_depth;
  s.set_spacing = g.set_spacing;
  return s;
}

std::vector<MNPoint> reinforced_diagram(const LiningSection& s, double h) {
  const StressBlock b = stress_block(s.concrete.compressive);
  // Pure tension: the limit of a neutral axis at the compressed face, both
  // layers yielding, the concrete cracked.
  std::vector<MNPoint> half{{0, -2 * s.bar_area * s.steel_yield}};
  // Pivot B: eps_cu3 at the compressed face, the neutral axis x in (0, h].
  for (int k = 1; k <= kSweepPoints; ++k) {
    const double x = h * k / kSweepPoints;
    half.push_back(reinforced_resultant(s, b, h, b.eps_cu3, b.eps_cu3 * (1 - h / x)));
  }
  // Pivot C: the section wholly compressed, eps_c3 held at the depth
  // (1 - eps_c3 / eps_cu3) h, up to the uniform eps_c3 of pure compression.
  for (int k = 1; k <= kSweepPoints; ++k) {
    const double u = double(k) / kSweepPoints;
    half.push_back(
        reinforced_resultant(s, b, h, b.eps_cu3 + u * (b.eps_c3 - b.eps_cu3), u * b.eps_c3));
  }
  half.back()[0] = 0;  // uniform strain: no moment (not a rounding's worth)
  // The section is symmetric: the M < 0 side mirrors it, back down.
  std::vector<MNPoint> out = half;
  for (std::size_t k = half.size() - 1; k-- > 1;) out.push_back({-half[k][0], half[k][1]});
  out.push_back(half.front());
  return out;
}

CompositeShares steel_set_shares(const LiningSection& s, double t) {
  const double ea_steel = s.steel_young * s.set_area / s.set_spacing;
  const double ei_steel = s.steel_young * s.set_inertia / s.set_spacing;
  const double ea_shot = s.concrete_young * t, ei_shot = s.concrete_young * t * t * t / 12;
  return {ea_steel / (ea_steel + ea_shot), ei_steel / (ei_steel + ei_shot)};
}

std::vector<MNPoint> capacity_diagram(const LiningSection& s, double t) {
  switch (s.kind) {
    case SectionKind::kPlain:
      return capacity_envelope(t, s.concrete, 1.0);
    case SectionKind::kReinforced:
      return reinforced_diagram(s, t);
    case SectionKind::kSteelSets:
      break;
  }
  const CompositeShares k = steel_set_shares(s, t);
  const auto shotcrete = open_ccw(
      in_composite_forces(elastic_diagram(t, t * t / 6, s.concrete.compressive, s.concrete.tensile),
                          1 - k.thrust, 1 - k.moment));
  const auto sets = open_ccw(in_composite_forces(steel_set_diagram(s), k.thrust, k.moment));
  std::vector<MNPoint> out = clip_convex(shotcrete, sets);
  if (!out.empty()) out.push_back(out.front());
  return out;
}

double radial_safety_factor(const std::vector<MNPoint>& diagram, const SectionForces& f) {
  const MNPoint p{f.moment, f.thrust};
  double fs = kInf;
  if (p[0] == 0 && p[1] == 0) return fs;
  // The ray s p meets the edge a + u (b - a): s = (a x d) / (p x d),
  // u = (a x p) / (p x d), d = b - a.
  for (std::size_t i = 0; i + 1 < diagram.size(); ++i) {
    const MNPoint a = diagram[i], d = minus(diagram[i + 1], a);
    const double pd = cross(p, d);
    if (pd == 0) continue;
    const double s = cross(a, d) / pd, u = cross(a, p) / pd;
    if (s > 0 && u >= 0 && u <= 1) fs = std::min(fs, s);
  }
  return fs;
}

double section_safety_factor(const SectionForces& f, double t, const LiningSection& s) {
  switch (s.kind) {
    case SectionKind::kPlain:
      return safety_factor(f, t, s.concrete);
    case SectionKind::kReinforced:
      return radial_safety_factor(reinforced_diagram(s, t), f);
    case SectionKind::kSteelSets:
      break;
  }
  return steel_set_safety_factor(f, t, s);
}

}  // namespace rockfdem::workflows
