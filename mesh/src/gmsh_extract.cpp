// From gmsh's mesh to the plain record. gmsh numbers nodes with arbitrary
// positive tags (dense after generation, anything in a user's file), keeps
// elements per entity, and orients triangles as the surface's parametrization
// happens to run; the record wants compact indices, one array per quantity
// and counter-clockwise triangles.
#include <gmsh.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "gmsh_model.hpp"

namespace rockfdem::mesh::detail {

TagIndex::TagIndex(const std::vector<std::size_t>& tags) {
  const std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
  const bool dense = max_tag <= 4 * tags.size() + 1024;
  if (dense) dense_.assign(max_tag + 1, -1);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    bool fresh = true;
    if (dense) {
      fresh = dense_[tags[i]] < 0;
      if (fresh) dense_[tags[i]] = static_cast<int>(i);
    } else {
      fresh = sparse_.emplace(tags[i], static_cast<int>(i)).second;
    }
    if (!fresh && n_duplicates_++ == 0) first_duplicate_ = tags[i];
  }
}

int TagIndex::operator()(std::size_t tag) const {
  if (!dense_.empty() || sparse_.empty()) return tag < dense_.size() ? dense_[tag] : -1;
  const auto it = sparse_.find(tag);
  return it == sparse_.end() ? -1 : it->second;
}

std::vector<std::size_t> read_gmsh_nodes(Mesh& m, std::vector<double>* z) {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  m.x.resize(tags.size());
  m.y.resize(tags.size());
  if (z) z->resize(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    m.x[i] = xyz[3 * i];
    m.y[i] = xyz[3 * i + 1];
    if (z) (*z)[i] = xyz[3 * i + 2];
  }
  return tags;
}

int index_of(const TagIndex& index, std::size_t tag) {
  const int i = index(tag);
  if (i < 0) throw std::runtime_error("element refers to unknown node " + std::to_string(tag));
  return i;
}

std::vector<std::size_t> append_triangles(int s, int zone, std::uint8_t fracture,
                                          const TagIndex& index, Mesh& m) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, node_tags;
  gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, s);
  std::vector<std::size_t> added;
  for (std::size_t k = 0; k < types.size(); ++k) {
    if (types[k] != 2)
      throw std::runtime_error("surface " + std::to_string(s) + " holds elements of gmsh type " +
                               std::to_string(types[k]) + "; only 3-node triangles (type 2)");
    const auto& nodes = node_tags[k];
    for (std::size_t e = 0; e < element_tags[k].size(); ++e) {
      m.triangles.push_back({index_of(index, nodes[3 * e]), index_of(index, nodes[3 * e + 1]),
                             index_of(index, nodes[3 * e + 2])});
      m.zone.push_back(zone);
      m.fracture.push_back(fracture);
      added.push_back(element_tags[k][e]);
    }
  }
  return added;
}

void append_edges(int c, int tag, const TagIndex& index, Mesh& m) {
  std::vector<std::size_t> element_tags, nodes;
  gmsh::model::mesh::getElementsByType(1, element_tags, nodes, c);
  for (std::size_t e = 0; e < element_tags.size(); ++e)
    m.edges.push_back({index_of(index, nodes[2 * e]), index_of(index, nodes[2 * e + 1]), tag});
}

void compact_vertices(Mesh& m) {
  std::vector<int> new_id(m.x.size(), -1);
  for (const auto& t : m.triangles)
    for (int v : t) new_id[v] = 0;
  int n = 0;
  for (std::size_t v = 0; v < new_id.size(); ++v) {
    if (new_id[v] < 0) continue;
    new_id[v] = n;
    m.x[n] = m.x[v];
    m.y[n] = m.y[v];
    ++n;
  }
  m.x.resize(n);
  m.y.resize(n);
  for (auto& t : m.triangles)
    for (int& v : t) v = new_id[v];
  // Edges whose vertices no triangle uses cannot be boundaries of anything.
  std::vector<TaggedEdge> kept;
  for (const TaggedEdge& e : m.edges)
    if (new_id[e.a] >= 0 && new_id[e.b] >= 0) kept.push_back({new_id[e.a], new_id[e.b], e.tag});
  m.edges.swap(kept);
  std::vector<JointEdge> joints;
  for (const JointEdge& e : m.joint_edges)
    if (new_id[e.a] >= 0 && new_id[e.b] >= 0) joints.push_back({new_id[e.a], new_id[e.b], e.trace});
  m.joint_edges.swap(joints);
}

void orient_counter_clockwise(Mesh& m) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (signed_area(m, t) < 0) std::swap(m.triangles[t][1], m.triangles[t][2]);
}

Mesh extract_mesh(const GmshModelMap& model) {
  Mesh m;
  const TagIndex index(read_gmsh_nodes(m));
  for (const auto& [s, zone] : model.surface_zone) append_triangles(s, zone, 0, index, m);
  for (const auto& [c, tag] : model.curve_tag) append_edges(c, tag, index, m);
  for (const auto& [c, trace] : model.joint_curve) {
    std::vector<std::size_t> element_tags, nodes;
    gmsh::model::mesh::getElementsByType(1, element_tags, nodes, c);
    for (std::size_t e = 0; e < element_tags.size(); ++e)
      m.joint_edges.push_back(
          {index_of(index, nodes[2 * e]), index_of(index, nodes[2 * e + 1]), trace});
  }
  compact_vertices(m);
  orient_counter_clockwise(m);
  return m;
}

}  // namespace rockfdem::mesh::detail
