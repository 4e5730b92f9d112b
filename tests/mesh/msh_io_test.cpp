// .msh files: a meshed tunnel written and read back unchanged, a hand-written
// file read with named groups, and malformed files each refused with an
// InputError that names the file.
#include "rockfdem/mesh/msh_io.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <tuple>

#include "msh_test_files.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "scratch_dir.hpp"

namespace rockfdem::mesh {
namespace {

std::string temp_path(const std::string& name) { return test::scratch_path(name); }

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(MshRoundTrip, written_tunnel_reads_back_identical) {
  MeshSpec s;
  s.tunnel.shape = TunnelShape::kHorseshoe;
  s.tunnel.span = 6, s.tunnel.height = 5, s.tunnel.lining_thickness = 0.3;
  s.tunnel.fracture_zone = 1;
  s.domain = {30, 30, 0, 0};
  s.size.size_near = 0.4, s.size.size_far = 3;
  s.joints = {{-10, 4, 10, 6}, {-8, -10, -2, 10}};  // crossing; one across the opening
  Mesh m = build_mesh(s);
  ASSERT_GT(m.joint_edges.size(), 20u);
  m.edges.push_back({m.triangles[0][0], m.triangles[0][1], 101});  // a user tag
  const std::string path = temp_path("rockfdem_roundtrip.msh");
  write_msh(m, path);
  const Mesh r = read_msh({path, {}, {}, "", {}});
  // gmsh writes coordinates with 16 significant digits: equal to rounding.
  ASSERT_EQ(r.n_vertices(), m.n_vertices());
  for (std::size_t v = 0; v < m.n_vertices(); ++v) {
    ASSERT_NEAR(r.x[v], m.x[v], 1e-15 * 15) << "vertex " << v;
    ASSERT_NEAR(r.y[v], m.y[v], 1e-15 * 15) << "vertex " << v;
  }
  EXPECT_EQ(r.triangles, m.triangles);
  EXPECT_EQ(r.zone, m.zone);
  EXPECT_EQ(r.fracture, m.fracture);
  ASSERT_EQ(r.edges.size(), m.edges.size());
  std::multiset<std::tuple<int, int, int>> a, b;
  for (const TaggedEdge& e : m.edges) a.insert({e.a, e.b, e.tag});
  for (const TaggedEdge& e : r.edges) b.insert({e.a, e.b, e.tag});
  EXPECT_EQ(a, b);
  // The joints: each trace a curve of "joints", read back with its number.
  std::multiset<std::tuple<int, int, int>> ja, jb;
  for (const JointEdge& e : m.joint_edges) ja.insert({e.a, e.b, e.trace});
  for (const JointEdge& e : r.joint_edges) jb.insert({e.a, e.b, e.trace});
  EXPECT_EQ(ja, jb);
}

// The same tunnel written by gmsh as MSH 2.2 (Mesh.SaveAll = 0, as gmsh 2.x
// wrote every file): each triangle of the fracture zone comes twice, once
// under 'rock' and once under 'fracture', each curve's lines once per edge
// group. It reads as the MSH 4.1 file does: the same triangles, zones,
// fracture flags and edges (it was refused as "triangles ... overlap").
TEST(MshRoundTrip, gmsh_msh22_with_a_triangle_per_physical_group_reads_as_msh41) {
  const std::string v41 = temp_path("rockfdem_v41.msh"), v22 = temp_path("rockfdem_v22.msh");
  write_msh(build_mesh(test::lined_circular_tunnel()), v41);
  test::gmsh_rewrite(v41, v22, 2.2);
  std::ifstream in(v22);
  std::string line;
  std::getline(in, line), std::getline(in, line);
  ASSERT_EQ(line, "2.2 0 8");
  const Mesh a = read_msh({v41, {}, {}, "", {}}), b = read_msh({v22, {}, {}, "", {}});
  ASSERT_GT(std::count(a.fracture.begin(), a.fracture.end(), 1), 0);
  EXPECT_EQ(b.x, a.x);
  EXPECT_EQ(b.y, a.y);
  // gmsh numbers the copies anew, so the triangles come in another order.
  const auto triangles = [](const Mesh& m) {
    std::multiset<std::tuple<std::array<int, 3>, int, int>> out;
    for (std::size_t t = 0; t < m.n_triangles(); ++t) {
      std::array<int, 3> v = m.triangles[t];
      std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());  // same turn
      out.insert({v, m.zone[t], m.fracture[t]});
    }
    return out;
  };
  EXPECT_EQ(b.n_triangles(), a.n_triangles());
  EXPECT_TRUE(triangles(b) == triangles(a));
  std::multiset<std::tuple<int, int, int>> ea, eb;
  for (const TaggedEdge& e : a.edges) ea.insert({std::min(e.a, e.b), std::max(e.a, e.b), e.tag});
  for (const TaggedEdge& e : b.edges) eb.insert({std::min(e.a, e.b), std::max(e.a, e.b), e.tag});
  EXPECT_EQ(eb, ea);
}

TEST(MshRoundTrip, unwritable_path_is_an_error_and_leaves_nothing) {
  Mesh m;
  m.x = {0, 1, 0}, m.y = {0, 0, 1};
  m.triangles = {{0, 1, 2}}, m.zone = {kRock}, m.fracture = {0};
  const std::string path = temp_path("rockfdem_no_such_dir/mesh.msh");
  EXPECT_THROW(write_msh(m, path), std::runtime_error);
  EXPECT_FALSE(std::ifstream(path).good());
}

TEST(MshRoundTrip, named_groups_choose_zones_and_edges) {
  MeshSpec s;
  s.kind = ModelKind::kUcs;
  s.size.size_near = 0.01;
  const Mesh m = build_mesh(s);
  const std::string path = temp_path("rockfdem_named.msh");
  write_msh(m, path);
  const Mesh r = read_msh({path, {{"rock", kCore}}, {{"top", 42}}, "", {}});
  EXPECT_EQ(r.n_triangles(), m.n_triangles());
  for (int z : r.zone) EXPECT_EQ(z, kCore);
  EXPECT_FALSE(r.edges.empty());
  for (const TaggedEdge& e : r.edges) EXPECT_EQ(e.tag, 42);
}

// A unit square of two triangles, in the MSH 2.2 format a user might write;
// `nodes` and `elements` are the sections' bodies.
std::string square_msh(const std::string& nodes, const std::string& elements) {
  return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         "$PhysicalNames\n2\n1 1 \"base\"\n2 7 \"granite\"\n$EndPhysicalNames\n"
         "$Nodes\n" +
         nodes + "$EndNodes\n$Elements\n" + elements + "$EndElements\n";
}
const std::string kNodes = "4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n";
const std::string kElements = "3\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 3\n3 2 2 7 1 1 3 4\n";
const MshFileSpec kGroups{"", {{"granite", kRock}}, {{"base", kBottom}}, "", {}};

Mesh read_text(const std::string& name, const std::string& text) {
  MshFileSpec spec = kGroups;
  spec.path = temp_path(name);
  write_text(spec.path, text);
  return read_msh(spec);
}

TEST(MshUserFile, well_formed_square_reads) {
  const Mesh m = read_text("rockfdem_square.msh", square_msh(kNodes, kElements));
  EXPECT_EQ(m.n_triangles(), 2u);
  EXPECT_EQ(m.n_vertices(), 4u);
  ASSERT_EQ(m.edges.size(), 1u);
  EXPECT_EQ(m.edges[0].tag, kBottom);
  EXPECT_EQ(m.fracture, (std::vector<std::uint8_t>{1, 1}));  // no fracture group: all rock
}

TEST(MshUserFile, clockwise_triangle_is_turned) {
  const Mesh m =
      read_text("rockfdem_cw.msh",
                square_msh(kNodes, "3\n1 1 2 1 1 1 2\n2 2 2 7 1 1 3 2\n3 2 2 7 1 1 3 4\n"));
  for (std::size_t t = 0; t < m.n_triangles(); ++t) EXPECT_NEAR(signed_area(m, t), 0.5, 1e-15);
}

// gmsh 2.x writes an element once per physical group it is in (MSH 2.2 has
// one physical tag per element line): a surface in the zone group
// 'granite' and the group 'fracture' gives every triangle twice, same
// nodes, same surface, the second copy under the next element number (and
// a curve in two edge groups each line twice). That is one mesh of two
// triangles, every one in the fracture zone, not a mesh folded over
// itself (which it was refused as).
TEST(MshUserFile, triangle_written_once_per_physical_group_reads_once) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
      "$PhysicalNames\n4\n1 1 \"base\"\n1 2 \"ground\"\n2 7 \"granite\"\n"
      "2 9 \"fracture\"\n$EndPhysicalNames\n$Nodes\n" +
      kNodes +
      "$EndNodes\n$Elements\n6\n1 1 2 1 1 1 2\n2 1 2 2 1 1 2\n3 2 2 7 1 1 2 3\n"
      "4 2 2 9 1 1 2 3\n5 2 2 7 1 1 3 4\n6 2 2 9 1 1 3 4\n$EndElements\n";
  MshFileSpec spec{temp_path("rockfdem_per_group.msh"),
                   {{"granite", kRock}},
                   {{"base", kBottom}, {"ground", kTop}},
                   "fracture",
                   {}};
  write_text(spec.path, text);
  const Mesh m = read_msh(spec);
  EXPECT_EQ(m.n_triangles(), 2u);
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(m.fracture, (std::vector<std::uint8_t>{1, 1}));
  EXPECT_EQ(m.zone, (std::vector<int>{kRock, kRock}));
  ASSERT_EQ(m.edges.size(), 2u);  // the line once per edge group it is in
  std::set<int> tags{m.edges[0].tag, m.edges[1].tag};
  EXPECT_EQ(tags, (std::set<int>{kBottom, kTop}));
  for (std::size_t t = 0; t < m.n_triangles(); ++t) EXPECT_NEAR(signed_area(m, t), 0.5, 1e-15);
}

