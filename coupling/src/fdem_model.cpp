#include "rockfdem/coupling/fdem_model.hpp"

#include <string>

#include "array_legend.hpp"
#include "principal_stress.hpp"
#include "rockfdem/coupling/joint_cracks.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::coupling {

fdem::ModelInput model_input(const mesh::Mesh& m,
                             const std::map<mesh::Zone, fdem::Material>& by_zone,
                             fdem::Plane plane) {
  fdem::ModelInput in;
  in.x = m.x;
  in.y = m.y;
  in.triangles = m.triangles;
  in.fracture = m.fracture;
  in.plane = plane;
  // Zones become a compact material list in zone order.
  std::map<int, int> index;
  for (const auto& [zone, material] : by_zone) {
    index[zone] = int(in.materials.size());
    in.materials.push_back(material);
  }
  in.material.resize(m.n_triangles());
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const auto it = index.find(m.zone[t]);
    if (it == index.end())
      throw InputError("mesh zone " + std::to_string(m.zone[t]) + " (triangle " +
                       std::to_string(t) + ") has no material; give [materials.*] for it");
    in.material[t] = it->second;
  }
  for (const mesh::TaggedEdge& e : m.edges) in.edges.push_back({e.a, e.b, e.tag});
  return in;
}

void apply_insitu(const insitu::InsituField& field, fdem::ModelInput& in) {
  in.initial_stress.resize(field.stress.size());
  for (std::size_t t = 0; t < field.stress.size(); ++t)
    in.initial_stress[t] = {field.stress[t].sxx, field.stress[t].syy, field.stress[t].sxy};
}

namespace {

void add_node_arrays(const fdem::Engine& e, const insitu::InsituField* implicit, VtkGrid& g) {
  const std::size_t n = e.n_nodes();
  std::vector<double> u(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto d = e.displacement(i);
    const int v = e.node_vertex()[i];
    u[2 * i] = d[0] + (implicit ? implicit->ux[v] : 0.0);
    u[2 * i + 1] = d[1] + (implicit ? implicit->uy[v] : 0.0);
  }
  g.point_arrays.push_back(vector_array("displacement", 2, std::move(u)));
  g.point_arrays.push_back(vector_array("velocity", 2, e.velocities()));
}

void add_triangle_arrays(const fdem::Engine& e, const mesh::Mesh& m,
                         const insitu::InsituField* implicit, VtkGrid& g) {
  const std::size_t n = e.n_triangles();
  std::vector<double> stress(4 * n), principal(2 * n);
  std::vector<std::int32_t> active(n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto s = e.triangle_stress(t);
    const auto p = principal_stresses(s[0], s[1], s[2]);
    const double zz0 = implicit ? implicit->stress[t].szz : 0.0;
    const double zz = e.triangle_stress_zz(t, zz0);
    const double full[4] = {s[0], s[1], zz, s[2]};
    std::copy(full, full + 4, stress.begin() + 4 * t);
    principal[2 * t] = p[0];
    principal[2 * t + 1] = p[1];
    active[t] = e.active(t) ? 1 : 0;
  }
  g.cell_arrays.push_back(triangle_cell_array(g, tensor_array("stress", 4, std::move(stress))));
  g.cell_arrays.push_back(
      triangle_cell_array(g, vector_array("principal_stress", 2, std::move(principal))));
  g.cell_arrays.push_back(triangle_cell_array(
      g, scalar_array("zone", std::vector<std::int32_t>(m.zone.begin(), m.zone.end()))));
  g.cell_arrays.push_back(triangle_cell_array(g, scalar_array("active", std::move(active))));
}

void add_crack_arrays(const fdem::Engine& e, VtkGrid& g) {
  const std::size_t n = e.n_cracks();
  std::vector<double> damage(n);
  std::vector<std::int32_t> state(n), mode(n);
  for (std::size_t c = 0; c < n; ++c) {
    damage[c] = e.crack_damage(c);
    state[c] = std::int32_t(e.crack_state(c));
    mode[c] = std::int32_t(e.crack_mode(c));
  }
  g.cell_arrays.push_back(line_cell_array(g, scalar_array("damage", std::move(damage))));
  g.cell_arrays.push_back(line_cell_array(g, scalar_array("crack_state", std::move(state))));
  g.cell_arrays.push_back(line_cell_array(g, scalar_array("failure_mode", std::move(mode))));
}

}  // namespace

VtkGrid fdem_grid(const fdem::Engine& e, const mesh::Mesh& m, const insitu::InsituField* implicit) {
  VtkGrid g;
  const std::vector<double>& pos = e.positions();
  const std::size_t n = e.n_nodes();
  g.x.resize(n);
  g.y.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    g.x[i] = pos[2 * i];
    g.y[i] = pos[2 * i + 1];
  }
  g.triangles.resize(e.n_triangles());
  for (std::size_t t = 0; t < e.n_triangles(); ++t) g.triangles[t] = e.triangle_nodes(t);
  // A crack element is drawn along its first face (nodes 0, 1).
  g.lines.resize(e.n_cracks());
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto nodes = e.crack_nodes(c);
    g.lines[c] = {nodes[0], nodes[1]};
  }
  add_node_arrays(e, implicit, g);
  add_triangle_arrays(e, m, implicit, g);
  add_crack_arrays(e, g);
  // Only a jointed model has the array, so other files stay as they were.
  if (!m.joint_edges.empty())
    g.cell_arrays.push_back(line_cell_array(g, scalar_array("joint", joint_crack_traces(e, m))));
  add_array_legend(g.field, !m.joint_edges.empty());
  return g;
}

void add_frame_info(VtkFieldData& f, const std::string& stage, long step, double time) {
  f.text.push_back({"stage", stage});
  f.numbers.push_back({"step", double(step)});
  f.numbers.push_back({"time_s", time});
}

}  // namespace rockfdem::coupling
