// Core softening and the lining, against closed forms for a circular opening
// of radius a in hydrostatic far field p0 (plane strain, same E, nu in core
// and rock). The box is 80a wide with far-field tractions: the finite-box
// effect on the wall displacement is O((a/L)^2) ~ 0.1%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fixtures.hpp"

namespace rockfdem::insitu::test {
namespace {

constexpr double kP0 = 15e6;

TEST(CoreSoftening, wall_displacement_follows_the_soft_inclusion_closed_form) {
  // u(alpha) - u(1) = (S a/(2K)) [(K + mu)/(alpha K + mu) - 1], S = -p0: the
  // core's stress alpha (sigma0 + C eps) makes it an elastic inclusion of
  // stiffness alpha C pre-stressed by alpha sigma0 (derivation in
  // docs/insitu.md). Tolerance 1%: the P1 wall displacement and the finite
  // box together stay below 0.5% at this size (measured), so 1% fails on
  // any modelling error (scaling only the modulus gives u = 0 throughout).
  const mesh::Mesh m = polar_box_mesh({1.0, 40.0, 96, true, 0.0});
  InsituSpec spec = seed_spec(kP0, kP0);
  spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.01, 0.0};
  const auto fields = solve_insitu(m, spec);
  ASSERT_EQ(fields.size(), spec.alphas.size());
  double previous = 0;
  for (const InsituField& f : fields) {
    const double u = mean_wall_ur(m, f);
    const double exact = core_softening_wall_displacement(f.alpha, kP0, 1.0, kE, kNu);
    std::printf("  alpha %5.2f: wall u_r %.6e m, closed form %.6e m (%+.3f%%)\n", f.alpha, u, exact,
                f.alpha < 1 ? 100 * (u / exact - 1) : 0.0);
    if (f.alpha == 1.0) {
      EXPECT_LT(std::abs(u), 1e-12);  // nothing moves with the core intact
    } else {
      EXPECT_NEAR(u, exact, 0.01 * std::abs(exact));
      EXPECT_LT(u, previous);  // monotonic: more softening, more convergence
    }
    previous = u;
    EXPECT_LT(f.reaction_ratio, 1e-10);
  }
  // alpha = 0 is the open hole: S a / (2 mu).
  const double mu = kE / (2 * (1 + kNu));
  EXPECT_NEAR(mean_wall_ur(m, fields.back()), -kP0 / (2 * mu), 0.01 * kP0 / (2 * mu));
}

/// Closed form of a ring b <= r <= a (lining, installed stress-free when the
/// opening is excavated) in a hole in rock under p0: the support pressure p
/// makes the rock wall and the ring's outer face move together:
///   rock:  u(a) = -(p0 - p) a / (2 G)
///   ring:  u = A r + B / r with s_rr(b) = 0, s_rr(a) = -p.
struct LinedTunnel {
  double p;          ///< support pressure [Pa]
  double hoop_mean;  ///< area mean of the ring's hoop stress (tension +) [Pa]
  double wall_u;     ///< rock wall radial displacement [m]
};

LinedTunnel lined_tunnel(double p0, double a, double b, const ElasticMaterial& rock,
                         const ElasticMaterial& ring) {
  const double G = rock.E / (2 * (1 + rock.nu));
  const double mu = ring.E / (2 * (1 + ring.nu));
  const double lambda = ring.E * ring.nu / ((1 + ring.nu) * (1 - 2 * ring.nu));
  const double d = a * a - b * b;
  // Per unit p: A = -a^2/(2(lambda+mu) d), B = -a^2 b^2/(2 mu d).
  const double A1 = -a * a / (2 * (lambda + mu) * d), B1 = -a * a * b * b / (2 * mu * d);
  const double c_ring = -(A1 * a + B1 / a);  // inward wall motion per unit p
  const double c_rock = a / (2 * G);
  LinedTunnel out;
  out.p = p0 * c_rock / (c_ring + c_rock);
  out.wall_u = -(p0 - out.p) * c_rock;
  out.hoop_mean = out.p * (2 * (lambda + mu) * A1 + 2 * mu * B1 * 2 * std::log(a / b) / d);
  return out;
}

double mean_lining_hoop(const mesh::Mesh& m, const InsituField& f) {
  double num = 0, den = 0;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kLining) continue;
    const auto& tri = m.triangles[t];
    const double xa = m.x[tri[0]], ya = m.y[tri[0]], xb = m.x[tri[1]], yb = m.y[tri[1]];
    const double xc = m.x[tri[2]], yc = m.y[tri[2]];
    const double area = 0.5 * ((xb - xa) * (yc - ya) - (xc - xa) * (yb - ya));
    const double phi = std::atan2((ya + yb + yc) / 3, (xa + xb + xc) / 3);
    const double c = std::cos(phi), s = std::sin(phi);
    const Stress& st = f.stress[t];
    num += area * (st.sxx * s * s + st.syy * c * c - 2 * st.sxy * s * c);
    den += area;
  }
  return num / den;
}

