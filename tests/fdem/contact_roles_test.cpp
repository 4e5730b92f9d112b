// The narrow phase's batch kernel (fdem/src/contact_roles.hpp) against an
// independent computation of its integrals, and its instruction sets
// against each other bit by bit.
#include "contact_roles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

namespace {

using rockfdem::fdem::detail::kRoleBatch;
using rockfdem::fdem::detail::RoleBatch;
using rockfdem::fdem::detail::RoleIsa;
using rockfdem::fdem::detail::RoleParams;

struct Tri {
  double x[3], y[3];
};

/// A random counter-clockwise triangle of about unit size around (cx, cy).
Tri random_triangle(std::mt19937& rng, double cx, double cy) {
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  Tri t;
  for (;;) {
    for (int k = 0; k < 3; ++k) {
      t.x[k] = cx + u(rng);
      t.y[k] = cy + u(rng);
    }
    const double two_a =
        (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
    if (std::fabs(two_a) < 0.05) continue;  // no slivers
    if (two_a < 0) {
      std::swap(t.x[1], t.x[2]);
      std::swap(t.y[1], t.y[2]);
    }
    return t;
  }
}

double two_area(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

/// Lane r: contactor c against target t, as contact_force.cpp packs them.
void load(const Tri& c, const Tri& t, std::mt19937& rng, RoleBatch& b, int r) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double two_a = two_area(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
  double longest = 0;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3, l = (k + 2) % 3;
    b.cx[k][r] = c.x[k];
    b.cy[k][r] = c.y[k];
    b.cvx[k][r] = u(rng);
    b.cvy[k][r] = u(rng);
    b.cm[k][r] = 1.5 + u(rng);
    const double ex = c.x[j] - c.x[k], ey = c.y[j] - c.y[k], len = std::sqrt(ex * ex + ey * ey);
    b.len[k][r] = len;
    b.ex[k][r] = ex / len;
    b.ey[k][r] = ey / len;
    b.tx[k][r] = t.x[k];
    b.ty[k][r] = t.y[k];
    b.tvx[k][r] = u(rng);
    b.tvy[k][r] = u(rng);
    b.gx[k][r] = (t.y[j] - t.y[l]) / two_a;
    b.gy[k][r] = (t.x[l] - t.x[j]) / two_a;
    b.spring[k][r] = 0.1 * u(rng);
    longest = std::max(longest, std::hypot(t.x[j] - t.x[k], t.y[j] - t.y[k]));
  }
  b.h[r] = two_a / longest;
  b.mu[r] = 0.6 + 0.2 * u(rng);
}

/// A batch of n random roles and their triangles: targets at the origin,
/// contactors shifted so that some overlap and some do not.
struct Draw {
  RoleBatch b{};
  Tri c[kRoleBatch], t[kRoleBatch];
};

Draw random_batch(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.8, 0.8);
  Draw d;
  for (int r = 0; r < n; ++r) {
    d.t[r] = random_triangle(rng, 0, 0);
    const double sx = shift(rng), sy = shift(rng);
    d.c[r] = random_triangle(rng, sx, sy);
    load(d.c[r], d.t[r], rng, d.b, r);
  }
  return d;
}

/// int_0^1 phi xi^m dxi along the contactor edge from (ax, ay) to (bx, by),
/// phi = 3 max(0, min lambda) of target t, lambda from signed areas (not
/// from the gradients the kernel uses); midpoint rule.
double quadrature(const Tri& t, double ax, double ay, double bx, double by, int m) {
  const int n = 200000;
  const double two_a = two_area(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
  double sum = 0;
  for (int s = 0; s < n; ++s) {
    const double xi = (s + 0.5) / n, px = ax + (bx - ax) * xi, py = ay + (by - ay) * xi;
    double low = 1e300;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      low = std::min(low, two_area(px, py, t.x[j], t.y[j], t.x[k], t.y[k]) / two_a);
    }
    sum += 3.0 * std::max(0.0, low) * (m == 0 ? 1.0 : xi);
  }
  return sum / n;
}

// Without friction and damping the contactor's corners a, b of edge k get
// -F_A n and -F_B n, F_A + F_B = p L int phi, F_B = p L int phi xi. Both
// integrals against a 200,000-point midpoint rule on coordinates from
// signed areas: the rule's error on the kinks of phi is below 1e-8 of
// p L; tolerance 1e-6 p L.
TEST(ContactRoles, edge_forces_integrate_the_target_potential) {
  const int n = 30;
  const Draw d = random_batch(7, n);
  RoleBatch b = d.b;
  RoleParams rp;
  rp.p = 2.0;
  rp.dt = 1e-3;
  rockfdem::fdem::detail::run_roles(b, n, rp);
  int hits = 0, misses = 0;
  for (int r = 0; r < n; ++r) {
    const Tri& t = d.t[r];
    const Tri& c = d.c[r];
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      const double i0 = quadrature(t, c.x[k], c.y[k], c.x[j], c.y[j], 0);
      const double i1 = quadrature(t, c.x[k], c.y[k], c.x[j], c.y[j], 1);
      const double nx = b.ey[k][r], ny = -b.ex[k][r], s = rp.p * b.len[k][r];
      if (b.hit[k][r] == 0.0) {
        ++misses;
        EXPECT_LT(i0, 1e-9) << "lane " << r << " edge " << k;
        EXPECT_EQ(b.spring[k][r], 0.0);
        continue;
      }
      ++hits;
      const double f_a = -(b.fc[k][0][r] * nx + b.fc[k][1][r] * ny);
      const double f_b = -(b.fc[k][2][r] * nx + b.fc[k][3][r] * ny);
      EXPECT_NEAR(f_a + f_b, s * i0, 1e-6 * s) << "lane " << r << " edge " << k;
      EXPECT_NEAR(f_b, s * i1, 1e-6 * s) << "lane " << r << " edge " << k;
      // The target's share balances the contactor's force.
      double sx = b.fc[k][0][r] + b.fc[k][2][r], sy = b.fc[k][1][r] + b.fc[k][3][r];
      for (int i = 0; i < 3; ++i) {
        sx += b.ft[k][2 * i][r];
        sy += b.ft[k][2 * i + 1][r];
      }
      EXPECT_NEAR(sx, 0.0, 1e-12 * s);
      EXPECT_NEAR(sy, 0.0, 1e-12 * s);
    }
  }
  EXPECT_GT(hits, 10);  // the draw must exercise both cases
  EXPECT_GT(misses, 10);
}

