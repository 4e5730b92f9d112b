// Boundary conditions.
//
// Kinematic parts (fixed, prescribed velocity) act on every engine node at
// the tagged edges' vertices: a platen touches all the corners there, not
// only those of the triangle owning the edge. Force parts act on the owning
// triangle's two nodes, each receiving half of the edge's resultant (the
// consistent split for a constant traction on a linear edge).
#include "boundary.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "node_list.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::fdem::detail {
namespace {

/// Triangles around each mesh vertex (CSR), for finding an edge's owner.
struct VertexTriangles {
  std::vector<int> start, tris;
};

VertexTriangles vertex_triangles(const ModelInput& in) {
  VertexTriangles vt;
  vt.start.assign(in.x.size() + 1, 0);
  for (const auto& t : in.triangles)
    for (int v : t) ++vt.start[v + 1];
  for (std::size_t i = 0; i + 1 < vt.start.size(); ++i) vt.start[i + 1] += vt.start[i];
  vt.tris.resize(vt.start.back());
  std::vector<int> fill(vt.start.begin(), vt.start.end() - 1);
  for (std::size_t t = 0; t < in.triangles.size(); ++t)
    for (int v : in.triangles[t]) vt.tris[fill[v]++] = static_cast<int>(t);
  return vt;
}

/// The owner of edge (a, b): the only triangle, or the one where a->b is
/// counter-clockwise.
EdgeRef resolve_edge(const ModelInput& in, const VertexTriangles& vt, const TaggedEdge& e) {
  EdgeRef found{e.tag, -1, 0, 0};
  int n_found = 0;
  for (int i = vt.start[e.a]; i < vt.start[e.a + 1]; ++i) {
    const int t = vt.tris[i];
    const auto& v = in.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      const bool forward = v[k] == e.a && v[k1] == e.b;
      const bool backward = v[k] == e.b && v[k1] == e.a;
      if (!forward && !backward) continue;
      ++n_found;
      if (forward || found.tri < 0) found = {e.tag, t, k, k1};
    }
  }
  if (n_found == 0)
    throw InputError("fdem model input: tagged edge (" + std::to_string(e.a) + ", " +
                     std::to_string(e.b) + ") with tag " + std::to_string(e.tag) +
                     " is not an edge of any triangle");
  return found;
}

void add_dashpot(BoundaryRecord& r, const SolidConstants& m, double nx, double ny,
                 double half_len) {
  const double cn = m.rho * m.cp * half_len, ct = m.rho * m.cs * half_len;
  // C = cn n n^T + ct t t^T with t = (-ny, nx).
  r.cxx += cn * nx * nx + ct * ny * ny;
  r.cxy += (cn - ct) * nx * ny;
  r.cyy += cn * ny * ny + ct * nx * nx;
}

void constrain(BoundaryRecord& r, const BoundaryCondition& bc) {
  if (bc.x != Constraint::kFree) {
    r.x = bc.x;
    r.vx = bc.x == Constraint::kVelocity ? bc.vx : 0.0;
  }
  if (bc.y != Constraint::kFree) {
    r.y = bc.y;
    r.vy = bc.y == Constraint::kVelocity ? bc.vy : 0.0;
  }
}

/// Edge geometry in the mesh (reference) configuration: length and outward
/// unit normal of the owning triangle.
void edge_geometry(const EngineData& d, const EdgeRef& e, double& len, double& nx, double& ny) {
  const int na = d.tris.nodes[3 * e.tri + e.ka], nb = d.tris.nodes[3 * e.tri + e.kb];
  const Nodes& n = d.nodes;
  const double dx = n.mesh_position(nb, 0) - n.mesh_position(na, 0);
  const double dy = n.mesh_position(nb, 1) - n.mesh_position(na, 1);
  len = std::sqrt(dx * dx + dy * dy);
  nx = dy / len;
  ny = -dx / len;
}

bool is_kinematic(const BoundaryCondition& bc) {
  return bc.x != Constraint::kFree || bc.y != Constraint::kFree;
}

/// Calls f(node) for every engine node at mesh vertex v.
template <class F>
void for_vertex_nodes(const EngineData& d, int v, F&& f) {
  for (int i = d.vertex_node_start[v]; i < d.vertex_node_start[v + 1]; ++i) f(d.vertex_nodes[i]);
}