// The error must be an InputError naming the file and containing `detail`.
void expect_refused(const std::string& name, const std::string& text, const std::string& detail,
                    MshFileSpec spec = kGroups) {
  spec.path = temp_path(name);
  write_text(spec.path, text);
  try {
    read_msh(spec);
    ADD_FAILURE() << name << " was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(spec.path), std::string::npos) << what;
    EXPECT_NE(what.find(detail), std::string::npos) << what;
    std::cout << "  refused: " << what << "\n";
  }
}

TEST(MshUserFile, truncated_file_is_refused) {
  const std::string full = square_msh(kNodes, kElements);
  expect_refused("rockfdem_truncated.msh", full.substr(0, full.find("2 1 0 0") + 3), "");
}

TEST(MshUserFile, nan_coordinate_is_refused) {
  expect_refused("rockfdem_nan.msh",
                 square_msh("4\n1 0 0 0\n2 1 0 0\n3 nan 1 0\n4 0 1 0\n", kElements), "node 3");
}

// z is dropped: a node off the mesh's plane (here z = 5 among z = 0) would
// be moved onto it without a word. Refused naming the node and both z; a
// mesh whose every node has one z (a plane parallel to x-y) reads exactly.
TEST(MshUserFile, node_off_the_plane_is_refused) {
  expect_refused("rockfdem_z.msh", square_msh("4\n1 0 0 0\n2 1 0 0\n3 1 1 5\n4 0 1 0\n", kElements),
                 "node 3 has z = 5 and node 1 z = 0: the mesh is not flat; allowed: every node "
                 "at one z");
  const Mesh m = read_text("rockfdem_z5.msh",
                           square_msh("4\n1 0 0 5\n2 1 0 5\n3 1 1 5\n4 0 1 5\n", kElements));
  EXPECT_EQ(m.n_triangles(), 2u);
  EXPECT_EQ(m.x, (std::vector<double>{0, 1, 1, 0}));
}

