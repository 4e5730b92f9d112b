#include "outputs/continuum_comparison.hpp"

#include <cmath>
#include <sstream>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {

bool kirsch_case(const Scene& s, insitu::KirschCase* k) {
  const mesh::MeshSpec& m = s.mesh;
  if (m.kind != mesh::ModelKind::kTunnel || m.tunnel.shape != mesh::TunnelShape::kCircular ||
      m.tunnel.lining_thickness > 0 || s.insitu.unit_weight > 0)
    return false;
  const MaterialSpec& rock = s.materials.at(mesh::kRock);
  *k = {m.tunnel.radius,    s.insitu.sigma_h, s.insitu.sigma_v,
        s.insitu.angle_deg, rock.young,       rock.poisson};
  return true;
}

ContinuumComparison compare_with_continuum(const Scene& scene, const mesh::Mesh& m,
                                           const fdem::Engine& e,
                                           const insitu::InsituField& open_hole,
                                           const std::string& csv_path) {
  const mesh::HalfExtent h = mesh::opening_half_extent(scene.mesh.tunnel);
  const double reach = 5 * std::max(h.hx, h.hy);
  insitu::KirschCase k;
  const bool kirsch = kirsch_case(scene, &k);
  StressL2 vs_fem, vs_kirsch;
  std::ostringstream csv;
  csv.precision(10);
  csv << "triangle,x,y,fdem_sxx,fdem_syy,fdem_sxy,fem_sxx,fem_syy,fem_sxy"
      << (kirsch ? ",kirsch_sxx,kirsch_syy,kirsch_sxy" : "") << '\n';
  std::size_t n = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock || !e.active(t)) continue;
    const auto& tri = m.triangles[t];
    const double x = (m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3;
    const double y = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
    if (std::hypot(x, y) > reach) continue;
    const double area = std::abs(mesh::signed_area(m, t));
    const auto s = e.triangle_stress(t);
    const insitu::Stress& f = open_hole.stress[t];
    vs_fem.add(area, s, {f.sxx, f.syy, f.sxy});
    csv << t << ',' << x << ',' << y << ',' << s[0] << ',' << s[1] << ',' << s[2] << ',' << f.sxx
        << ',' << f.syy << ',' << f.sxy;
    if (kirsch) {
      const insitu::Stress ks = insitu::kirsch_stress(k, x, y);
      vs_kirsch.add(area, s, {ks.sxx, ks.syy, ks.sxy});
      csv << ',' << ks.sxx << ',' << ks.syy << ',' << ks.sxy;
    }
    csv << '\n';
    ++n;
  }
  coupling::atomic_write_text(csv_path, csv.str());
  ContinuumComparison c{n, vs_fem.value(), std::nullopt};
  if (kirsch) c.fdem_vs_kirsch_rel_l2 = vs_kirsch.value();
  return c;
}

}  // namespace rockfdem::workflows
