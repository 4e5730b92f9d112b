#include "run/handoff_choice.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <utility>

#include "run/engine_setup.hpp"

namespace rockfdem::workflows {

// The normal and tangent are computed from the edge when a field is read:
// 16 bytes a face held through the implicit stage's solves, not 40.
struct StrengthRatio::Face {
  int t1, t2;  ///< the two triangles
  int a, b;    ///< the edge's vertices as the second triangle runs it
};

namespace {

using Face = StrengthRatio::Face;

// Interior edges with a fracture triangle on either side, in a fixed order
// (by their vertex pair): the engine's crack elements (fdem topology).
std::vector<Face> crack_faces(const mesh::Mesh& m) {
  std::map<std::pair<int, int>, int> first;
  std::vector<Face> faces;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      const auto key = std::minmax(a, b);
      const auto [it, fresh] = first.emplace(key, int(t));
      if (fresh) continue;
      const int u = it->second;
      if (!m.fracture[t] && !m.fracture[u]) continue;
      faces.push_back({u, int(t), a, b});
    }
  return faces;
}

// The largest traction-to-strength ratio over the faces (handoff_choice.hpp).
double worst_ratio(const std::vector<Face>& faces,
                   const std::map<mesh::Zone, fdem::Material>& materials, const mesh::Mesh& m,
                   const insitu::InsituField& field) {
  double worst = 0;
  for (const Face& f : faces) {
    if (!field.active[f.t1] || !field.active[f.t2]) continue;
    const fdem::Material& m1 = materials.at(mesh::Zone(m.zone[f.t1]));
    const fdem::Material& m2 = materials.at(mesh::Zone(m.zone[f.t2]));
    const fdem::Material& mat = m2.tensile_strength < m1.tensile_strength ? m2 : m1;
    const insitu::Stress& a = field.stress[f.t1];
    const insitu::Stress& b = field.stress[f.t2];
    const double sxx = (a.sxx + b.sxx) / 2, syy = (a.syy + b.syy) / 2, sxy = (a.sxy + b.sxy) / 2;
    const double dx = m.x[f.b] - m.x[f.a], dy = m.y[f.b] - m.y[f.a], len = std::hypot(dx, dy);
    const double nx = dy / len, ny = -dx / len, tx = dx / len, ty = dy / len;
    const double tr_x = sxx * nx + sxy * ny, tr_y = sxy * nx + syy * ny;
    const double sn = tr_x * nx + tr_y * ny, tau = tr_x * tx + tr_y * ty;  // tension +
    const double fs =
        sn < 0 ? mat.cohesion - sn * std::tan(mat.friction_deg * M_PI / 180) : mat.cohesion;
    worst = std::max({worst, sn / mat.tensile_strength, std::fabs(tau) / fs});
  }
  return worst;
}

}  // namespace

StrengthRatio::StrengthRatio(const Scene& scene, const mesh::Mesh& m)
    : mesh_(&m), materials_(engine_materials(scene)) {}

double StrengthRatio::operator()(const insitu::InsituField& f) {
  if (!faces_) faces_ = std::make_shared<const std::vector<Face>>(crack_faces(*mesh_));
  return worst_ratio(*faces_, materials_, *mesh_, f);
}

HandoffChoice choose_handoff(const Scene& scene, std::vector<double> strength_ratio) {
  HandoffChoice c;
  c.strength_ratio = std::move(strength_ratio);
  c.index = c.strength_ratio.size() - 1;
  if (!scene.insitu.handoff_first_crack) return c;
  c.index = 0;
  while (c.index + 1 < c.strength_ratio.size() && c.strength_ratio[c.index + 1] <= 1.0) ++c.index;
  return c;
}

}  // namespace rockfdem::workflows
