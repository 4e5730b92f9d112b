// read_msh: a user's .msh through gmsh's reader (every version and binary
// form gmsh knows), then checked hard, since a bad mesh would otherwise fail
// much later and far from its cause. Each check names the file and the node,
// element or physical group at fault, and says what is allowed. The checks
// before gmsh run in the caller's process, gmsh's read and the checks after
// it in a child process (msh_child.hpp).
#include "msh_read.hpp"

#include <gmsh.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <new>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "gmsh_model.hpp"
#include "gmsh_session.hpp"
#include "msh_child.hpp"
#include "msh_header.hpp"
#include "msh_names.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/printable.hpp"

namespace rockfdem::mesh {
namespace {

using detail::TagIndex;

struct Reader {
  const MshFileSpec& spec;

  // Group names and gmsh's messages come from the file: shown as escapes.
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(printable(spec.path + ": " + what));
  }

  // Before gmsh reads a byte: a regular file (a FIFO would block, a device
  // such as /dev/zero never end), its first 64 bytes a mesh's start, its
  // last 4 KiB a section's end, and (ASCII) its size within what its
  // declared counts can take. Each is read in bounded time and memory.
  std::uint64_t check_file() const {
    struct stat st {};
    if (::stat(spec.path.c_str(), &st) != 0)
      fail("cannot open the file; give the path of a readable gmsh .msh file");
    if (!S_ISREG(st.st_mode))
      fail("is not a regular file (a directory, FIFO or device); give a gmsh .msh file");
    if (!std::ifstream(spec.path).good())
      fail("cannot open the file; give the path of a readable gmsh .msh file");
    if (!detail::starts_as_msh(spec.path))
      fail(
          "does not start with $MeshFormat (or $NOD); give a gmsh .msh mesh file (gmsh "
          "reads other text as a .geo script, which is never run here)");
    const std::uint64_t size = std::uint64_t(st.st_size);
    if (const auto after = detail::text_after_last_section(spec.path, size))
      fail(*after +
           "; a gmsh .msh file ends with its last section's $End line (refused before "
           "gmsh reads it)");
    return size;
  }

  // The checks before gmsh; returns the file's size.
  std::uint64_t check_before_gmsh() const {
    const std::uint64_t size = check_file();
    if (const auto items = detail::declared_items(spec.path)) {
      const std::uint64_t bound = detail::kFixedBytes + detail::kBytesPerItem * *items;
      if (size > bound)
        fail("holds " + std::to_string(size) + " bytes, more than the " + std::to_string(bound) +
             " its " + std::to_string(*items) +
             " declared nodes and elements can take (1 MiB + 1 KiB each); give the mesh "
             "without data appended (refused before gmsh reads it)");
    }
    if (const auto bad = detail::count_beyond_file(spec.path))
      fail(*bad + " (refused before gmsh reads it)");
    if (const auto bad = detail::tag_out_of_int_range(spec.path))
      fail(*bad +
           " is not a node, element or entity tag gmsh can read; tags in $Elements "
           "and $Periodic must be integers from 0 to 2147483647");
    return size;
  }

  void open() const {
    detail::gmsh_guarded(spec.path + ": not a readable gmsh mesh", detail::GmshFailure::kInput,
                         [&] {
                           // A backstop for what count_beyond_file cannot see
                           // (binary counts, an entity's count of physical
                           // groups or bounding entities): gmsh allocates by a
                           // declared count, and a vector's size beyond its
                           // limit is a std::length_error.
                           try {
                             gmsh::open(spec.path);
                           } catch (const std::bad_alloc&) {
                             fail(
                                 "gmsh ran out of memory reading it: a count in the file is "
                                 "larger than the file holds; give a complete gmsh .msh file");
                           } catch (const std::length_error&) {
                             fail(
                                 "gmsh could not allocate what a count in the file asks for (more "
                                 "than any array can hold): a count in the file is larger than "
                                 "the file holds; give a complete gmsh .msh file");
                           }
                         });
    std::string last;
    gmsh::logger::getLastError(last);
    if (!last.empty()) fail("not a readable gmsh mesh: " + last);
  }

  // Only 3-node triangles, 2-node lines and points (ignored) are accepted.
  void check_element_types() const {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes);
    for (std::size_t k = 0; k < types.size(); ++k) {
      if (types[k] == 1 || types[k] == 2 || types[k] == 15) continue;
      std::string name;
      int dim, order, n_nodes, n_primary;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(types[k], name, dim, order, n_nodes, local,
                                              n_primary);
      fail("element " + std::to_string(tags[k].front()) + " is a " + name + " (gmsh type " +
           std::to_string(types[k]) +
           "); allowed: 3-node triangles (type 2), 2-node lines "
           "(type 1) and points (type 15)");
    }
    if (std::find(types.begin(), types.end(), 2) == types.end())
      fail("no 3-node triangles; the mesh must be 2D and made of 3-node triangles");
  }

