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

using rockfdem::fdem::detail::kPairBatch;
using rockfdem::fdem::detail::PairBatch;
using rockfdem::fdem::detail::RoleIsa;
using rockfdem::fdem::detail::RoleParams;
using rockfdem::fdem::detail::TriLanes;

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

/// Copies triangle t into lane r, as contact_force.cpp packs it; random
/// velocities and masses.
void load(const Tri& t, std::mt19937& rng, TriLanes& lanes, int r) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double two_a = two_area(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
  double longest = 0;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3, l = (k + 2) % 3;
    lanes.x[k][r] = t.x[k];
    lanes.y[k][r] = t.y[k];
    lanes.vx[k][r] = u(rng);
    lanes.vy[k][r] = u(rng);
    lanes.m[k][r] = 1.5 + u(rng);
    const double ex = t.x[j] - t.x[k], ey = t.y[j] - t.y[k], len = std::sqrt(ex * ex + ey * ey);
    lanes.len[k][r] = len;
    lanes.ex[k][r] = ex / len;
    lanes.ey[k][r] = ey / len;
    lanes.gx[k][r] = (t.y[j] - t.y[l]) / two_a;
    lanes.gy[k][r] = (t.x[l] - t.x[j]) / two_a;
    longest = std::max(longest, len);
  }
  lanes.h[r] = two_a / longest;
  lanes.two_a[r] = two_a;
}

/// A batch of n random pairs and their triangles: B at the origin, A
/// shifted so that some overlap and some do not.
struct Draw {
  PairBatch b{};
  Tri a[kPairBatch], t[kPairBatch];
};

