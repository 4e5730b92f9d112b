// Density factors for quasi-static mass scaling (mass_scaling.hpp).
//
// Scaling a node's masses by f lowers its frequency by sqrt(f), so a node
// whose bound is l needs f = (target / l)^2 without damping (node_need has
// the damped form). A triangle takes the largest need of its three nodes
// (its factor scales all three corners). Crack
// elements couple nodes of neighbouring triangles through 1 / sqrt(m_i m_j)
// (stable_dt.cpp), so a node next to a less scaled neighbour may still fall
// short after one pass: a few passes settle it. The engine's dt is then
// computed from the scaled masses as always (critical_dt), so the scaling
// only has to be good, never exact, to be safe. With contact on, each
// triangle's contact frequency joins its own; the engine adds the largest
// contact frequency to the model's (Engine::Impl::refresh), so the step
// then lands near target / sqrt(2).
#include "mass_scaling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "node_update.hpp"
#include "stable_dt.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Passes of the factor update; each costs one node_frequencies sweep.
constexpr int kPasses = 6;

/// Relative shortfall of a node's bound below the target that is accepted.
constexpr double kTolerance = 1e-3;

/// Largest density factor: a target far above what the model needs would
/// otherwise overflow the masses and freeze the nodes.
constexpr double kMaxFactor = 1e12;

/// Mass factor that brings a node (frequency^2 w2, viscous and dashpot
/// ratio xi, on its current masses) to the limit `g` = 2 / step without
/// local damping. Scaling the masses by f gives omega' = omega / sqrt(f),
/// omega' xi' = omega xi / f for the viscous and dashpot part, and leaves
/// the mass-proportional part c / 2 as it is; solving
/// omega' (sqrt(1 + xi'^2) + xi') = g (damped_limit) for f:
///   f = (omega^2 + 2 g omega xi) / (g (g - c)).
/// Mass-proportional damping alone caps the step at 2 / c: beyond it no
/// mass helps, so the target is held at 80% of that cap.
double node_need(double w2, double xi, double c, double g) {
  if (!(w2 > 0)) return 1.0;
  g = std::max(g, 1.25 * c);
  return (w2 + 2.0 * g * std::sqrt(w2) * xi) / (g * (g - c));
}

}  // namespace

double largest_node_limit(const EngineData& d) {
  std::vector<double> limit;
  node_limits(d, limit, d.contact_on);
  // A softened triangle (alpha < 1, an excavation core) is no measure of
  // the model: its limit grows as it is emptied.
  std::vector<std::uint8_t> softened(d.nodes.size(), 0);
  for (std::size_t t = 0; t < d.tris.size(); ++t)
    if (d.tris.active[t] && d.tris.alpha[t] < 1.0)
      for (int k = 0; k < 3; ++k) softened[d.tris.nodes[3 * t + k]] = 1;
  double best = 0, any = 0;
  for (std::size_t n = 0; n < limit.size(); ++n) {
    if (!std::isfinite(limit[n])) continue;
    any = std::max(any, limit[n]);
    if (!softened[n]) best = std::max(best, limit[n]);
  }
  return best > 0 ? best : any;
}

void scale_masses(EngineData& d) {
  Triangles& tr = d.tris;
  tr.mass_scale.assign(tr.size(), 1.0);
  refresh_masses(d);  // the true masses
  // Local damping divides every limit by the same sqrt(1 + alpha): the
  // target is held without it, so a later change of local damping does not
  // scale every mass.
  if (!(d.scaled_dt > 0))
    d.scaled_dt = d.mass_scaling.dt > 0 ? d.mass_scaling.dt
                                        : std::sqrt(1.0 + d.damping.local) * largest_node_limit(d);
  if (!(d.scaled_dt > 0)) return;  // nothing stiff yet: resolved at a later refresh
  const double g = 2.0 / d.scaled_dt, c = d.damping.mass_proportional;
  std::vector<double> w2, xi;
  for (int pass = 0; pass < kPasses; ++pass) {
    node_frequencies(d, d.contact_on, w2, xi);
    bool raised = false;
    for (std::size_t t = 0; t < tr.size(); ++t) {
      if (!tr.active[t]) continue;
      double need = 1.0;
      for (int k = 0; k < 3; ++k) {
        const int n = tr.nodes[3 * t + k];
        need = std::max(need, node_need(w2[n], xi[n], c, g));
      }
      if (need > 1.0 + kTolerance && tr.mass_scale[t] < kMaxFactor) {
        tr.mass_scale[t] = std::min(kMaxFactor, tr.mass_scale[t] * need);
        raised = true;
      }
    }
    if (!raised) break;
    refresh_masses(d);
  }
}

}  // namespace rockfdem::fdem::detail