  // Nodes sorted by tag, all finite, in one plane parallel to x-y, no tag
  // twice, no two at one position.
  std::vector<std::size_t> read_nodes(Mesh& m) const {
    std::vector<double> z;
    std::vector<std::size_t> tags = detail::read_gmsh_nodes(m, &z);
    check_planar(m, z, tags);
    std::vector<std::size_t> order(tags.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return tags[a] < tags[b]; });
    Mesh sorted;
    std::vector<std::size_t> sorted_tags;
    for (std::size_t i : order) {
      if (!std::isfinite(m.x[i]) || !std::isfinite(m.y[i]))
        fail("node " + std::to_string(tags[i]) +
             " has a coordinate that is not a finite "
             "number; every coordinate must be finite");
      sorted.x.push_back(m.x[i]), sorted.y.push_back(m.y[i]), sorted_tags.push_back(tags[i]);
    }
    m.x.swap(sorted.x), m.y.swap(sorted.y);
    check_coincident(m, sorted_tags);
    return sorted_tags;
  }

  // The model is the x-y plane: x and y are read, z dropped. That is exact
  // only when every node has the same z (gmsh's 2D meshes: 0); a node off
  // that plane (a 3D or tilted mesh) would be moved onto it without a word,
  // changing lengths and areas, so it is refused. Round-off is allowed:
  // 1e-9 of the mesh's extent in x and y.
  void check_planar(const Mesh& m, const std::vector<double>& z,
                    const std::vector<std::size_t>& tags) const {
    if (z.empty()) return;
    double extent = 0;
    for (std::size_t i = 0; i < z.size(); ++i)
      extent = std::max({extent, std::abs(m.x[i] - m.x[0]), std::abs(m.y[i] - m.y[0])});
    std::size_t first = 0, off = z.size();  // off: the lowest tag off the plane
    for (std::size_t i = 0; i < z.size(); ++i) {
      if (!std::isfinite(z[i]))
        fail("node " + std::to_string(tags[i]) +
             " has a z coordinate that is not a finite number; every coordinate must be finite");
      if (tags[i] < tags[first]) first = i;
    }
    for (std::size_t i = 0; i < z.size(); ++i)
      if (std::abs(z[i] - z[first]) > 1e-9 * extent && (off == z.size() || tags[i] < tags[off]))
        off = i;
    if (off == z.size()) return;
    const auto text = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.6g", v);
      return std::string(buf);
    };
    fail("node " + std::to_string(tags[off]) + " has z = " + text(z[off]) + " and node " +
         std::to_string(tags[first]) + " z = " + text(z[first]) +
         ": the mesh is not flat; allowed: every node at one z (a 2D mesh in the x-y plane, "
         "usually z = 0), since z is dropped");
  }

  void check_coincident(const Mesh& m, const std::vector<std::size_t>& tags) const {
    const auto declared = detail::declared_node_count(spec.path);
    if (declared && *declared != tags.size())
      fail("the $Nodes section declares " + std::to_string(*declared) + " nodes but holds " +
           std::to_string(tags.size()) + " distinct node tags; each node tag must be unique");
    std::vector<std::size_t> order(tags.size());
    std::iota(order.begin(), order.end(), 0);
    const auto key = [&](std::size_t i) { return std::make_pair(m.x[i], m.y[i]); };
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return key(a) < key(b); });
    for (std::size_t k = 1; k < order.size(); ++k)
      if (key(order[k]) == key(order[k - 1]))
        fail("nodes " + std::to_string(tags[order[k - 1]]) + " and " +
             std::to_string(tags[order[k]]) +
             " lie at the same position; each position may "
             "hold one node only (merge duplicate nodes)");
  }

  // name -> physical tag of the groups of dimension `dim` in the file.
  std::map<std::string, int> groups(int dim) const {
    gmsh::vectorpair dim_tags;
    gmsh::model::getPhysicalGroups(dim_tags, dim);
    std::map<std::string, int> out;
    for (const auto& [d, tag] : dim_tags) {
      std::string name;
      gmsh::model::getPhysicalName(d, tag, name);
      out[name.empty() ? std::to_string(tag) : name] = tag;
    }
    return out;
  }

  static std::string list(const std::map<std::string, int>& g) {
    std::string s;
    for (const auto& [name, tag] : g) s += (s.empty() ? "" : ", ") + ("'" + name + "'");
    return s.empty() ? "(none)" : s;
  }

  std::vector<int> entities(int dim, const std::string& name,
                            const std::map<std::string, int>& present, const char* role) const {
    const auto it = present.find(name);
    if (it == present.end())
      fail(std::string(role) + " physical group '" + name + "' (" + std::to_string(dim) +
           "D) is not in the file; its " + std::to_string(dim) + "D groups are: " + list(present));
    std::vector<int> tags;
    gmsh::model::getEntitiesForPhysicalGroup(dim, it->second, tags);
    return tags;
  }
};

