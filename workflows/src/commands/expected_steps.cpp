#include "commands/expected_steps.hpp"

#include <algorithm>
#include <cmath>

#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {

double local_size(const mesh::MeshSpec& m, double d) {
  const double grading = m.size.grading_distance > 0
                             ? m.size.grading_distance
                             : 0.5 * std::min(m.domain.width, m.domain.height);
  const double beyond = std::max(0.0, d - m.tunnel.fracture_zone);
  return m.size.size_near + (m.size.size_far - m.size.size_near) * std::min(1.0, beyond / grading);
}

bool staged(const Scene& s) {
  return s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile;
}

double explicit_steps(const Scene& s) {
  if (!staged(s)) return double(s.engine.steps);
  double n = s.stages.empty() ? 0 : 1;  // the hand-off step
  for (const StageSpec& st : s.stages) n += double(st.max_steps);
  return n;
}

namespace {

// The time a P-wave takes [s] along the four axis rays from the opening's
// centre (the origin) to the box's sides, averaged: the slowest modes of
// a square box about a central opening run along them.
double transit_seconds(const Scene& s, double cp) {
  const mesh::MeshSpec& m = s.mesh;
  const mesh::Outline outline = mesh::tunnel_outline(m.tunnel);
  const double box[4][2] = {{m.domain.center_x - m.domain.width / 2, 0},
                            {m.domain.center_x + m.domain.width / 2, 0},
                            {0, m.domain.center_y - m.domain.height / 2},
                            {0, m.domain.center_y + m.domain.height / 2}};
  const int n = 2000;
  double total = 0;
  for (const auto& end : box) {
    const double ds = std::hypot(end[0], end[1]) / n;
    for (int i = 0; i < n; ++i) {
      const double x = end[0] * (i + 0.5) / n, y = end[1] * (i + 0.5) / n;
      if (mesh::inside_outline(outline, x, y)) continue;
      const double h = local_size(m, mesh::distance_to_outline(outline, x, y));
      // Mass scaling slows an element of size h to the coarsest one's step.
      const double c_eff = s.engine.mass_scaling ? cp * h / m.size.size_far : cp;
      total += ds / c_eff;
    }
  }
  return total / 4;
}

// Steps to an unbalanced-force ratio `ratio` from `transits` at 1e-3,
// no fewer than `hold` outputs, rounded up to an output, at most the cap.
double criterion_steps(const StageSpec& st, double transits, double transit) {
  const double ratio = st.ratio > 0 ? st.ratio : 1e-3;
  double n = transits * transit * std::log(1 / ratio) / std::log(1e3);
  const double every = std::max(1, st.every_steps);
  n = std::max(n, double(std::max(1, st.hold)) * every);
  return std::min(double(st.max_steps), std::ceil(n / every) * every);
}

// A stage's expected steps; without a transit, a criterion stage at half
// its cap (the shipped tunnels stopped at 0.17-0.63 of their caps).
double stage_steps(const StageSpec& st, double transit, bool fractures) {
  const bool ratio_stage = (st.kind == "equilibrium" || st.kind == "soften") && st.ratio > 0;
  if (st.kind == "grout" || ratio_stage) {
    if (transit <= 0) return 0.5 * double(st.max_steps);
    if (st.kind == "grout") return std::min(double(st.max_steps), kGroutTransits * transit);
    return criterion_steps(st, fractures ? kFractureTransits : kElasticTransits, transit);
  }
  return double(st.max_steps);
}

}  // namespace

double transit_steps(const Scene& s, double dt, double cp) {
  if (s.mesh.kind != mesh::ModelKind::kTunnel || !(dt > 0) || !(cp > 0)) return 0;
  return transit_seconds(s, cp) / dt;
}

double expected_steps(const Scene& s, double transit) {
  if (!staged(s))
    return double(s.engine.steps) * (s.engine.stop_after_peak > 0 ? kSpecimenShare : 1.0);
  double n = s.stages.empty() ? 0 : 1;
  const bool fractures = s.mesh.tunnel.fracture_zone > 0;
  for (const StageSpec& st : s.stages) n += stage_steps(st, transit, fractures);
  return n;
}

}  // namespace rockfdem::workflows
