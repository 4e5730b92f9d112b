// The narrow phase's batch kernel (fdem/src/contact_roles.hpp) against an
// independent computation of its integrals, and its instruction sets
// against each other bit by bit.
#include "contact_roles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "contact.hpp"

namespace {

using rockfdem::fdem::detail::kPairBatch;
using rockfdem::fdem::detail::PairBatch;
using rockfdem::fdem::detail::RoleParams;
using rockfdem::fdem::detail::SimdIsa;
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

// The scalar narrow phase the kernel replaced (fdem/src/contact_force.cpp
// before 2026-12-01), kept here as the reference: branches where the
// kernel selects, only the segments that exist, early returns.
namespace scalar {

struct Tri {
  double x[3], y[3], vx[3], vy[3], m[3], two_a, gx[3], gy[3], h, len[3], tx[3], ty[3];
};

Tri lane(const TriLanes& l, int r) {
  Tri t;
  for (int k = 0; k < 3; ++k) {
    t.x[k] = l.x[k][r];
    t.y[k] = l.y[k][r];
    t.vx[k] = l.vx[k][r];
    t.vy[k] = l.vy[k][r];
    t.m[k] = l.m[k][r];
    t.gx[k] = l.gx[k][r];
    t.gy[k] = l.gy[k][r];
    t.len[k] = l.len[k][r];
    t.tx[k] = l.ex[k][r];
    t.ty[k] = l.ey[k][r];
  }
  t.two_a = l.two_a[r];
  t.h = l.h[r];
  return t;
}

struct EdgeIntegral {
  double i0 = 0, i1 = 0, inside = 0;
};

bool integrate_edge(const double la[3], const double lb[3], EdgeIntegral& out) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (la[i] < 0.0 && lb[i] < 0.0) return false;
    if (la[i] < 0.0)
      lo = std::max(lo, la[i] / (la[i] - lb[i]));
    else if (lb[i] < 0.0)
      hi = std::min(hi, la[i] / (la[i] - lb[i]));
  }
  if (!(hi > lo)) return false;
  double xs[5];
  xs[0] = lo;
  int n = 1;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const double d0 = la[i] - la[j], d1 = lb[i] - lb[j];
      if ((d0 < 0.0) != (d1 < 0.0) && d0 != d1) {
        const double x = d0 / (d0 - d1);
        if (x > lo && x < hi) xs[n++] = x;
      }
    }
  for (int i = 2; i < n; ++i)
    for (int j = i; j > 1 && xs[j] < xs[j - 1]; --j) std::swap(xs[j], xs[j - 1]);
  xs[n++] = hi;
  double ph[5];
  for (int s = 0; s < n; ++s) {
    double m = la[0] + (lb[0] - la[0]) * xs[s];
    for (int i = 1; i < 3; ++i) m = std::min(m, la[i] + (lb[i] - la[i]) * xs[s]);
    ph[s] = 3.0 * std::max(0.0, m);
  }
  for (int s = 0; s + 1 < n; ++s) {
    const double a = xs[s], b = xs[s + 1], w = b - a;
    out.i0 += 0.5 * w * (ph[s] + ph[s + 1]);
    out.i1 += w / 6.0 * (ph[s] * (2.0 * a + b) + ph[s + 1] * (a + 2.0 * b));
  }
  out.inside = hi - lo;
  return out.i0 > 0.0;
}

struct Loss {
  double friction = 0, damping = 0;
};

