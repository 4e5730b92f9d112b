#include "commands/expected_steps.hpp"

#include <algorithm>
#include <cmath>

#include "rockfdem/mesh/outline.hpp"
#include "rockfdem/workflows/rock_mass.hpp"

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

// Transits to settle at the stage's ratio: an exponentially damped
// residual falls by a fixed factor per transit.
double settle_transits(const StageSpec& st) {
  const double ratio = st.ratio > 0 ? st.ratio : 1e-3;
  return kSettleTransits * std::log(1 / ratio) / std::log(1e3);
}

// A stage's expected steps, given the failure transits not yet spent;
// without a transit, a criterion stage at half its cap (the shipped
// tunnels stopped at 0.17-0.63 of their caps).
double stage_steps(const StageSpec& st, double transit, double failure) {
  const bool ratio_stage = (st.kind == "equilibrium" || st.kind == "soften") && st.ratio > 0;
  const double cap = double(st.max_steps);
  if (st.kind != "grout" && !ratio_stage) return cap;
  if (transit <= 0) return 0.5 * cap;
  if (st.kind == "grout") return std::min(cap, kGroutTransits * transit);
  const double every = std::max(1, st.every_steps);
  const double n =
      std::max((settle_transits(st) + failure) * transit, double(std::max(1, st.hold)) * every);
  return std::min(cap, std::ceil(n / every) * every);
}

}  // namespace

bool rock_fails_at_opening(const Scene& s) {
  if (!(s.mesh.tunnel.fracture_zone > 0)) return false;
  const MaterialSpec& rock = s.materials.at(mesh::kRock);
  const double high = std::max(s.insitu.sigma_h, s.insitu.sigma_v);
  const double low = std::min(s.insitu.sigma_h, s.insitu.sigma_v);
  return 3 * high - low > mohr_coulomb_ucs(rock.cohesion, rock.friction_angle);
}

bool fails_at_once(const Scene& s) {
  return rock_fails_at_opening(s) &&
         std::none_of(s.stages.begin(), s.stages.end(),
                      [](const StageSpec& st) { return st.kind == "soften"; });
}

double transit_steps(const Scene& s, double dt, double cp) {
  if (s.mesh.kind != mesh::ModelKind::kTunnel || !(dt > 0) || !(cp > 0)) return 0;
  return transit_seconds(s, cp) / dt;
}

double expected_steps(const Scene& s, double transit) {
  if (!staged(s))
    return double(s.engine.steps) * (s.engine.stop_after_peak > 0 ? kSpecimenShare : 1.0);
  double n = s.stages.empty() ? 0 : 1;
  // The failure goes on through the stages, each spending what it takes.
  double failure = rock_fails_at_opening(s) ? kFailureTransits : 0;
  for (const StageSpec& st : s.stages) {
    const double steps = stage_steps(st, transit, failure);
    if (transit > 0) failure = std::max(0.0, failure - steps / transit);
    n += steps;
  }
  return n;
}

}  // namespace rockfdem::workflows
