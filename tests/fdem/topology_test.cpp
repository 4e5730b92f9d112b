// Engine nodes and crack elements from a mesh with and without fracture
// zones, the node -> vertex map, input validation, and the initial
// displacement hand-off.
#include <gtest/gtest.h>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

/// A rock rectangle of nx by ny unit cells.
ModelInput rock_rectangle(int nx, int ny) {
  RectangleSpec spec;
  spec.width = nx;
  spec.height = ny;
  spec.nx = nx;
  spec.ny = ny;
  return structured_rectangle(spec, test::rock());
}

// Two cells: the left one without fracture (its two triangles share nodes),
// the right one with fracture (own nodes per triangle). Crack elements: the
// middle edge and the right cell's diagonal, not the left cell's diagonal.
TEST(Topology, nodes_split_only_where_fracture_is_allowed) {
  ModelInput in = rock_rectangle(2, 1);
  in.fracture = {0, 0, 1, 1};
  Engine e(in);
  EXPECT_EQ(e.n_nodes(), 4u + 6u);
  EXPECT_EQ(e.n_cracks(), 2u);
  std::vector<int> per_vertex(in.x.size(), 0);
  for (int v : e.node_vertex()) ++per_vertex[v];
  EXPECT_EQ(per_vertex[0], 1);  // (0, 0): left cell only
  EXPECT_EQ(per_vertex[1], 2);  // (1, 0): shared node + one fracture triangle
  EXPECT_EQ(per_vertex[4], 3);  // (1, 1): shared node + both fracture triangles
  EXPECT_EQ(per_vertex[2], 2);  // (2, 0): both fracture triangles
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto n = e.crack_nodes(c);
    // Facing nodes sit at the same mesh vertex (0 faces 3, 1 faces 2).
    EXPECT_EQ(e.node_vertex()[n[0]], e.node_vertex()[n[3]]);
    EXPECT_EQ(e.node_vertex()[n[1]], e.node_vertex()[n[2]]);
  }
}

// The triangles a crack element joins are derived from the node incidence,
// not stored: on a mesh with a shared-node zone beside a fracture zone (so
// that one face's nodes are shared by several triangles), each face's
// triangle holds that face's two nodes, and the two differ. The middle
// column's triangles without fracture, the rest with.
TEST(Topology, crack_triangles_hold_their_faces_nodes) {
  ModelInput in = rock_rectangle(3, 2);
  in.fracture.assign(in.triangles.size(), 1);
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    double cx = 0;
    for (int v : in.triangles[t]) cx += in.x[v] / 3;
    if (cx > 1 && cx < 2) in.fracture[t] = 0;
  }
  Engine e(in);
  ASSERT_GT(e.n_cracks(), 0u);
  auto holds = [&](int t, int a, int b) {
    const auto n = e.triangle_nodes(std::size_t(t));
    auto has = [&](int x) { return n[0] == x || n[1] == x || n[2] == x; };
    return has(a) && has(b);
  };
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto n = e.crack_nodes(c);
    const auto t = e.crack_triangles(c);
    EXPECT_NE(t[0], t[1]) << "crack " << c;
    EXPECT_TRUE(holds(t[0], n[0], n[1])) << "crack " << c << ": first face";
    EXPECT_TRUE(holds(t[1], n[3], n[2])) << "crack " << c << ": second face";
  }
}

TEST(Topology, bad_input_is_refused_with_a_clear_message) {
  ModelInput in = test::two_triangles(0.01, test::rock());
  in.triangles[1] = {0, 3, 1};  // clockwise
  try {
    Engine e(in);
    FAIL() << "clockwise triangle accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("triangle 1 is not counter-clockwise"),
              std::string::npos)
        << err.what();
  }
  in = test::two_triangles(0.01, test::rock());
  in.material = {0, 3};
  EXPECT_THROW(Engine{in}, InputError);
  in = test::two_triangles(0.01, test::rock());
  in.materials[0].poisson = 0.5;
  EXPECT_THROW(Engine{in}, InputError);
}

// The implicit stage's displacement moves the nodes without straining them
// (its stress comes as initial stress); displacement() includes it.
TEST(Topology, initial_displacement_moves_nodes_without_stress) {
  ModelInput in = test::two_triangles(0.01, test::rock());
  in.initial_displacement = {{1e-4, 0}, {2e-4, 1e-4}, {0, -1e-4}, {1e-4, 2e-4}};
  Engine e(in);
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const int v = e.node_vertex()[n];
    EXPECT_NEAR(e.displacement(n)[0], in.initial_displacement[v][0], 1e-15);
    EXPECT_NEAR(e.displacement(n)[1], in.initial_displacement[v][1], 1e-15);
  }
  for (std::size_t t = 0; t < 2; ++t)
    for (double s : e.triangle_stress(t)) EXPECT_NEAR(s, 0.0, 1e-12 * in.materials[0].young);
}

}  // namespace
}  // namespace rockfdem::fdem