bool role(const Tri& c, const Tri& t, const RoleParams& rp, double mu, double* spring, double* fc,
          double* ft, Loss& loss) {
  if (!(t.two_a > 0.0)) return false;
  double lam[3][3];
  for (int v = 0; v < 3; ++v)
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      lam[v][i] = t.gx[i] * (c.x[v] - t.x[j]) + t.gy[i] * (c.y[v] - t.y[j]);
    }
  for (int i = 0; i < 3; ++i)
    if (lam[0][i] < 0.0 && lam[1][i] < 0.0 && lam[2][i] < 0.0) {
      spring[0] = spring[1] = spring[2] = 0.0;
      return false;
    }
  bool touching = false;
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3;
    const double* la = lam[a];
    const double* lb = lam[b];
    EdgeIntegral e;
    if (!integrate_edge(la, lb, e)) {
      spring[k] = 0.0;
      continue;
    }
    touching = true;
    const double tx = c.tx[k], ty = c.ty[k], nx = ty, ny = -tx;
    const double s = rp.p * c.len[k];
    const double f_ab = s * e.i0, f_b = s * e.i1, f_a = f_ab - f_b;
    const double xi = e.i1 / e.i0;
    double lc[3], vtx = 0, vty = 0;
    for (int i = 0; i < 3; ++i) {
      lc[i] = la[i] + (lb[i] - la[i]) * xi;
      vtx += lc[i] * t.vx[i];
      vty += lc[i] * t.vy[i];
    }
    const double vrx = (1 - xi) * c.vx[a] + xi * c.vx[b] - vtx;
    const double vry = (1 - xi) * c.vy[a] + xi * c.vy[b] - vty;
    const double k_n = 3.0 * s * e.inside / t.h;
    double f_d = 0.0;
    if (rp.damping > 0.0) {
      const double m = std::min(c.m[a], c.m[b]);
      const double v_n = vrx * nx + vry * ny;
      f_d = std::max(rp.damping * 2.0 * std::sqrt(k_n * m) * v_n, -f_ab);
      loss.damping += f_d * v_n * rp.dt;
    }
    double f_t = 0.0;
    if (rp.friction) {
      const double trial = spring[k] - k_n * (vrx * tx + vry * ty) * rp.dt;
      const double cap = mu * (f_ab + f_d);
      f_t = std::clamp(trial, -cap, cap);
      spring[k] = f_t;
      if (f_t != trial) loss.friction += f_t * (trial - f_t) / k_n;
    }
    const double px = f_t * tx - f_d * nx, py = f_t * ty - f_d * ny;
    fc[2 * a] += -f_a * nx + (1 - xi) * px;
    fc[2 * a + 1] += -f_a * ny + (1 - xi) * py;
    fc[2 * b] += -f_b * nx + xi * px;
    fc[2 * b + 1] += -f_b * ny + xi * py;
    const double gx = f_ab * nx - px, gy = f_ab * ny - py;
    for (int i = 0; i < 3; ++i) {
      ft[2 * i] += lc[i] * gx;
      ft[2 * i + 1] += lc[i] * gy;
    }
  }
  return touching;
}

}  // namespace scalar

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
    rockfdem::fdem::detail::run_roles(reference, n, rp, SimdIsa::kBaseline);
    for (int r = 0; r < n; ++r) touching += reference.touching[r] != 0.0;
    for (SimdIsa isa : {SimdIsa::kAvx2, SimdIsa::kAvx512}) {
      if (!rockfdem::fdem::detail::simd_isa_available(isa)) continue;
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

/// Pair kinds a fractured mesh produces: apart, overlapping, across a
/// shared edge (the faces of a broken crack element) and around a shared
/// vertex, with coordinates on a grid (exact ties), nudged by one ulp, or
/// negative zeros.
Draw tricky_batch(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 5), grid(-8, 8);
  Draw d;
  for (int r = 0; r < n; ++r) {
    Tri t = random_triangle(rng, 0, 0), a;
    switch (kind(rng)) {
      case 0:  // overlapping, random
        a = random_triangle(rng, 0.3 * u(rng), 0.3 * u(rng));
        break;
      case 1:  // on a grid of eighths: ties between coordinates
      case 2:
        for (int k = 0; k < 3; ++k) {
          t.x[k] = grid(rng) / 8.0;
          t.y[k] = grid(rng) / 8.0;
          a.x[k] = grid(rng) / 8.0;
          a.y[k] = grid(rng) / 8.0;
        }
        break;
      case 3: {  // across t's edge 0 -> 1, the third corner on the other side
        a.x[0] = t.x[1], a.y[0] = t.y[1];
        a.x[1] = t.x[0], a.y[1] = t.y[0];
        const double mx = 0.5 * (t.x[0] + t.x[1]), my = 0.5 * (t.y[0] + t.y[1]);
        a.x[2] = 2 * mx - t.x[2] + 0.1 * u(rng);
        a.y[2] = 2 * my - t.y[2] + 0.1 * u(rng);
        if (u(rng) > 0) a.x[0] = std::nextafter(a.x[0], 10.0);  // one ulp in
        break;
      }
      case 4: {  // around t's corner 0, rotated away by about 120 degrees
        const double c = std::cos(2.1 + 0.3 * u(rng)), s = std::sin(2.1 + 0.3 * u(rng));
        for (int k = 0; k < 3; ++k) {
          const double x = t.x[k] - t.x[0], y = t.y[k] - t.y[0];
          a.x[k] = t.x[0] + c * x - s * y;
          a.y[k] = t.y[0] + s * x + c * y;
        }
        a.x[0] = t.x[0] + 1e-3 * u(rng);
        a.y[0] = t.y[0] + 1e-3 * u(rng);
        break;
      }
      default:  // negative zeros at the origin corner of both
        t.x[0] = t.y[0] = -0.0;
        a = random_triangle(rng, 0.2 * u(rng), 0.2 * u(rng));
        a.x[1] = -0.0;
        a.y[1] = 0.0;
        break;
    }
    for (Tri* x : {&t, &a}) {  // counter-clockwise and not degenerate
      const double two_a = two_area(x->x[0], x->y[0], x->x[1], x->y[1], x->x[2], x->y[2]);
      if (two_a < 0) {
        std::swap(x->x[1], x->x[2]);
        std::swap(x->y[1], x->y[2]);
      }
    }
    if (std::fabs(two_area(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2])) < 1e-3 ||
        std::fabs(two_area(a.x[0], a.y[0], a.x[1], a.y[1], a.x[2], a.y[2])) < 1e-3) {
      --r;  // draw again
      continue;
    }
    d.t[r] = t;
    d.a[r] = a;
    load(a, rng, d.b.tri[0], r);
    load(t, rng, d.b.tri[1], r);
    d.b.mu[r] = 0.6 + 0.2 * u(rng);
    for (int j = 0; j < 6; ++j) d.b.spring[j][r] = 0.1 * u(rng);
  }
  return d;
}