// Zone groups to read: the caller's, or write_msh's names that are present.
std::map<std::string, int> zone_groups_to_read(const MshFileSpec& spec,
                                               const std::map<std::string, int>& present) {
  if (!spec.zone_groups.empty() || !spec.edge_groups.empty()) return spec.zone_groups;
  std::map<std::string, int> out;
  for (const auto& [name, zone] : detail::default_zone_groups())
    if (present.count(name)) out[name] = zone;
  return out;
}

std::map<std::string, int> edge_groups_to_read(const MshFileSpec& spec,
                                               const std::map<std::string, int>& present) {
  if (!spec.zone_groups.empty() || !spec.edge_groups.empty()) return spec.edge_groups;
  std::map<std::string, int> out;
  for (const auto& [name, tag] : present)
    if (edge_tag_name(tag) == name) out[name] = tag;
  return out;
}

// Returns the element tags in their new (ascending) order.
std::vector<std::size_t> sort_triangles_by_tag(const std::vector<std::size_t>& tags, Mesh& m) {
  std::vector<std::size_t> order(tags.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return tags[a] < tags[b]; });
  Mesh s;
  for (std::size_t i : order) {
    s.triangles.push_back(m.triangles[i]);
    s.zone.push_back(m.zone[i]);
    s.fracture.push_back(m.fracture[i]);
  }
  m.triangles.swap(s.triangles), m.zone.swap(s.zone), m.fracture.swap(s.fracture);
  std::vector<std::size_t> sorted(tags.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = tags[order[k]];
  return sorted;
}

// gmsh 2.x writes an element once per physical group it is in (MSH 2.2 has
// one physical tag per element line), each copy under the next element
// number: a surface in a zone group and in the fracture group holds every
// triangle twice. Copies (the same three nodes in the same surface, from
// index `first` on) are one triangle; the lowest element number stands.
// The same nodes in two surfaces are two triangles, and check_folds
// refuses them.
void drop_copies(std::size_t first, std::vector<std::size_t>& tags, Mesh& m) {
  using Key = std::tuple<std::array<int, 3>, std::size_t, std::size_t>;  // nodes, tag, index
  std::vector<Key> keys;
  for (std::size_t i = first; i < m.triangles.size(); ++i) {
    std::array<int, 3> nodes = m.triangles[i];
    std::sort(nodes.begin(), nodes.end());
    keys.emplace_back(nodes, tags[i - first], i);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> copy(m.triangles.size() - first, 0);
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (std::get<0>(keys[k]) == std::get<0>(keys[k - 1])) copy[std::get<2>(keys[k]) - first] = 1;
  std::size_t kept = first;
  for (std::size_t i = first; i < m.triangles.size(); ++i) {
    if (copy[i - first]) continue;
    m.triangles[kept] = m.triangles[i], m.zone[kept] = m.zone[i];
    m.fracture[kept] = m.fracture[i], tags[kept - first] = tags[i - first];
    ++kept;
  }
  m.triangles.resize(kept), m.zone.resize(kept), m.fracture.resize(kept);
  tags.resize(kept - first);
}

// Returns the triangles' element tags, in the record's order.
std::vector<std::size_t> read_triangles(const Reader& r, const TagIndex& index, Mesh& m) {
  const auto present = r.groups(2);
  const auto zones = zone_groups_to_read(r.spec, present);
  if (zones.empty())
    r.fail(
        "no zone groups to read: name the 2D physical groups to use (zone_groups); the "
        "file's 2D groups are: " +
        Reader::list(present));
  std::set<int> fractured;
  std::string fracture_group = r.spec.fracture_group;
  if (fracture_group.empty() && present.count(detail::kFractureGroup))
    fracture_group = detail::kFractureGroup;
  if (!fracture_group.empty())
    for (int s : r.entities(2, fracture_group, present, "fracture")) fractured.insert(s);
  std::map<int, std::string> zone_of_surface;
  std::vector<std::size_t> element_tags;
  for (const auto& [name, zone] : zones) {
    for (int s : r.entities(2, name, present, "zone")) {
      if (!zone_of_surface.emplace(s, name).second)
        r.fail("surface " + std::to_string(s) + " is in zone groups '" + zone_of_surface[s] +
               "' and '" + name + "'; each surface may be in one zone group only");
      const bool flag = fracture_group.empty() ? zone == kRock : fractured.count(s) > 0;
      const std::size_t first = m.n_triangles();
      auto tags = detail::append_triangles(s, zone, flag ? 1 : 0, index, m);
      drop_copies(first, tags, m);
      element_tags.insert(element_tags.end(), tags.begin(), tags.end());
    }
  }
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [d, s] : surfaces) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes, s);
    if (!tags.empty() && !zone_of_surface.count(s))
      r.fail("triangle " + std::to_string(tags.front()) + " (surface " + std::to_string(s) +
             ") is in none of the zone groups read (" + Reader::list(zones) +
             "); every triangle must belong to one");
  }
  return sort_triangles_by_tag(element_tags, m);
}