TEST(MshUserFile, duplicate_node_is_refused) {
  expect_refused("rockfdem_dup.msh",
                 square_msh("5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 1 1 0\n",
                            "3\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 5\n3 2 2 7 1 1 3 4\n"),
                 "same position");
}

TEST(MshUserFile, node_tag_given_twice_is_refused) {
  expect_refused("rockfdem_duptag.msh",
                 square_msh("5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n3 0.5 0.5 0\n", kElements),
                 "node");
}

TEST(MshUserFile, degenerate_triangle_is_refused) {
  expect_refused(
      "rockfdem_flat.msh",
      square_msh("5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0 0\n",
                 "4\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 3\n3 2 2 7 1 1 3 4\n4 2 2 7 1 1 5 2\n"),
      "zero area");
}

// Node 3 moved past the diagonal 1-3's far side: triangle 1-3-4 turns
// clockwise and, turned back, lies over triangle 1-2-3. Renumbering cannot
// mend that (it did silently before); the file is refused naming both.
TEST(MshUserFile, folded_mesh_is_refused) {
  expect_refused("rockfdem_fold.msh",
                 square_msh("4\n1 0 0 0\n2 1 0 0\n3 -0.5 0.5 0\n4 0 1 0\n", kElements),
                 "overlap at their edge (nodes 1, 3)");
}

