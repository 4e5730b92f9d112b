#include "outputs/convergence_confinement.hpp"

#include "outputs/lining_forces.hpp"
#include "outputs/support_lines.hpp"

namespace rockfdem::workflows {
namespace {

/// The ring's mean thrust [N/m] over its segments; none without a ring.
std::optional<double> mean_thrust(const mesh::Mesh& m, const fdem::Engine& e) {
  const std::optional<LiningGeometry> g = lining_geometry(m);
  if (!g || g->segments.empty()) return std::nullopt;
  std::vector<std::array<double, 3>> stress(m.n_triangles(), {0, 0, 0});
  for (const LiningSegment& s : g->segments)
    for (const int t : s.triangles) stress[std::size_t(t)] = e.triangle_stress(std::size_t(t));
  double sum = 0;
  const std::vector<SectionForces> f = lining_forces(*g, stress);
  for (const SectionForces& x : f) sum += x.thrust;
  return sum / double(f.size());
}

}  // namespace

ConvergenceConfinementFigures convergence_confinement(const Scene& scene, const mesh::Mesh& m,
                                                      const fdem::Engine& e,
                                                      const ConvergenceConfinementState& s) {
  const EquivalentOpening o = equivalent_opening(m);
  ConvergenceConfinementFigures c;
  c.radius_m = o.radius;
  c.lining_thickness_m = o.lining_thickness;
  for (const SupportLine& l : scene_support_lines(scene, o, ring_parts(scene, m, o)))
    c.support.push_back({l.name, l.p_max, l.stiffness, 1e3 * l.max_displacement(), l.note});
  c.install_radial_mm = s.install_radial_mm;
  c.install_alpha = s.install_alpha;
  c.end_radial_mm = s.end_radial_mm;
  if (s.lining_installed)
    if (const std::optional<double> n = mean_thrust(m, e)) c.end_pressure_Pa = *n / o.radius;
  return c;
}

}  // namespace rockfdem::workflows
