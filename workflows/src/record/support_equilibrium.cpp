#include "record/support_equilibrium.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rockfdem::workflows {
namespace {

template <class Point>
void add_mean(GroundCurve& g, const Point& key_points) {
  if (key_points.empty()) return;
  double u = 0, p = 0;
  for (const auto& [name, k] : key_points) {
    u += k.radial_mm;
    p += k.pressure_Pa;
  }
  g.radial_mm.push_back(u / double(key_points.size()));
  g.pressure_Pa.push_back(p / double(key_points.size()));
}

// The curve's vertices, with the elastic curve's straight continuation to
// p = 0 as one more.
void extend_to_zero(GroundCurve& g) {
  const std::size_t n = g.radial_mm.size();
  const double du = g.radial_mm[n - 1] - g.radial_mm[n - 2];
  const double dp = g.pressure_Pa[n - 2] - g.pressure_Pa[n - 1];
  if (g.pressure_Pa[n - 1] <= 0 || du <= 0 || dp <= 0) return;
  g.radial_mm.push_back(g.radial_mm[n - 1] + g.pressure_Pa[n - 1] * du / dp);
  g.pressure_Pa.push_back(0.0);
  g.extended_to_zero = true;
}

// The support line's pressure at u [mm] (elastic-perfectly plastic).
struct Line {
  double u0, k_per_mm, p_max;
  double at(double u) const { return u <= u0 ? 0.0 : std::min(k_per_mm * (u - u0), p_max); }
  double kink() const { return u0 + p_max / k_per_mm; }
};

double lerp(double a, double b, double s) { return a + (b - a) * s; }

std::string figure(double v, const char* unit) {
  char b[48];
  std::snprintf(b, sizeof b, "%.3g %s", v, unit);
  return b;
}

SupportEquilibrium meet(const SupportLineFigures& s, double u0, const GroundCurve& g) {
  SupportEquilibrium r;
  r.name = s.name;
  const Line line{u0, 1e-3 * s.stiffness_Pa_per_m, s.p_max_Pa};
  if (line.k_per_mm <= 0 || line.p_max <= 0) {
    r.note = "the line has no stiffness or no capacity";
    return r;
  }
  const std::vector<double>& u = g.radial_mm;
  const std::vector<double>& p = g.pressure_Pa;
  for (std::size_t i = 0; i + 1 < u.size(); ++i) {
    // Split the segment where the line bends: both are straight between.
    std::vector<double> cuts = {u[i], u[i + 1]};
    for (const double x : {line.u0, line.kink()})
      if (x > std::min(u[i], u[i + 1]) && x < std::max(u[i], u[i + 1])) cuts.push_back(x);
    std::sort(cuts.begin(), cuts.end());
    if (u[i + 1] < u[i]) std::reverse(cuts.begin(), cuts.end());
    const auto ground = [&](double x) {
      return u[i + 1] == u[i] ? p[i + 1] : lerp(p[i], p[i + 1], (x - u[i]) / (u[i + 1] - u[i]));
    };
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double a = cuts[c], b = cuts[c + 1];
      if (std::max(a, b) < line.u0) continue;
      const double ga = ground(a) - line.at(a), gb = ground(b) - line.at(b);
      if (ga > 0 && gb > 0) continue;
      const double x = ga <= 0 ? a : lerp(a, b, ga / (ga - gb));
      r.found = true;
      r.radial_mm = x;
      r.pressure_Pa = std::max(0.0, line.at(x));
      if (r.pressure_Pa <= 0) {
        r.note = "not loaded: the ground stands before the support is in";
      } else if (x >= line.kink() * (1 - 1e-12)) {
        r.factor_of_safety = 1.0;
        r.note = "on the line's plateau: the support yields at p_max";
      } else {
        r.factor_of_safety = line.p_max / r.pressure_Pa;
        r.note = "elastic: p_max / p";
      }
      return r;
    }
  }
  const double p_end = p.back(), u_end = u.back();
  if (p_end <= 0)
    r.note = "not loaded: the ground's curve reaches p = 0 at " + figure(u_end, "mm") +
             ", before the installation";
  else
    r.note = "none: the ground's curve ends at p = " + figure(p_end / 1e6, "MPa") +
             " above the line (the continuum gives way there)";
  if (p_end <= 0 && u_end <= line.u0) {
    r.found = true;
    r.radial_mm = line.u0;
  }
  return r;
}

}  // namespace

std::optional<GroundCurve> ground_curve(const std::vector<GroundReactionPoint>& implicit,
                                        const std::optional<CounterpartComparison>& counterpart) {
  GroundCurve g;
  if (counterpart && counterpart->model == "mohr_coulomb" &&
      counterpart->ground_reaction.size() >= 2) {
    g.source = "mohr_coulomb";
    for (const ContinuumGroundReactionPoint& x : counterpart->ground_reaction)
      add_mean(g, x.key_points);
  } else {
    g.source = "elastic";
    for (const GroundReactionPoint& x : implicit) add_mean(g, x.key_points);
    if (g.radial_mm.size() >= 2) extend_to_zero(g);
  }
  if (g.radial_mm.size() < 2) return std::nullopt;
  return g;
}

std::vector<SupportEquilibrium> support_equilibria(const ConvergenceConfinementFigures& c,
                                                   const GroundCurve& g) {
  std::vector<SupportEquilibrium> out;
  for (const SupportLineFigures& s : c.support) out.push_back(meet(s, c.install_radial_mm, g));
  return out;
}

std::optional<SupportEquilibria> meet_ground_curve(
    const ConvergenceConfinementFigures& c, const std::vector<GroundReactionPoint>& implicit,
    const std::optional<CounterpartComparison>& counterpart) {
  std::optional<GroundCurve> g = ground_curve(implicit, counterpart);
  if (!g) return std::nullopt;
  std::vector<SupportEquilibrium> lines = support_equilibria(c, *g);
  return SupportEquilibria{std::move(*g), std::move(lines)};
}

}  // namespace rockfdem::workflows