// Two triangles with the same nodes in different surfaces are two
// triangles over one another, not copies: still refused.
TEST(MshUserFile, same_triangle_in_two_surfaces_is_refused) {
  expect_refused("rockfdem_two_surfaces.msh",
                 square_msh(kNodes,
                            "4\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 3\n3 2 2 7 1 1 3 4\n"
                            "4 2 2 7 2 1 2 3\n"),
                 "overlap");
}

TEST(MshUserFile, quadrangle_is_refused) {
  expect_refused("rockfdem_quad.msh", square_msh(kNodes, "1\n1 3 2 7 1 1 2 3 4\n"), "gmsh type 3");
}

// A group's name comes from the file: its control bytes (an ESC sequence
// that would clear the screen) are shown as escapes in the message.
TEST(MshUserFile, control_bytes_of_a_group_name_are_escaped_in_the_message) {
  std::string text = square_msh(kNodes, kElements);
  text.replace(text.find("granite"), 7, "gran\x1b[2J\x7fite");
  expect_refused("rockfdem_esc.msh", text, "'gran\\x1b[2J\\x7fite'");
  MshFileSpec spec = kGroups;
  spec.path = temp_path("rockfdem_esc.msh");
  try {
    read_msh(spec);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos) << e.what();
  }
}

TEST(MshUserFile, missing_physical_group_is_refused) {
  MshFileSpec spec = kGroups;
  spec.zone_groups = {{"basalt", kRock}};
  expect_refused("rockfdem_nogroup.msh", square_msh(kNodes, kElements), "'basalt'", spec);
}

TEST(MshUserFile, triangle_outside_every_zone_group_is_refused) {
  expect_refused("rockfdem_unzoned.msh",
                 square_msh(kNodes, "3\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 3\n3 2 2 8 2 1 3 4\n"),
                 "none of the zone groups");
}

// Found by tests/fuzz/fuzz_msh: gmsh 4.8's MSH 4 reader looks node tags up
// as int, so an element naming node 180000000000001 or -7 crashed it (SEGV in
// GModel::getMeshVertexByTag / gmsh::model::mesh::getElements). Such files
// are now refused before gmsh reads them.
std::string msh4_triangle(const std::string& third_node) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n"
         "0 0 0\n1 0 0\n0 1 0\n$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 " +
         third_node + "\n$EndElements\n";
}

TEST(MshUserFile, node_tag_beyond_int_is_refused) {
  expect_refused("rockfdem_bigtag.msh", msh4_triangle("180000000000001"),
                 "line 17: '180000000000001'");
}

TEST(MshUserFile, negative_node_tag_is_refused) {
  expect_refused("rockfdem_negtag.msh", msh4_triangle("-7"), "from 0 to 2147483647");
}

// A count in a section header is checked against what the rest of the file
// can hold before gmsh sees it: gmsh 4.8 allocates by the declared count
// first, so $Nodes claiming 999,999,999,999 nodes ended in std::bad_alloc
// (exit 1, no file named), and an MSH 4 total below its blocks' counts
// made it write past its allocation.
TEST(MshUserFile, node_count_beyond_the_file_is_refused) {
  expect_refused("rockfdem_hugenodes.msh",
                 square_msh("999999999999\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n", kElements),
                 "the $Nodes section declares 999999999999 nodes, but the");
}

TEST(MshUserFile, element_count_beyond_the_file_is_refused) {
  expect_refused("rockfdem_hugeelements.msh",
                 square_msh(kNodes, "88888888888\n1 1 2 1 1 1 2\n2 2 2 7 1 1 2 3\n"),
                 "the $Elements section declares 88888888888 elements");
}

