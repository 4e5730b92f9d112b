#include "rockfdem/coupling/insitu_grid.hpp"

#include "array_legend.hpp"
#include "principal_stress.hpp"

namespace rockfdem::coupling {

VtkGrid insitu_grid(const mesh::Mesh& m, const insitu::InsituField& field) {
  VtkGrid g;
  g.x = m.x;
  g.y = m.y;
  g.triangles = m.triangles;

  std::vector<double> u(2 * m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    u[2 * v] = field.ux[v];
    u[2 * v + 1] = field.uy[v];
  }
  g.point_arrays.push_back(vector_array("displacement", 2, std::move(u)));

  std::vector<double> stress, principal;
  stress.reserve(4 * m.n_triangles());
  principal.reserve(2 * m.n_triangles());
  for (const insitu::Stress& s : field.stress) {
    stress.insert(stress.end(), {s.sxx, s.syy, s.szz, s.sxy});
    const auto p = principal_stresses(s.sxx, s.syy, s.sxy);
    principal.insert(principal.end(), {p[0], p[1]});
  }
  g.cell_arrays.push_back(tensor_array("stress", 4, std::move(stress)));
  VtkArray p = vector_array("principal_stress", 2, std::move(principal));
  g.cell_arrays.push_back(std::move(p));
  g.cell_arrays.push_back(
      scalar_array("zone", std::vector<std::int32_t>(m.zone.begin(), m.zone.end())));
  g.cell_arrays.push_back(
      scalar_array("active", std::vector<std::int32_t>(field.active.begin(), field.active.end())));
  add_array_legend(g.field);
  g.field.numbers.push_back({"alpha", field.alpha});
  g.field.numbers.push_back({"deconfinement", 1.0 - field.alpha});
  return g;
}

}  // namespace rockfdem::coupling