// A line in two edge groups is an edge of each; its copies within one
// group (gmsh 2.x writes a line once per physical group, as triangles
// above) are one edge.
void read_edges(const Reader& r, const TagIndex& index, Mesh& m) {
  const auto present = r.groups(1);
  for (const auto& [name, tag] : edge_groups_to_read(r.spec, present))
    for (int c : r.entities(1, name, present, "edge")) detail::append_edges(c, tag, index, m);
  std::set<std::tuple<int, int, int>> seen;
  std::vector<TaggedEdge> kept;
  for (const TaggedEdge& e : m.edges)
    if (seen.emplace(std::min(e.a, e.b), std::max(e.a, e.b), e.tag).second) kept.push_back(e);
  m.edges.swap(kept);
}

// Each curve of the joint groups is one trace, numbered in the groups'
// order (a group's curves by tag; a curve in two groups is the first's).
// A joint acts through the crack element between the triangles on either
// side of it, so every joint line must be an edge of two triangles: a
// curve the surface mesh does not follow (not embedded) or on the outer
// boundary would act nowhere, without a word. Refused.
void read_joint_edges(const Reader& r, const TagIndex& index, Mesh& m) {
  const auto present = r.groups(1);
  std::vector<std::string> names = r.spec.joint_groups;
  const bool unnamed = r.spec.zone_groups.empty() && r.spec.edge_groups.empty();
  if (names.empty() && unnamed && present.count(detail::kJointGroup))
    names.push_back(detail::kJointGroup);  // write_msh's
  if (names.empty()) return;
  std::map<std::pair<int, int>, int> sides;  // triangle edge -> triangles
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++sides[std::minmax(t[k], t[(k + 1) % 3])];
  std::set<int> curves;
  std::set<std::pair<int, int>> seen;
  int trace = 0;
  for (const std::string& name : names) {
    std::size_t lines = 0;
    for (int c : r.entities(1, name, present, "joint")) {
      if (!curves.insert(c).second) continue;
      std::vector<std::size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(1, tags, nodes, c);
      lines += tags.size();
      const std::size_t before = m.joint_edges.size();
      for (std::size_t e = 0; e < tags.size(); ++e) {
        const int a = index(nodes[2 * e]), b = index(nodes[2 * e + 1]);
        const auto side = sides.find(std::minmax(a, b));
        if (a < 0 || b < 0 || side == sides.end() || side->second != 2)
          r.fail("joint physical group '" + name + "': line " + std::to_string(tags[e]) +
                 " (nodes " + std::to_string(nodes[2 * e]) + ", " +
                 std::to_string(nodes[2 * e + 1]) +
                 ") is not an edge between two triangles; a joint's lines must be interior "
                 "edges of the triangle mesh (in gmsh: embed the curve in the surface, "
                 "Curve{...} In Surface{...}, or fragment it with the surface)");
        if (seen.insert(std::minmax(a, b)).second) m.joint_edges.push_back({a, b, trace});
      }
      if (m.joint_edges.size() > before) ++trace;  // a curve of lines read before: none
    }
    if (lines == 0)
      r.fail("joint physical group '" + name +
             "' holds no 2-node lines; a joint group must hold the meshed lines of its traces");
  }
}

