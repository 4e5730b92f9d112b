// The lining integrator on analytic stress fields laid on a structured ring
// (lining_forces.hpp): a thick cylinder under external pressure carries the
// thrust p a (equilibrium of half the ring), a linear hoop stress the moment
// k t^3 / 12, a uniform shear stress the shear tau t; and the plain section's
// safety factor against its closed form.
#include "outputs/lining_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace rw = rockfdem::workflows;
namespace rm = rockfdem::mesh;

namespace {

constexpr double kInner = 2.7, kOuter = 3.0;  // lining radii [m]
constexpr int kAround = 180, kLayers = 3;

// Rings of quads split in two: lining from kInner to kOuter in kLayers
// layers, then two layers of rock to 4 m (an opening for find_opening).
rm::Mesh ring_mesh() {
  std::vector<double> radii;
  for (int j = 0; j <= kLayers; ++j) radii.push_back(kInner + (kOuter - kInner) * j / kLayers);
  radii.push_back(3.5);
  radii.push_back(4.0);
  rm::Mesh m;
  for (double r : radii)
    for (int i = 0; i < kAround; ++i) {
      m.x.push_back(r * std::cos(2 * M_PI * i / kAround));
      m.y.push_back(r * std::sin(2 * M_PI * i / kAround));
    }
  const auto id = [](int i, int j) { return j * kAround + i % kAround; };
  for (int j = 0; j + 1 < int(radii.size()); ++j)
    for (int i = 0; i < kAround; ++i) {
      const int zone = j < kLayers ? rm::kLining : rm::kRock;
      m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      m.zone.insert(m.zone.end(), 2, zone);
    }
  return m;
}

// A polar field (srr, stt, srt)(r), tension positive, at each triangle's
// centroid in Cartesian components.
std::vector<std::array<double, 3>> polar_field(
    const rm::Mesh& m, const std::function<std::array<double, 3>(double)>& f) {
  std::vector<std::array<double, 3>> out;
  for (const auto& v : m.triangles) {
    const double x = (m.x[v[0]] + m.x[v[1]] + m.x[v[2]]) / 3;
    const double y = (m.y[v[0]] + m.y[v[1]] + m.y[v[2]]) / 3;
    const double r = std::hypot(x, y), c = x / r, s = y / r;
    const auto [srr, stt, srt] = f(r);
    out.push_back({srr * c * c + stt * s * s - 2 * srt * s * c,
                   srr * s * s + stt * c * c + 2 * srt * s * c,
                   (srr - stt) * s * c + srt * (c * c - s * s)});
  }
  return out;
}

rw::LiningGeometry geometry(const rm::Mesh& m) {
  const auto g = rw::lining_geometry(m);
  EXPECT_TRUE(g.has_value());
  return g ? *g : rw::LiningGeometry{};
}

}  // namespace

// One segment per outer edge, counter-clockwise from 0 deg, each as thick
// as the ring (the outer chord's midpoint to the inner chord: t cos(pi/n)),
// the arc along the mid-line.
TEST(LiningForces, segments_follow_the_ring) {
  const rm::Mesh m = ring_mesh();
  for (std::size_t t = 0; t < m.n_triangles(); ++t) ASSERT_GT(rm::signed_area(m, t), 0) << t;
  const rw::LiningGeometry g = geometry(m);
  ASSERT_EQ(g.segments.size(), std::size_t(kAround));
  const double t = kOuter - kInner, rm_ = (kInner + kOuter) / 2;
  for (std::size_t i = 0; i < g.segments.size(); ++i) {
    const rw::LiningSegment& s = g.segments[i];
    EXPECT_NEAR(s.thickness, t * std::cos(M_PI / kAround), 1e-9) << i;
    EXPECT_NEAR(s.angle_deg, (i + 0.5) * 360.0 / kAround, 1e-9) << i;
    EXPECT_EQ(s.triangles.size(), std::size_t(2 * kLayers)) << i;
    EXPECT_NEAR(s.nx, std::cos(s.angle_deg * M_PI / 180), 1e-12) << i;
  }
  EXPECT_NEAR(g.segments.back().arc_m, 2 * M_PI * rm_ * (kAround - 1) / kAround, 0.01);
}