TEST(MshUserFile, msh4_counts_beyond_the_file_are_refused) {
  const std::string good = msh4_triangle("3");
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  expect_refused("rockfdem_msh4_total.msh",
                 with("$Nodes\n1 3 1 3\n", "$Nodes\n1 999999999999 1 3\n"),
                 "the $Nodes section declares 999999999999 nodes");
  expect_refused("rockfdem_msh4_block.msh", with("2 1 0 3\n", "2 1 0 77777777777\n"),
                 "block 1 of the $Nodes section declares 77777777777 nodes");
  expect_refused("rockfdem_msh4_sum.msh", with("$Nodes\n1 3 1 3\n", "$Nodes\n1 2 1 3\n"),
                 "the $Nodes section declares 2 nodes, but its 1 blocks hold 3");
  expect_refused("rockfdem_msh4_elements.msh",
                 with("$Elements\n1 1 1 1\n", "$Elements\n1 5555555555 1 1\n"),
                 "the $Elements section declares 5555555555 elements");
  expect_refused("rockfdem_msh4_entities.msh",
                 with("$Nodes\n", "$Entities\n0 0 444444444444 0\n$EndEntities\n$Nodes\n"),
                 "the $Entities section declares 444444444444 entity surfaces");
  expect_refused("rockfdem_msh4_negative.msh", with("2 1 0 3\n", "2 1 0 -3\n"),
                 "declares -3 nodes");
}

// Binary .msh files, built byte by byte: the same unit square of two
// triangles in MSH 2.2 (counts as text lines, records binary) and MSH 4.1
// (counts binary too). gmsh 4.8 allocates by their declared counts as well.
template <class T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}
const char kBinaryHead2[] = "$MeshFormat\n2.2 1 8\n";
const char kBinaryHead4[] = "$MeshFormat\n4.1 1 8\n";
const char kBinaryNames[] =
    "\n$EndMeshFormat\n$PhysicalNames\n2\n1 1 \"base\"\n2 7 \"granite\"\n$EndPhysicalNames\n";