Draw random_batch(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.8, 0.8), u(-1.0, 1.0);
  Draw d;
  for (int r = 0; r < n; ++r) {
    d.t[r] = random_triangle(rng, 0, 0);
    const double sx = shift(rng), sy = shift(rng);
    d.a[r] = random_triangle(rng, sx, sy);
    load(d.a[r], rng, d.b.tri[0], r);
    load(d.t[r], rng, d.b.tri[1], r);
    d.b.mu[r] = 0.6 + 0.2 * u(rng);
    for (int j = 0; j < 6; ++j) d.b.spring[j][r] = 0.1 * u(rng);
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

// Role 0 alone (A's edges against B; A is made an invalid target so that
// role 1 is skipped), without friction and damping: edge k of A pushes its
// corners by -F_A n, -F_B n with F_A + F_B = p L int phi and F_B =
// p L int phi xi. A's total force and moment against a 200,000-point
// midpoint rule on coordinates from signed areas (the rule's error on the
// kinks of phi is below 1e-8 p L; tolerance 1e-6 p L); B receives the
// opposite force and moment; springs: kept where an edge touches (no
// friction), reset where it does not, kept for the skipped role.
TEST(ContactRoles, forces_integrate_the_target_potential_and_balance) {
  const int n = 30;
  Draw d = random_batch(7, n);
  for (int r = 0; r < n; ++r) d.b.tri[0].two_a[r] = -1.0;
  PairBatch b = d.b;
  RoleParams rp;
  rp.p = 2.0;
  rp.dt = 1e-3;
  rockfdem::fdem::detail::run_roles(b, n, rp);
  int hits = 0, misses = 0;
  for (int r = 0; r < n; ++r) {
    const Tri& a = d.a[r];
    const Tri& t = d.t[r];
    double fx = 0, fy = 0, moment = 0, scale = 0;
    bool touching = false;
    int lane_misses = 0;
    for (int k = 0; k < 3; ++k) {
      const int j = (k + 1) % 3;
      const double i0 = quadrature(t, a.x[k], a.y[k], a.x[j], a.y[j], 0);
      const double i1 = quadrature(t, a.x[k], a.y[k], a.x[j], a.y[j], 1);
      const double nx = b.tri[0].ey[k][r], ny = -b.tri[0].ex[k][r], s = rp.p * b.tri[0].len[k][r];
      const double f_b = s * i1, f_a = s * i0 - f_b;
      fx -= (f_a + f_b) * nx;
      fy -= (f_a + f_b) * ny;
      moment -= f_a * (a.x[k] * ny - a.y[k] * nx) + f_b * (a.x[j] * ny - a.y[j] * nx);
      scale = std::max(scale, s);
      if (i0 > 1e-9) {
        ++hits;
        touching = true;
        EXPECT_EQ(b.spring[k][r], d.b.spring[k][r]) << "lane " << r << " edge " << k;
      } else if (i0 < 1e-14) {
        ++misses;
        ++lane_misses;
        EXPECT_EQ(b.spring[k][r], 0.0) << "lane " << r << " edge " << k;
      }
      EXPECT_EQ(b.spring[3 + k][r], d.b.spring[3 + k][r]);  // role 1 skipped
    }
    double ax = 0, ay = 0, am = 0, bx = 0, by = 0, bm = 0;
    for (int i = 0; i < 3; ++i) {
      ax += b.force[2 * i][r];
      ay += b.force[2 * i + 1][r];
      am += a.x[i] * b.force[2 * i + 1][r] - a.y[i] * b.force[2 * i][r];
      bx += b.force[6 + 2 * i][r];
      by += b.force[7 + 2 * i][r];
      bm += t.x[i] * b.force[7 + 2 * i][r] - t.y[i] * b.force[6 + 2 * i][r];
    }
    EXPECT_NEAR(ax, fx, 1e-6 * scale) << "lane " << r;
    EXPECT_NEAR(ay, fy, 1e-6 * scale) << "lane " << r;
    EXPECT_NEAR(am, moment, 1e-6 * scale) << "lane " << r;
    EXPECT_NEAR(bx, -ax, 1e-12 * scale);
    EXPECT_NEAR(by, -ay, 1e-12 * scale);
    EXPECT_NEAR(bm, -am, 1e-12 * scale);
    if (touching) {
      EXPECT_EQ(b.touching[r], 1.0) << "lane " << r;
    } else if (lane_misses == 3) {
      EXPECT_EQ(b.touching[r], 0.0) << "lane " << r;
    }
  }
  EXPECT_GT(hits, 10);  // the draw must exercise both cases
  EXPECT_GT(misses, 10);
}

// Every instruction set this processor has gives the baseline's bits in
// every output of every lane, with friction and damping on, one lane whose
// A has no positive area, and a lane count that leaves the wide sets a
// partial last vector.
TEST(ContactRoles, every_instruction_set_gives_the_same_bits) {
  const int n = kPairBatch - 3;
  RoleParams rp;
  rp.p = 3.0;
  rp.dt = 1e-2;
  rp.damping = 0.1;
  rp.friction = true;
  int compared = 0, touching = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    PairBatch input = random_batch(seed, n).b;
    input.tri[0].two_a[5] = -1.0;
    PairBatch reference = input;
    rockfdem::fdem::detail::run_roles(reference, n, rp, RoleIsa::kBaseline);
    for (int r = 0; r < n; ++r) touching += reference.touching[r] != 0.0;
    for (RoleIsa isa : {RoleIsa::kAvx2, RoleIsa::kAvx512}) {
      if (!rockfdem::fdem::detail::role_isa_available(isa)) continue;
      PairBatch wide = input;
      rockfdem::fdem::detail::run_roles(wide, n, rp, isa);
      for (int r = 0; r < n; ++r) {
        auto same = [&](const double* x, const double* y) {
          return std::memcmp(x, y, sizeof(double)) == 0;
        };
        for (int i = 0; i < 12; ++i)
          EXPECT_TRUE(same(&wide.force[i][r], &reference.force[i][r])) << "lane " << r;
        for (int j = 0; j < 6; ++j) {
          EXPECT_TRUE(same(&wide.spring[j][r], &reference.spring[j][r])) << "lane " << r;
          EXPECT_TRUE(same(&wide.loss_friction[j][r], &reference.loss_friction[j][r]));
          EXPECT_TRUE(same(&wide.loss_damping[j][r], &reference.loss_damping[j][r]));
        }
        EXPECT_TRUE(same(&wide.touching[r], &reference.touching[r]));
      }
      ++compared;
    }
  }
  EXPECT_GT(touching, 100);
  if (compared == 0) GTEST_SKIP() << "this processor has no vector set wider than the baseline";
}

}  // namespace