// Zero-area triangles cannot carry stress; clockwise ones are only
// numbered the other way round and are turned.
void check_areas(const Reader& r, const std::vector<std::size_t>& element_tags,
                 const std::vector<std::size_t>& tags, Mesh& m) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    const auto& v = m.triangles[t];
    double longest = 0;
    for (int k = 0; k < 3; ++k)
      longest = std::max(
          longest, std::hypot(m.x[v[k]] - m.x[v[(k + 1) % 3]], m.y[v[k]] - m.y[v[(k + 1) % 3]]));
    if (std::abs(signed_area(m, t)) <= 1e-12 * longest * longest)
      r.fail("triangle " + std::to_string(element_tags[t]) + " (nodes " +
             std::to_string(tags[v[0]]) + ", " + std::to_string(tags[v[1]]) + ", " +
             std::to_string(tags[v[2]]) +
             ") has zero area; every triangle must have positive area");
  }
  detail::orient_counter_clockwise(m);
}

// Turned counter-clockwise, two triangles side by side run through their
// shared edge in opposite directions. The same direction means they lie on
// one side of it, overlapping: the mesh folds (a node moved past the
// opposite edge), which no renumbering mends. So does an edge of three.
void check_folds(const Reader& r, const std::vector<std::size_t>& element_tags,
                 const std::vector<std::size_t>& tags, const Mesh& m) {
  struct Use {
    std::uint64_t key;
    bool forward;
    std::size_t tri;
  };
  std::vector<Use> uses;
  uses.reserve(3 * m.n_triangles());
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto a = std::uint64_t(m.triangles[t][k]),
                 b = std::uint64_t(m.triangles[t][(k + 1) % 3]);
      uses.push_back({(std::min(a, b) << 32) | std::max(a, b), a < b, t});
    }
  std::sort(uses.begin(), uses.end(), [](const Use& p, const Use& q) {
    return p.key != q.key ? p.key < q.key : p.tri < q.tri;
  });
  for (std::size_t i = 0; i + 1 < uses.size(); ++i) {
    if (uses[i].key != uses[i + 1].key) continue;
    const bool three = i + 2 < uses.size() && uses[i + 2].key == uses[i].key;
    if (!three && uses[i].forward != uses[i + 1].forward) continue;
    const auto a = std::size_t(uses[i].key >> 32), b = std::size_t(uses[i].key & 0xffffffffu);
    r.fail("triangles " + std::to_string(element_tags[uses[i].tri]) + " and " +
           std::to_string(element_tags[uses[i + 1].tri]) + " overlap at their edge (nodes " +
           std::to_string(tags[a]) + ", " + std::to_string(tags[b]) + "): the mesh folds over " +
           "itself there; triangles may share an edge only side by side");
  }
}

}  // namespace

namespace detail {

std::uint64_t check_before_gmsh(const MshFileSpec& spec) {
  return Reader{spec}.check_before_gmsh();
}

Mesh read_with_gmsh(const MshFileSpec& spec) {
  const Reader r{spec};
  GmshSession session(1);
  Mesh m;
  gmsh_guarded(spec.path, GmshFailure::kInput, [&] {
    r.open();
    r.check_element_types();
    const std::vector<std::size_t> node_tags = r.read_nodes(m);
    const TagIndex index(node_tags);
    const std::vector<std::size_t> triangle_tags = read_triangles(r, index, m);
    read_edges(r, index, m);
    read_joint_edges(r, index, m);
    check_areas(r, triangle_tags, node_tags, m);
    check_folds(r, triangle_tags, node_tags, m);
  });
  compact_vertices(m);
  return m;
}

Mesh read_msh_in_process(const MshFileSpec& spec) {
  check_before_gmsh(spec);
  return read_with_gmsh(spec);
}

}  // namespace detail

// The checks before gmsh here; gmsh's read in a child process, so that a
// crash of gmsh's reader on a malformed file is an InputError, not the
// end of the run (msh_child.hpp).
Mesh read_msh(const MshFileSpec& spec) {
  const std::uint64_t size = detail::check_before_gmsh(spec);
  std::set<int> zones;
  if (!spec.zone_groups.empty() || !spec.edge_groups.empty())
    for (const auto& [name, zone] : spec.zone_groups) zones.insert(zone);
  else
    for (const auto& [name, zone] : detail::default_zone_groups()) zones.insert(zone);
  return detail::read_in_child(spec.path, detail::record_limits(size, std::move(zones)),
                               [&] { return detail::read_with_gmsh(spec); });
}

}  // namespace rockfdem::mesh