const double kSquare[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

std::string binary_msh2(const std::string& node_count, const std::string& element_count) {
  std::string s = kBinaryHead2;
  put(s, 1);
  s += kBinaryNames + ("$Nodes\n" + node_count + "\n");
  for (int v = 0; v < 4; ++v)
    put(s, v + 1), put(s, kSquare[v][0]), put(s, kSquare[v][1]), put(s, 0.0);
  s += "\n$EndNodes\n$Elements\n" + element_count + "\n";
  for (int h : {1, 1, 2}) put(s, h);  // type, count, tags: one line
  for (int w : {1, 1, 1, 1, 2}) put(s, w);
  for (int h : {2, 2, 2}) put(s, h);  // two triangles
  for (int w : {2, 7, 1, 1, 2, 3, 3, 7, 1, 1, 3, 4}) put(s, w);
  return s + "\n$EndElements\n";
}

// An MSH 4.1 entity: tag, bounding box, one physical tag, its boundary.
void put_entity(std::string& s, int physical, std::initializer_list<int> boundary) {
  put(s, 1);
  for (double b : {0.0, 0.0, 0.0, 1.0, 1.0, 0.0}) put(s, b);
  put(s, std::size_t(1)), put(s, physical), put(s, boundary.size());
  for (int b : boundary) put(s, b);
}

std::string binary_msh4(std::size_t node_count, std::size_t block_nodes,
                        std::size_t element_count) {
  std::string s = kBinaryHead4;
  put(s, 1);
  s += kBinaryNames + std::string("$Entities\n");
  for (std::size_t n : {0, 1, 1, 0}) put(s, n);
  put_entity(s, 1, {});
  put_entity(s, 7, {1});
  s += "\n$EndEntities\n$Nodes\n";
  for (std::size_t n : {std::size_t(1), node_count, std::size_t(1), std::size_t(4)}) put(s, n);
  put(s, 2), put(s, 1), put(s, 0), put(s, block_nodes);
  for (std::size_t v = 1; v <= 4; ++v) put(s, v);
  for (const auto& p : kSquare) put(s, p[0]), put(s, p[1]), put(s, 0.0);
  s += "\n$EndNodes\n$Elements\n";
  for (std::size_t n : {std::size_t(2), element_count, std::size_t(1), std::size_t(3)}) put(s, n);
  put(s, 1), put(s, 1), put(s, 1), put(s, std::size_t(1));
  for (std::size_t w : {1, 1, 2}) put(s, w);
  put(s, 2), put(s, 1), put(s, 2), put(s, std::size_t(2));
  for (std::size_t w : {2, 1, 2, 3, 3, 1, 3, 4}) put(s, w);
  return s + "\n$EndElements\n";
}

TEST(MshUserFile, binary_squares_read) {
  for (const std::string& text : {binary_msh2("4", "3"), binary_msh4(4, 4, 3)}) {
    const Mesh m = read_text("rockfdem_binary.msh", text);
    EXPECT_EQ(m.n_triangles(), 2u);
    EXPECT_EQ(m.n_vertices(), 4u);
    ASSERT_EQ(m.edges.size(), 1u);
    EXPECT_EQ(m.edges[0].tag, kBottom);
  }
}

TEST(MshUserFile, binary_counts_beyond_the_file_are_refused) {
  expect_refused("rockfdem_bin2_nodes.msh", binary_msh2("999999999999", "3"),
                 "the $Nodes section declares 999999999999 nodes, but the");
  expect_refused("rockfdem_bin2_elements.msh", binary_msh2("4", "88888888888"),
                 "the $Elements section declares 88888888888 elements, but the");
  expect_refused("rockfdem_bin4_nodes.msh", binary_msh4(999999999999, 4, 3),
                 "the $Nodes section declares 999999999999 nodes, but the");
  expect_refused("rockfdem_bin4_block.msh", binary_msh4(4, 77777777777, 3),
                 "block 1 of the $Nodes section declares 77777777777 nodes");
  expect_refused("rockfdem_bin4_sum.msh", binary_msh4(3, 4, 3),
                 "the $Nodes section declares 3 nodes, but its 1 blocks hold 4");
  expect_refused("rockfdem_bin4_elements.msh", binary_msh4(4, 4, 5555555555),
                 "the $Elements section declares 5555555555 elements");
}

// Found by flipping bits of a binary MSH 4.1: the top
// bit of an entity's count of physical groups makes gmsh 4.8 throw
// std::length_error from its vector (it was exit 1, an unexpected error).
TEST(MshUserFile, binary_entity_count_beyond_any_array_is_refused) {
  std::string s = binary_msh4(4, 4, 3);
  // The first entity's physical count: after the 4 totals, its tag and box.
  const std::size_t at = s.find("$Entities\n") + 10 + 4 * 8 + 4 + 6 * 8;
  ASSERT_EQ(s[at], 1);
  s[at + 7] = char(0x80);
  expect_refused("rockfdem_bin4_physicals.msh", s,
                 "gmsh could not allocate what a count in the file asks for");
}

// Found by tests/fuzz/fuzz_msh: gmsh::open reads a file that does not start
// as a mesh as a .geo script, and a script can run shell commands. Such a
// file is refused before gmsh sees it, and its command never runs.
TEST(MshUserFile, geo_script_is_refused_and_never_run) {
  const std::string marker = temp_path("rockfdem_systemcall_ran");
  std::remove(marker.c_str());
  expect_refused("rockfdem_script.msh", "SystemCall \"touch " + marker + "\";\n",
                 "does not start with $MeshFormat");
  EXPECT_FALSE(std::ifstream(marker).good()) << "the script's command ran";
}

// Bounded reads. A 3 GB sparse file was read for 43 s
// and 7.5 GB before "does not start with $MeshFormat" (its "first line"
// had no end), and a valid mesh with 2 GB appended was read for 22.7 s and
// 4.6 GB, then accepted. The start is now told from 64 bytes, the end from
// the last 4 KiB, and an ASCII file's size is bounded by its declared
// counts, each before gmsh reads the file. The sparse files here take no
// disk space; each refusal must come within a second.
class MshBounded : public ::testing::Test {
 protected:
  // `text`, then `extra` bytes of zeros (a hole), then `end`.
  static std::string sparse(const std::string& name, const std::string& text, std::uint64_t extra,
                            const std::string& end = "") {
    const std::string path = temp_path(name);
    {
      std::ofstream out(path, std::ios::binary);
      out << text;
    }
    if (::truncate(path.c_str(), off_t(text.size() + extra)) != 0) ADD_FAILURE() << "truncate";
    std::ofstream(path, std::ios::binary | std::ios::app) << end;
    return path;
  }
  static std::string refusal(const std::string& path) {
    MshFileSpec spec = kGroups;
    spec.path = path;
    const auto t0 = std::chrono::steady_clock::now();
    std::string what;
    try {
      read_msh(spec);
    } catch (const InputError& e) {
      what = e.what();
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(s, 1.0) << path << ": refused after " << s << " s";
    std::remove(path.c_str());
    return what;
  }
};

TEST_F(MshBounded, a_huge_file_that_is_not_a_mesh_is_refused_from_its_first_bytes) {
  const std::string what = refusal(sparse("rockfdem_sparse.msh", "", std::uint64_t(3) << 30));
  EXPECT_NE(what.find("does not start with $MeshFormat"), std::string::npos) << what;
}

TEST_F(MshBounded, data_after_the_last_section_is_refused) {
  const std::string mesh = square_msh(kNodes, kElements);
  const std::string what = refusal(sparse("rockfdem_trailing.msh", mesh, std::uint64_t(2) << 30));
  EXPECT_NE(what.find("does not end with a section's end line ($End...): its last 4096 bytes "
                      "hold none"),
            std::string::npos)
      << what;
  const std::string text = refusal(sparse("rockfdem_trailing_text.msh", mesh, 0, "junk\n"));
  EXPECT_NE(text.find("holds 6 bytes after its last section's end line ($EndElements)"),
            std::string::npos)
      << text;
}

TEST_F(MshBounded, a_file_beyond_its_declared_counts_is_refused) {
  // 2 GB hidden in a comment section before the mesh's end: the end is a
  // section's, but 4 nodes and 3 elements take at most 1 MiB + 7 KiB.
  const std::string mesh = square_msh(kNodes, kElements);
  const std::string what = refusal(sparse("rockfdem_oversized.msh", mesh + "$Comments\n",
                                          std::uint64_t(2) << 30, "\n$EndComments\n"));
  EXPECT_NE(what.find(" bytes, more than the 1055744 its 7 declared nodes and elements can "
                      "take (1 MiB + 1 KiB each)"),
            std::string::npos)
      << what;
}

TEST_F(MshBounded, a_fifo_or_a_directory_is_refused_unread) {
  const std::string fifo = temp_path("rockfdem_fifo.msh");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(refusal(fifo).find("is not a regular file"), std::string::npos);
  const std::string dir = temp_path("rockfdem_dir.msh");
  ::mkdir(dir.c_str(), 0700);
  EXPECT_NE(refusal(dir).find("is not a regular file"), std::string::npos);
  ::rmdir(dir.c_str());
}

// Two inputs tests/fuzz/fuzz_msh found corrupting gmsh 4.8's heap (an
// MSH 4.1 $Nodes block cut off and followed by MSH 2 text; an invalid and
// a double free in gmsh::finalize, after the read): each ends with text
// after its last section's end line, and is refused before gmsh reads it.
TEST(MshUserFile, fuzzer_heap_corruptions_are_refused_before_gmsh) {
  for (const char* name :
       {"gmsh48_msh4_nodes_heap_corruption.msh", "gmsh48_msh4_double_free.msh"}) {
    MshFileSpec spec = kGroups;
    spec.path = std::string(ROCKFDEM_FUZZ_REFUSED_DIR) + "/" + name;
    try {
      read_msh(spec);
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(spec.path + ": holds "), std::string::npos) << what;
      EXPECT_NE(what.find("bytes after its last section's end line"), std::string::npos) << what;
    }
  }
}

TEST(MshUserFile, missing_file_is_refused) {
  MshFileSpec spec = kGroups;
  spec.path = temp_path("rockfdem_no_such_file.msh");
  EXPECT_THROW(read_msh(spec), InputError);
}

}  // namespace
}  // namespace rockfdem::mesh