// Lame: external pressure p on the ring (b, a), none inside. Half the ring
// is held by the thrust at its two cuts, so N = p a exactly; its moment
// about the mid-line is the first moment of C (1 + b^2 / r^2), C = p a^2 /
// (a^2 - b^2): M = C b^2 (ln(a/b) - r_m t / (a b)) < 0 (the opening's side
// more compressed). Tolerances: 0.2% on N, 2% on M (centroid sampling).
TEST(LiningForces, thick_cylinder_carries_p_times_outer_radius) {
  const rm::Mesh m = ring_mesh();
  const double p = 2e6, a = kOuter, b = kInner, t = a - b, r_mid = (a + b) / 2;
  const double C = p * a * a / (a * a - b * b);
  const auto stress = polar_field(m, [&](double r) {
    return std::array<double, 3>{-C * (1 - b * b / (r * r)), -C * (1 + b * b / (r * r)), 0};
  });
  const double moment = C * b * b * (std::log(a / b) - r_mid * t / (a * b));
  for (const rw::SectionForces& f : rw::lining_forces(geometry(m), stress)) {
    EXPECT_NEAR(f.thrust, p * a, 0.002 * p * a);
    EXPECT_NEAR(f.moment, moment, 0.02 * std::abs(moment));
    EXPECT_NEAR(f.shear, 0, 1e-3 * p * a);  // triangles off the cut: O(h / R)
  }
}

// A hoop stress linear through the thickness, compression k (r - r_m):
// the moment is k t^3 / 12 (the rock side compressed: positive) and the
// thrust nearly none (the ring's curvature weights the outer half by r:
// k t^3 / (12 r_m)); a uniform shear stress tau (tension positive) gives
// V = -tau t in the compression-positive convention. Tolerance 1%.
TEST(LiningForces, linear_hoop_stress_gives_the_moment_and_shear_the_shear) {
  const rm::Mesh m = ring_mesh();
  const double k = 1e8, tau = 3e5, t = kOuter - kInner, r_mid = (kOuter + kInner) / 2;
  const auto bending = polar_field(m, [&](double r) {
    return std::array<double, 3>{0, -k * (r - r_mid), 0};
  });
  for (const rw::SectionForces& f : rw::lining_forces(geometry(m), bending)) {
    EXPECT_NEAR(f.moment, k * t * t * t / 12, 0.01 * k * t * t * t / 12);
    EXPECT_NEAR(f.thrust, k * t * t * t / (12 * r_mid), 0.01 * k * t * t);
  }
  const auto shear = polar_field(m, [&](double) { return std::array<double, 3>{0, 0, tau}; });
  for (const rw::SectionForces& f : rw::lining_forces(geometry(m), shear)) {
    EXPECT_NEAR(f.shear, -tau * t, 0.01 * tau * t);
    EXPECT_NEAR(f.thrust, 0, 1e-3 * tau * t);
  }
}

// The elastic plain section: fibre stresses N/t +- 6M/t^2 against fc and
// -ft; the factor scales (N, M) onto the envelope.
TEST(LiningForces, safety_factor_of_the_plain_section) {
  const rw::ShotcreteStrength s{30e6, 3e6};
  const double t = 0.2;
  EXPECT_DOUBLE_EQ(rw::safety_factor({3e6, 0, 0}, t, s), 2.0);  // N/t = fc / 2
  EXPECT_NEAR(rw::safety_factor({0, 1e4, 0}, t, s), 3e6 * t * t / 6e4, 1e-12);
  // N/t = 5 MPa, 6M/t^2 = 1.5 MPa: the compressed fibre at 6.5 MPa.
  EXPECT_NEAR(rw::safety_factor({1e6, -1e4, 0}, t, s), 30.0 / 6.5, 1e-12);
  // A small thrust with a large moment: the tensile fibre governs.
  const rw::SectionForces f{2e5, 3e4, 0};
  const double fs = rw::safety_factor(f, t, s);
  EXPECT_NEAR(fs * (f.thrust / t - 6 * f.moment / (t * t)), -s.tensile, 1e-6);
  EXPECT_TRUE(std::isinf(rw::safety_factor({0, 0, 5e4}, t, s)));
  // The envelope's corners: N = fc t, ft t at M = 0; M = (fc + ft) t^2 / 12.
  const auto e = rw::capacity_envelope(t, s, 1.0);
  EXPECT_DOUBLE_EQ(e[0][1], 30e6 * t);
  EXPECT_DOUBLE_EQ(e[1][0], 33e6 * t * t / 12);
  EXPECT_DOUBLE_EQ(e[1][1], 27e6 * t / 2);
  EXPECT_DOUBLE_EQ(e[2][1], -3e6 * t);
  EXPECT_NEAR(rw::safety_factor({e[1][1], e[1][0], 0}, t, s), 1.0, 1e-12);
}
