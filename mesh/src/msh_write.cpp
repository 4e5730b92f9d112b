// write_msh: a discrete gmsh model built from the record and saved by gmsh's
// own writer, so the file is whatever gmsh itself would write. Triangles are
// grouped into one discrete surface per (zone, fracture) pair, edges into one
// discrete curve per tag, joint edges into one per trace; physical groups
// name them. Element tags are the record's indices + 1 (triangles first,
// then edges, then joint edges) and node tags the vertex indices + 1, so
// read_msh can restore the exact order.
#include <gmsh.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "gmsh_session.hpp"
#include "msh_names.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace rockfdem::mesh {
namespace {

struct Block {
  std::vector<std::size_t> element_tags, node_tags;
};

void add_nodes(const Mesh& m, int entity) {
  std::vector<std::size_t> tags(m.n_vertices());
  std::vector<double> xyz(3 * m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    tags[v] = v + 1;
    xyz[3 * v] = m.x[v], xyz[3 * v + 1] = m.y[v], xyz[3 * v + 2] = 0;
  }
  gmsh::model::mesh::addNodes(2, entity, tags, xyz);
}

// One discrete surface per (zone, fracture), with physical groups per zone
// name and one "fracture" group.
void add_triangles(const Mesh& m) {
  std::map<std::pair<int, int>, Block> blocks;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    Block& b = blocks[{m.zone[t], m.fracture[t] ? 1 : 0}];
    b.element_tags.push_back(t + 1);
    for (int v : m.triangles[t]) b.node_tags.push_back(v + 1);
  }
  std::map<int, std::vector<int>> by_zone;
  std::vector<int> fractured;
  bool nodes_added = false;
  for (const auto& [key, block] : blocks) {
    const int s = gmsh::model::addDiscreteEntity(2);
    if (!nodes_added) add_nodes(m, s), nodes_added = true;
    gmsh::model::mesh::addElementsByType(s, 2, block.element_tags, block.node_tags);
    by_zone[key.first].push_back(s);
    if (key.second) fractured.push_back(s);
  }
  for (const auto& [zone, surfaces] : by_zone)
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, surfaces, zone),
                                 zone_name(zone));
  if (!fractured.empty())
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, fractured),
                                 detail::kFractureGroup);
}

void add_edges(const Mesh& m) {
  std::map<int, Block> blocks;
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    Block& b = blocks[m.edges[e].tag];
    b.element_tags.push_back(m.n_triangles() + e + 1);
    b.node_tags.push_back(m.edges[e].a + 1);
    b.node_tags.push_back(m.edges[e].b + 1);
  }
  for (const auto& [tag, block] : blocks) {
    const int c = gmsh::model::addDiscreteEntity(1);
    gmsh::model::mesh::addElementsByType(c, 1, block.element_tags, block.node_tags);
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {c}, tag), edge_tag_name(tag));
  }
}

// One discrete curve per joint trace, in trace order (so read_msh numbers
// them back the same), all in the group "joints".
void add_joint_edges(const Mesh& m) {
  std::map<int, Block> blocks;
  for (std::size_t j = 0; j < m.joint_edges.size(); ++j) {
    Block& b = blocks[m.joint_edges[j].trace];
    b.element_tags.push_back(m.n_triangles() + m.edges.size() + j + 1);
    b.node_tags.push_back(m.joint_edges[j].a + 1);
    b.node_tags.push_back(m.joint_edges[j].b + 1);
  }
  std::vector<int> curves;
  for (const auto& [trace, block] : blocks) {
    curves.push_back(gmsh::model::addDiscreteEntity(1));
    gmsh::model::mesh::addElementsByType(curves.back(), 1, block.element_tags, block.node_tags);
  }
  if (!curves.empty())
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, curves), detail::kJointGroup);
}

// gmsh picks the format from the extension, so the temporary name ends in .msh.
std::string temporary_path(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  return dir + "." + base + ".tmp" + std::to_string(::getpid()) + ".msh";
}

}  // namespace

void write_msh(const Mesh& m, const std::string& path) {
  const std::string tmp = temporary_path(path);
  try {
    detail::GmshSession session(1);
    detail::gmsh_guarded("writing " + path, detail::GmshFailure::kRuntime, [&] {
      gmsh::model::add("rockfdem");
      add_triangles(m);
      add_edges(m);
      add_joint_edges(m);
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::option::setNumber("Mesh.Binary", 0);
      gmsh::option::setNumber("Mesh.SaveAll", 0);
      gmsh::write(tmp);
    });
  } catch (...) {
    std::remove(tmp.c_str());  // leave no half-written file behind
    throw;
  }
  // gmsh only logs some write failures (e.g. a missing folder): the file
  // must exist before it replaces anything.
  if (!std::ifstream(tmp).good() || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw OutputError("writing " + path +
                      ": cannot write the file; check that its "
                      "folder exists and is writable");
  }
}

}  // namespace rockfdem::mesh