TEST(Lining, ring_installed_at_excavation_matches_the_thick_ring_closed_form) {
  const double t = 0.1;
  const mesh::Mesh m = polar_box_mesh({1.0, 40.0, 128, true, t});
  InsituSpec spec = seed_spec(kP0, kP0);
  spec.lining.active = true;
  spec.lining.install_alpha = 1.0;
  spec.alphas = {0.0};
  const InsituField f = solve_insitu(m, spec).at(0);
  const LinedTunnel exact =
      lined_tunnel(kP0, 1.0, 1.0 - t, *spec.materials.rock, *spec.materials.lining);
  const double hoop = mean_lining_hoop(m, f), u = mean_wall_ur(m, f);
  std::printf(
      "  lining: hoop %.4e Pa (closed form %.4e), wall u_r %.4e m (closed form %.4e),"
      " support pressure %.3f p0\n",
      hoop, exact.hoop_mean, u, exact.wall_u, exact.p / kP0);
  EXPECT_TRUE(f.lining_installed);
  EXPECT_LT(hoop, 0);  // the ring is squeezed: compressive hoop stress
  EXPECT_NEAR(hoop, exact.hoop_mean, 0.02 * std::abs(exact.hoop_mean));
  EXPECT_NEAR(u, exact.wall_u, 0.02 * std::abs(exact.wall_u));
  // The core is gone, the lining stays.
  for (std::size_t i = 0; i < m.n_triangles(); ++i)
    EXPECT_EQ(f.active[i], m.zone[i] != mesh::kCore ? 1 : 0);
}

TEST(Lining, ring_active_during_softening_carries_growing_compressive_hoop_stress) {
  const mesh::Mesh m = polar_box_mesh({1.0, 20.0, 64, true, 0.1});
  InsituSpec spec = seed_spec();  // the seed's biaxial field
  spec.lining.active = true;
  spec.lining.install_alpha = 0.2;
  spec.alphas = {1.0, 0.5, 0.2, 0.1, 0.05, 0.0};
  const auto fields = solve_insitu(m, spec);
  double previous = 0;
  for (const InsituField& f : fields) {
    const double hoop = mean_lining_hoop(m, f);
    std::printf("  alpha %4.2f installed %d: lining mean hoop %.4e Pa, wall u_r %.4e m\n", f.alpha,
                f.lining_installed, hoop, mean_wall_ur(m, f));
    EXPECT_EQ(f.lining_installed, f.alpha <= 0.2);
    if (!f.lining_installed) continue;
    EXPECT_LT(hoop, previous);  // compressive, and more so as the core softens
    previous = hoop;
  }
  // Without the lining the wall converges more.
  InsituSpec unlined = spec;
  unlined.lining.active = false;
  const auto open = solve_insitu(m, unlined);
  EXPECT_LT(mean_wall_ur(m, open.back()), mean_wall_ur(m, fields.back()));
}

}  // namespace
}  // namespace rockfdem::insitu::test
