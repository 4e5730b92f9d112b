#include "run/implicit_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {
namespace {

// det F of triangle t under the displacement (ux, uy): the displaced
// signed area over the undeformed one.
double jacobian(const mesh::Mesh& m, std::size_t t, const insitu::InsituField& f) {
  const auto& v = m.triangles[t];
  const auto x = [&](int k) { return m.x[v[k]] + f.ux[v[k]]; };
  const auto y = [&](int k) { return m.y[v[k]] + f.uy[v[k]]; };
  const double now = (x(1) - x(0)) * (y(2) - y(0)) - (x(2) - x(0)) * (y(1) - y(0));
  return now / (2 * mesh::signed_area(m, t));
}

}  // namespace

Inversion inverted_triangles(const mesh::Mesh& m, const insitu::InsituField& f) {
  Inversion r;
  if (f.ux.size() != m.n_vertices()) return r;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (!f.active.empty() && !f.active[t]) continue;
    if (!(jacobian(m, t, f) > 0) && r.count++ == 0) r.first = t;
  }
  return r;
}

void check_implicit_field(const Scene& scene, const mesh::Mesh& m, double alpha,
                          const Inversion& inv) {
  if (inv.count == 0) return;
  const double stress = std::max(scene.insitu.sigma_h, scene.insitu.sigma_v);
  const double young = scene.materials.at(mesh::kRock).young;
  const auto& v = m.triangles[inv.first];
  char msg[700];
  std::snprintf(msg, sizeof msg,
                "%s: the implicit in-situ field (alpha %g) inverts %ld of %zu triangles "
                "(first: triangle %zu at (%.3g, %.3g) m): the in-situ stress (keys "
                "'insitu.sigma_h' = %g, 'insitu.sigma_v' = %g Pa) is %.3g times the rock's "
                "Young's modulus ('materials.rock.young' = %g Pa); a linear elastic stage "
                "needs it far below 1 (the seed's tunnel: 0.006). Check the units: "
                "stresses and moduli are in Pa",
                scene.source.c_str(), alpha, inv.count, m.n_triangles(), inv.first,
                (m.x[v[0]] + m.x[v[1]] + m.x[v[2]]) / 3, (m.y[v[0]] + m.y[v[1]] + m.y[v[2]]) / 3,
                scene.insitu.sigma_h, scene.insitu.sigma_v, stress / young, young);
  throw InputError(msg);
}

std::string with_likely_cause(const Scene& scene, const std::string& what) {
  const double stress = std::max(std::abs(scene.insitu.sigma_h), std::abs(scene.insitu.sigma_v));
  const double young = scene.materials.at(mesh::kRock).young;
  if (!(stress > kStressRatioLimit * young)) return what;
  char cause[600];
  std::snprintf(cause, sizeof cause,
                " Likely cause: the in-situ stress (keys 'insitu.sigma_h' = %g, "
                "'insitu.sigma_v' = %g Pa) is %.3g times the rock's Young's modulus "
                "('materials.rock.young' = %g Pa), above %g (the seed's tunnel: 0.006): "
                "check the units (stresses and moduli are in Pa) before changing dt or "
                "damping.",
                scene.insitu.sigma_h, scene.insitu.sigma_v, stress / young, young,
                kStressRatioLimit);
  return what + cause;
}

}  // namespace rockfdem::workflows