/// The nodes that get a boundary record, ascending: the two nodes of each
/// absorbing edge, and every node at a kinematic edge's two vertices.
std::vector<int> record_nodes(const std::vector<BoundaryCondition>& bcs, const EngineData& d) {
  std::vector<int> nodes;
  for (const BoundaryCondition& bc : bcs) {
    if (!is_kinematic(bc) && !bc.absorbing) continue;
    for (const EdgeRef& e : d.edges) {
      if (e.tag != bc.tag) continue;
      for (int k : {e.ka, e.kb}) {
        const int node = d.tris.nodes[3 * e.tri + k];
        if (bc.absorbing) nodes.push_back(node);
        if (is_kinematic(bc))
          for_vertex_nodes(d, d.nodes.vertex[node], [&](int n) { nodes.push_back(n); });
      }
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// The records of the listed nodes as they are built, and which of them
/// the current condition's tag already holds.
struct BoundaryBuild {
  std::vector<int> nodes;  ///< ascending (record_nodes)
  std::vector<BoundaryRecord> records;
  std::vector<std::uint8_t> in_tag;
};

/// One condition's loads, dashpots, constraints and tagged nodes, in the
/// order of the edges (the dashpots' sums and the tag's node order follow it).
void apply_condition(const BoundaryCondition& bc, EngineData& d, BoundaryBuild& b) {
  const bool kinematic = is_kinematic(bc);
  TagNodes tagged{bc.tag, {}};
  b.in_tag.assign(b.nodes.size(), 0);
  for (const EdgeRef& e : d.edges) {
    if (e.tag != bc.tag) continue;
    double len, nx, ny;
    edge_geometry(d, e, len, nx, ny);
    const SolidConstants& m = d.solids[d.tris.material[e.tri]];
    for (int k : {e.ka, e.kb}) {
      const int node = d.tris.nodes[3 * e.tri + k];
      const double fx = 0.5 * len * (bc.tx - bc.pressure * nx);
      const double fy = 0.5 * len * (bc.ty - bc.pressure * ny);
      if (fx != 0.0 || fy != 0.0) d.loads.push_back({node, fx, fy});
      if (bc.absorbing) add_dashpot(b.records[index_in(b.nodes, node)], m, nx, ny, 0.5 * len);
      if (!kinematic) continue;
      for_vertex_nodes(d, d.nodes.vertex[node], [&](int n) {
        const long r = index_in(b.nodes, n);
        constrain(b.records[r], bc);
        if (!b.in_tag[r]) tagged.nodes.push_back(n);
        b.in_tag[r] = 1;
      });
    }
  }
  if (kinematic) d.tag_nodes.push_back(std::move(tagged));
}

}  // namespace

void resolve_edges(const ModelInput& in, EngineData& d) {
  const VertexTriangles vt = vertex_triangles(in);
  d.edges.clear();
  for (const auto& e : in.edges) d.edges.push_back(resolve_edge(in, vt, e));
  // Vertex -> engine nodes, in node order.
  const std::size_t nv = in.x.size();
  d.vertex_node_start.assign(nv + 1, 0);
  for (int v : d.nodes.vertex) ++d.vertex_node_start[v + 1];
  for (std::size_t i = 0; i < nv; ++i) d.vertex_node_start[i + 1] += d.vertex_node_start[i];
  d.vertex_nodes.resize(d.nodes.size());
  std::vector<int> fill(d.vertex_node_start.begin(), d.vertex_node_start.end() - 1);
  for (std::size_t i = 0; i < d.nodes.size(); ++i)
    d.vertex_nodes[fill[d.nodes.vertex[i]]++] = static_cast<int>(i);
}

void apply_boundary_conditions(const std::vector<BoundaryCondition>& bcs, EngineData& d) {
  // Records for the listed nodes only, not a record per node: the engine
  // may be at its full size when a stage changes its conditions.
  BoundaryBuild b{record_nodes(bcs, d), {}, {}};
  b.records.resize(b.nodes.size());
  d.loads.clear();
  d.tag_nodes.clear();
  for (const BoundaryCondition& bc : bcs) apply_condition(bc, d, b);
  d.nodes.bc_node = std::move(b.nodes);
  d.nodes.bc_node.shrink_to_fit();
  d.bc_records = std::move(b.records);
  d.masses_dirty = true;  // external forces are rebuilt with the masses
}

}  // namespace rockfdem::fdem::detail
