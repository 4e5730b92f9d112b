// The locality order changes only the numbering, never the answer: the same
// elastic excavation (a circular hole released from a hydrostatic in-situ
// stress, crack elements in a fracture zone round it) on the meshed
// tunnel in its locality order and in a scrambled order gives the same
// displacement at every node to round-off, with any thread count, and both
// give the closed-form wall displacement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/locality.hpp"

namespace rockfdem::coupling {
namespace {

constexpr double kRadius = 1.0, kHalfWidth = 6.0, kS = 2e6;  // [m], [m], [Pa]

mesh::Mesh tunnel() {
  mesh::MeshSpec s;
  s.tunnel.shape = mesh::TunnelShape::kCircular;
  s.tunnel.radius = kRadius;
  s.tunnel.fracture_zone = 0.5;
  s.domain = {2 * kHalfWidth, 2 * kHalfWidth, 0, 0};
  s.size.size_near = 0.15, s.size.size_far = 1.0;
  return mesh::build_mesh(s);
}

/// A scattered order of 0..n-1: i -> i k mod n with k = 7919, a prime that
/// does not divide n (checked), so every id is taken once and consecutive
/// ids land k mod n apart.
std::vector<int> scramble(std::size_t n) {
  constexpr std::size_t k = 7919;
  EXPECT_NE(n % k, 0u);
  std::vector<int> p(n);
  for (std::size_t i = 0; i < n; ++i) p[i] = int(i * k % n);
  return p;
}

fdem::Material rock() {
  fdem::Material r;
  r.young = 10e9;
  r.poisson = 0.25;
  r.tensile_strength = 1e9;  // intact throughout: an elastic problem
  r.cohesion = 1e9;
  r.normal_penalty = 100 * r.young;  // the cracks' compliance below 1%
  return r;
}

/// Hydrostatic in-situ stress -S, rollers on the four sides (they hold the
/// in-situ field as it is), the core removed, mass-proportional damping
/// (linear, so round-off stays round-off).
fdem::Engine excavated(const mesh::Mesh& m, int threads) {
  fdem::ModelInput in =
      model_input(m, {{mesh::kRock, rock()}, {mesh::kCore, rock()}}, fdem::Plane::kStrain);
  in.initial_stress.assign(m.n_triangles(), {-kS, -kS, 0.0});
  fdem::BoundaryCondition left, right, bottom, top;
  left.tag = mesh::kLeft, right.tag = mesh::kRight;
  bottom.tag = mesh::kBottom, top.tag = mesh::kTop;
  left.x = right.x = fdem::Constraint::kFixed;
  bottom.y = top.y = fdem::Constraint::kFixed;
  in.boundary_conditions = {left, right, bottom, top};
  in.damping.mass_proportional = 1500;
  fdem::Engine e(in);
  e.set_threads(threads);
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == mesh::kCore) e.set_active(t, false);
  return e;
}

TEST(LocalityOrder, scrambled_and_ordered_meshes_give_the_same_elastic_answer) {
  const mesh::Mesh ordered = tunnel();
  const std::vector<int> order = scramble(ordered.n_triangles());
  const mesh::Mesh scrambled = mesh::with_triangle_order(ordered, order);
  fdem::Engine a = excavated(ordered, 1), b = excavated(scrambled, 2);
  // The automatic dt comes from a Lanczos iteration whose start vector is in
  // node order, so it differs in the last digits between the orders: both
  // run at one dt, for 3000 steps.
  const double dt = 0.95 * std::min(a.stable_dt(), b.stable_dt());
  a.set_dt(dt);
  b.set_dt(dt);
  a.run(3000);
  b.run(3000);
  ASSERT_EQ(a.n_nodes(), b.n_nodes());
  ASSERT_EQ(a.n_cracks(), b.n_cracks());
  ASSERT_GT(a.n_cracks(), 500u);

  // Scrambled triangle t is ordered triangle order[t]; corner k's node
  // holds the same point in both.
  double u_max = 0, diff_max = 0;
  for (std::size_t t = 0; t < scrambled.n_triangles(); ++t) {
    const auto nb = b.triangle_nodes(t), na = a.triangle_nodes(std::size_t(order[t]));
    for (int k = 0; k < 3; ++k) {
      const auto ua = a.displacement(std::size_t(na[k]));
      const auto ub = b.displacement(std::size_t(nb[k]));
      u_max = std::max(u_max, std::hypot(ua[0], ua[1]));
      diff_max = std::max(diff_max, std::hypot(ua[0] - ub[0], ua[1] - ub[1]));
    }
  }
  std::printf("largest displacement %.6e m, largest difference between orders %.3e m\n", u_max,
              diff_max);
  // Summation orders differ (a node gathers its slots in slot order), so
  // the two runs agree to round-off amplified over 3000 steps, not bitwise.
  EXPECT_LT(diff_max, 1e-9 * u_max);

  // Wall displacement against Lame's ring with its outer radius held at b
  // (u = A r + B/r, sigma_rr(a) = S released, u(b) = 0; plane strain):
  // B = -S / (2 (lambda + mu) / b^2 + 2 mu / a^2), u(a) = B (1/a - a/b^2).
  // The square box with rollers lies between the circles b = 6 m and
  // b = 6 sqrt(2) m, whose u(a) differ by 4.2%: their mean is within 2.1%
  // of either. The mesh (0.15 m on a 1 m radius) and the crack elements'
  // compliance (penalty 100 E) add about 2%: 5% in all.
  const fdem::Material r = rock();
  const double mu = r.young / (2 * (1 + r.poisson));
  const double lambda = r.young * r.poisson / ((1 + r.poisson) * (1 - 2 * r.poisson));
  auto wall = [&](double b) {
    const double B = -kS / (2 * (lambda + mu) / (b * b) + 2 * mu / (kRadius * kRadius));
    return B * (1 / kRadius - kRadius / (b * b));
  };
  const double u_ref = 0.5 * (wall(kHalfWidth) + wall(kHalfWidth * std::sqrt(2.0)));
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < a.n_nodes(); ++i) {
    const double x = ordered.x[a.node_vertex()[i]], y = ordered.y[a.node_vertex()[i]];
    const double r0 = std::hypot(x, y);
    if (std::abs(r0 - kRadius) > 1e-6 || a.node_mass()[i] == 0) continue;
    const auto u = a.displacement(i);
    sum += (u[0] * x + u[1] * y) / r0;
    ++n;
  }
  ASSERT_GT(n, 20);
  std::printf("mean radial wall displacement %.6e m, Lame ring %.6e m (%d nodes)\n", sum / n, u_ref,
              n);
  EXPECT_NEAR(sum / n, u_ref, 0.05 * std::abs(u_ref));
}

}  // namespace
}  // namespace rockfdem::coupling