// The kernel against the scalar loop it replaced, bit for bit: forces,
// springs, touching flags and the dissipation summed as contact_force.cpp
// sums it (lane and edge order, zeros skipped), for every combination of
// friction and damping, on every instruction set, over tricky and random
// pairs, in a batch reused from one draw to the next (every output must be
// rewritten).
TEST(ContactRoles, matches_the_scalar_loop_bit_for_bit) {
  const int n = kPairBatch - 1;
  int touching = 0, compared = 0;
  for (SimdIsa isa : {SimdIsa::kBaseline, SimdIsa::kAvx2, SimdIsa::kAvx512}) {
    if (!rockfdem::fdem::detail::simd_isa_available(isa)) continue;
    PairBatch b{};  // reused: lanes past n keep an earlier draw
    for (unsigned seed = 1; seed <= 40; ++seed)
      for (int setting = 0; setting < 4; ++setting) {
        RoleParams rp;
        rp.p = 2.5;
        rp.dt = 1e-2;
        rp.friction = setting & 1;
        rp.damping = (setting & 2) ? 0.2 : 0.0;
        const Draw d = seed % 2 ? tricky_batch(seed, n) : random_batch(seed, n);
        b.tri[0] = d.b.tri[0];  // inputs only: the outputs of the last draw stay
        b.tri[1] = d.b.tri[1];
        std::memcpy(b.mu, d.b.mu, sizeof b.mu);
        std::memcpy(b.spring, d.b.spring, sizeof b.spring);
        rockfdem::fdem::detail::run_roles(b, n, rp, isa);
        scalar::Loss want_loss, got_loss;
        for (int r = 0; r < n; ++r) {
          const scalar::Tri a = scalar::lane(d.b.tri[0], r), t = scalar::lane(d.b.tri[1], r);
          double force[12] = {}, spring[6];
          for (int j = 0; j < 6; ++j) spring[j] = d.b.spring[j][r];
          const bool t0 = scalar::role(a, t, rp, d.b.mu[r], spring, force, force + 6, want_loss);
          const bool t1 =
              scalar::role(t, a, rp, d.b.mu[r], spring + 3, force + 6, force, want_loss);
          touching += t0 || t1;
          EXPECT_EQ(b.touching[r], (t0 || t1) ? 1.0 : 0.0) << "seed " << seed << " lane " << r;
          for (int i = 0; i < 12; ++i)
            EXPECT_EQ(std::memcmp(&b.force[i][r], &force[i], sizeof(double)), 0)
                << "seed " << seed << " lane " << r << " force " << i << ": " << b.force[i][r]
                << " against " << force[i];
          for (int j = 0; j < 6; ++j) {
            EXPECT_EQ(std::memcmp(&b.spring[j][r], &spring[j], sizeof(double)), 0)
                << "seed " << seed << " lane " << r << " spring " << j;
            if (b.loss_friction[j][r] != 0.0) got_loss.friction += b.loss_friction[j][r];
            if (b.loss_damping[j][r] != 0.0) got_loss.damping += b.loss_damping[j][r];
          }
        }
        EXPECT_EQ(std::memcmp(&got_loss.friction, &want_loss.friction, sizeof(double)), 0)
            << "seed " << seed << " setting " << setting;
        EXPECT_EQ(std::memcmp(&got_loss.damping, &want_loss.damping, sizeof(double)), 0)
            << "seed " << seed << " setting " << setting;
        ++compared;
      }
  }
  EXPECT_GT(compared, 0);
  EXPECT_GT(touching, 1000);  // the draws must exercise contact
}

