// The in-situ stage on meshes from mesh/ (gmsh), as the product builds them:
// Kirsch around a circular tunnel, and the seed's default tunnel through the
// whole softening sequence. Built only when rockfdem_mesh exists.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fixtures.hpp"
#include "rockfdem/mesh/build.hpp"

namespace rockfdem::insitu::test {
namespace {

mesh::MeshSpec circular_tunnel(double a, double half_width, double size_near, double size_far) {
  mesh::MeshSpec s;
  s.kind = mesh::ModelKind::kTunnel;
  s.tunnel.shape = mesh::TunnelShape::kCircular;
  s.tunnel.radius = a;
  s.domain.width = s.domain.height = 2 * half_width;
  s.size.size_near = size_near;
  s.size.size_far = size_far;
  return s;
}

class GmshKirsch : public ::testing::TestWithParam<double> {};  // param: sV / sH

TEST_P(GmshKirsch, error_falls_with_refinement_and_is_below_1pct_at_20k_triangles) {
  const double a = 5.0;
  InsituSpec spec = seed_spec(18.2 * kMPa, GetParam() * 18.2 * kMPa);
  spec.loading = BoundaryLoading::kKirschExact;
  spec.kirsch_radius = a;
  spec.alphas = {0.0};
  const KirschCase k = kirsch_case(spec, a);
  double previous = 1;
  KirschComparison c;
  std::size_t rock_cells = 0;
  for (const double h : {0.8, 0.4, 0.2}) {
    const mesh::Mesh m = mesh::build_mesh(circular_tunnel(a, 40, h, 10 * h));
    const InsituField f = solve_insitu(m, spec).at(0);
    c = compare_kirsch(m, f, k);
    rock_cells = f.n_cells;
    std::printf(
        "  sV/sH %.3f gmsh h_near %.2f: %zu triangles (%zu rock)  stress L2 %.4f%%  wall u_r %.4f%%"
        "  %s (%d it)\n",
        GetParam(), h, m.n_triangles(), f.n_cells, 100 * c.stress_rel_l2, 100 * c.wall_ur_rel_l2,
        f.solver.c_str(), f.iterations);
    EXPECT_LT(c.stress_rel_l2, 0.75 * previous);
    previous = c.stress_rel_l2;
  }
  EXPECT_GT(rock_cells, 15000u);
  EXPECT_LT(c.stress_rel_l2, 0.01);
  EXPECT_LT(c.wall_ur_rel_l2, 0.02);
}

INSTANTIATE_TEST_SUITE_P(FarFields, GmshKirsch, ::testing::Values(11.4 / 18.2, 1.0),
                         [](const auto& info) {
                           return info.param == 1.0 ? "hydrostatic" : "seed_18_2_over_11_4";
                         });

TEST(GmshDefaultTunnel, seed_sequence_converges_inward_and_stays_in_balance) {
  mesh::MeshSpec s;  // defaults: horseshoe 11.3 x 8.8 in a 100 m box
  s.tunnel.lining_thickness = 0.2;
  s.size.size_near = 0.5;
  s.size.size_far = 5;
  const mesh::Mesh m = mesh::build_mesh(s);
  InsituSpec spec = seed_spec();
  spec.lining.active = true;
  spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.01, 0.0};
  const auto fields = solve_insitu(m, spec);
  ASSERT_EQ(fields.size(), spec.alphas.size());
  // The crown: the wall vertex with the largest y.
  int crown = -1;
  for (const auto& e : m.edges)
    if (e.tag == mesh::kExcavation && (crown < 0 || m.y[e.a] > m.y[crown])) crown = e.a;
  ASSERT_GE(crown, 0);
  double previous = 0;
  for (const InsituField& f : fields) {
    EXPECT_LT(f.unbalanced_ratio, 1e-8);
    EXPECT_LT(f.reaction_ratio, 1e-8);
    if (f.alpha < 1) {
      EXPECT_LT(f.uy[crown], previous);  // the crown settles, more each stage
    }
    previous = f.uy[crown];
  }
  EXPECT_TRUE(fields.back().lining_installed);
  EXPECT_FALSE(fields[4].lining_installed);  // alpha = 0.05 > install_alpha = 0.01
}

}  // namespace
}  // namespace rockfdem::insitu::test
