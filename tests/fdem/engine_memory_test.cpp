// What the engine holds per element: the fracturing UCS's arrays, counted
// from the model's sizes (docs/engine.md, "Memory per triangle"), against
// memory_bytes(). A new per-element array, or one of the derived ones
// (1/m, nodes 3 and 2's crack forces, per-node mesh positions, a zero
// external force, the crack elements' triangles) stored again, shows here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

TEST(EngineMemory, fracturing_ucs_holds_its_arrays_and_at_most_500_B_per_triangle) {
  Material m = test::rock();
  m.damping_ratio = 0.1;  // the energy ledger's viscous term, as in bench_ucs
  ModelInput in = ucs_specimen(ucs_grid(0.02, 0.04, 1600), m, 2.0);
  Engine e(in);
  e.run(10);
  const double nt = double(e.n_triangles()), nc = double(e.n_cracks()), nn = double(e.n_nodes());
  const std::vector<int>& vertex = e.node_vertex();
  const double nv = double(*std::max_element(vertex.begin(), vertex.end()) + 1);
  // Per node: position, velocity 16 each, mass (single precision), vertex,
  // CSR start 4 each; per element corner a 4-byte slot entry; per mesh vertex its
  // position 16 and the vertex -> nodes CSR (4 per node, 4 per vertex).
  const double nodes = nn * 44 + (3 * nt + 4 * nc) * 4 + nv * 20 + nn * 4;
  // Per triangle: nodes 12, F0^-1 32, area, eta, alpha 4 each (single
  // precision), the last viscous stress 12, material 2, active 1.
  const double tris = nt * 71;
  // Per crack element: nodes 16, damages 12 (single precision), material 2,
  // state, mode, active 1 each, broken step 4 (its triangles come from the
  // slots).
  const double cracks = nc * 37;
  const double slots = (3 * nt + 2 * nc) * 16;  // two per crack element
  const double expected = nodes + tris + cracks + slots;
  const double bytes = double(e.memory_bytes());
  // Above the per-element arrays only the block sums (56 B per 512 nodes,
  // 8 B per 4096 elements), the crack pass's marks (1 B per 128 crack
  // elements), the CSR ends and the list of the platens' nodes (4 B
  // each): 0.1% here.
  EXPECT_GE(bytes, expected);
  EXPECT_LE(bytes, expected * 1.002) << "bytes " << bytes << ", arrays " << expected;
  EXPECT_LE(bytes / nt, 500.0) << "cracks per triangle " << nc / nt;
}

// Tractions on a block without gravity: the external forces are held for
// the loaded nodes only (an index and two doubles each, not two doubles per
// node), every other node reads zero, and the top's nodes carry syy times
// its width.
TEST(EngineMemory, dead_loads_are_held_for_the_loaded_nodes_only) {
  RectangleSpec spec;
  spec.width = spec.height = 1.0;
  spec.nx = spec.ny = 8;
  ModelInput in = structured_rectangle(spec, test::rock());
  const double syy = -5e6;
  in.boundary_conditions = test::side_tractions({-10e6, syy, 0.0});
  Engine e(in);
  e.step();  // from rest, unstrained: the slots hold zero and node_force the dead load
  long loaded = 0;
  double top = 0;
  for (std::size_t n = 0; n < e.n_nodes(); ++n) {
    const std::array<double, 2> f = e.node_force(n);
    if (f[0] != 0.0 || f[1] != 0.0) ++loaded;
    if (in.y[e.node_vertex()[n]] == spec.height) top += f[1];
  }
  EXPECT_NEAR(top, syy * spec.width, 1e-12 * std::fabs(syy));
  // Each of the 32 outline edges loads its triangle's two nodes there.
  EXPECT_GT(loaded, 0);
  EXPECT_LE(loaded, 64);
  std::size_t bytes = 0;
  for (const MemoryPart& p : e.memory_breakdown())
    if (p.name == "nodes.fext" || p.name == "nodes.fext_node") bytes += p.bytes;
  EXPECT_EQ(bytes, std::size_t(20 * loaded)) << "nodes " << e.n_nodes();
}

}  // namespace
}  // namespace rockfdem::fdem