// The pair loop skips the pairs that pair_apart calls apart (an edge of
// either separates them) as if the roles had run: for each such pair the
// roles must give no force (positive zeros), reset springs, no dissipation
// and no touch. Over tricky draws (pairs around a shared vertex moved by
// 1e-3, across a shared edge moved by one ulp, on a grid with exact ties)
// and random ones, with friction and damping; pairs whose boxes overlap
// must be among those called apart, and touching pairs among those kept.
TEST(ContactRoles, pairs_called_apart_get_nothing_from_the_roles) {
  using rockfdem::fdem::detail::ContactTriangle;
  const int n = kPairBatch - 1;
  int apart = 0, apart_overlapping = 0, kept_touching = 0;
  const double zero = 0.0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    RoleParams rp;
    rp.p = 2.5;
    rp.dt = 1e-2;
    rp.friction = true;
    rp.damping = 0.2;
    Draw d = seed % 2 ? tricky_batch(seed, n) : random_batch(seed, n);
    rockfdem::fdem::detail::run_roles(d.b, n, rp, SimdIsa::kBaseline);
    for (int r = 0; r < n; ++r) {
      ContactTriangle a{}, t{};
      for (int k = 0; k < 3; ++k) {
        a.x[k] = d.a[r].x[k], a.y[k] = d.a[r].y[k];
        t.x[k] = d.t[r].x[k], t.y[k] = d.t[r].y[k];
      }
      rockfdem::fdem::detail::pack_geometry(a);
      rockfdem::fdem::detail::pack_geometry(t);
      if (!rockfdem::fdem::detail::pair_apart(a, t)) {
        kept_touching += d.b.touching[r] != 0.0;
        continue;
      }
      ++apart;
      const auto [alo, ahi] = std::minmax({a.x[0], a.x[1], a.x[2]});
      const auto [tlo, thi] = std::minmax({t.x[0], t.x[1], t.x[2]});
      const auto [blo, bhi] = std::minmax({a.y[0], a.y[1], a.y[2]});
      const auto [clo, chi] = std::minmax({t.y[0], t.y[1], t.y[2]});
      apart_overlapping += !(ahi < tlo || thi < alo || bhi < clo || chi < blo);
      EXPECT_EQ(d.b.touching[r], 0.0) << "seed " << seed << " lane " << r;
      for (int i = 0; i < 12; ++i)
        EXPECT_EQ(std::memcmp(&d.b.force[i][r], &zero, sizeof zero), 0)
            << "seed " << seed << " lane " << r << " force " << i << ": " << d.b.force[i][r];
      for (int j = 0; j < 6; ++j) {
        EXPECT_EQ(std::memcmp(&d.b.spring[j][r], &zero, sizeof zero), 0)
            << "seed " << seed << " lane " << r << " spring " << j;
        EXPECT_EQ(d.b.loss_friction[j][r], 0.0);
        EXPECT_EQ(d.b.loss_damping[j][r], 0.0);
      }
    }
  }
  EXPECT_GT(apart_overlapping, 200);  // the cases a box test leaves
  EXPECT_GT(kept_touching, 1000);
  EXPECT_GT(apart, apart_overlapping);
}

}  // namespace