// Every instruction set this processor has gives the baseline's bits in
// every output of every lane, with friction and damping on and a lane
// count that leaves the wide sets a partial last vector.
TEST(ContactRoles, every_instruction_set_gives_the_same_bits) {
  const int n = kRoleBatch - 3;
  RoleParams rp;
  rp.p = 3.0;
  rp.dt = 1e-2;
  rp.damping = 0.1;
  rp.friction = true;
  int compared = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const RoleBatch input = random_batch(seed, n).b;
    RoleBatch reference = input;
    rockfdem::fdem::detail::run_roles(reference, n, rp, RoleIsa::kBaseline);
    for (RoleIsa isa : {RoleIsa::kAvx2, RoleIsa::kAvx512}) {
      if (!rockfdem::fdem::detail::role_isa_available(isa)) continue;
      RoleBatch wide = input;
      rockfdem::fdem::detail::run_roles(wide, n, rp, isa);
      for (int k = 0; k < 3; ++k) {
        for (int r = 0; r < n; ++r) {
          const double* got[] = {&wide.hit[k][r], &wide.spring[k][r], &wide.loss_friction[k][r],
                                 &wide.loss_damping[k][r]};
          const double* want[] = {&reference.hit[k][r], &reference.spring[k][r],
                                  &reference.loss_friction[k][r], &reference.loss_damping[k][r]};
          for (int q = 0; q < 4; ++q)
            EXPECT_EQ(std::memcmp(got[q], want[q], sizeof(double)), 0) << "lane " << r;
          if (reference.hit[k][r] == 0.0) continue;
          for (int i = 0; i < 4; ++i)
            EXPECT_EQ(std::memcmp(&wide.fc[k][i][r], &reference.fc[k][i][r], sizeof(double)), 0);
          for (int i = 0; i < 6; ++i)
            EXPECT_EQ(std::memcmp(&wide.ft[k][i][r], &reference.ft[k][i][r], sizeof(double)), 0);
        }
      }
      ++compared;
    }
  }
  if (compared == 0) GTEST_SKIP() << "this processor has no vector set wider than the baseline";
}

}  // namespace
