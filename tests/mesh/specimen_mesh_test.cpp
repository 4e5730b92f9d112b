// Laboratory specimens: the UCS prism and the Brazilian disc, their areas,
// edge tags and the crack flag on every triangle.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh_checks.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/constants.hpp"

namespace rockfdem::mesh {
namespace {

using namespace checks;
MeshSpec ucs() {
  MeshSpec s;
  s.kind = ModelKind::kUcs;
  s.specimen.width = 0.05, s.specimen.height = 0.1;
  s.size.size_near = 0.004;
  return s;
}

MeshSpec disc() {
  MeshSpec s;
  s.kind = ModelKind::kBrazilian;
  s.specimen.diameter = 0.05, s.specimen.load_arc_deg = 10;
  s.size.size_near = 0.002;
  return s;
}

bool all_flagged_rock(const Mesh& m) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] != kRock || m.fracture[t] != 1 || signed_area(m, t) <= 0) return false;
  return true;
}

TEST(UcsSpecimen, area_is_width_times_height_and_every_triangle_may_crack) {
  const Mesh m = build_mesh(ucs());
  EXPECT_NEAR(zone_area(m, 0), 0.05 * 0.1, 1e-12 * 0.005);
  EXPECT_TRUE(all_flagged_rock(m));
}

// Platens: bottom at y = 0, top at y = height; sides at x = -+width/2.
TEST(UcsSpecimen, sides_are_tagged_where_they_lie) {
  const Mesh m = build_mesh(ucs());
  double length[5] = {0, 0, 0, 0, 0};
  for (const TaggedEdge& e : m.edges) {
    ASSERT_GE(e.tag, kBottom);
    ASSERT_LE(e.tag, kLeft);
    const double xm = (m.x[e.a] + m.x[e.b]) / 2, ym = (m.y[e.a] + m.y[e.b]) / 2;
    const double expected[5] = {0, 0, 0.025, 0.1, -0.025};  // by tag
    EXPECT_NEAR(e.tag == kBottom || e.tag == kTop ? ym : xm, expected[e.tag], 1e-12);
    length[e.tag] += edge_length(m, e.a, e.b);
  }
  EXPECT_NEAR(length[kBottom], 0.05, 1e-12);
  EXPECT_NEAR(length[kTop], 0.05, 1e-12);
  EXPECT_NEAR(length[kLeft], 0.1, 1e-12);
  EXPECT_NEAR(length[kRight], 0.1, 1e-12);
}

TEST(BrazilianDisc, area_is_pi_r2_within_chord_error) {
  const Mesh m = build_mesh(disc());
  const double r = 0.025, exact = kPi * r * r;
  TunnelSpec circle;
  circle.shape = TunnelShape::kCircular, circle.radius = r;
  const double bound = chord_loss_bound(tunnel_outline(circle), 1.3 * 0.002);
  const double area = zone_area(m, 0);
  EXPECT_LE(area, exact);
  EXPECT_GE(area, exact - bound);
  EXPECT_TRUE(all_flagged_rock(m));
}

// Each loading arc spans load_arc_deg about the vertical; its chords add up
// to between the arc's chord and the arc's length.
TEST(BrazilianDisc, loading_arcs_are_tagged_at_top_and_bottom) {
  const Mesh m = build_mesh(disc());
  const double r = 0.025, half = 5 * kPi / 180;
  double top = 0, bottom = 0, rim = 0;
  for (const TaggedEdge& e : m.edges) {
    EXPECT_NEAR(std::hypot(m.x[e.a], m.y[e.a]), r, 1e-12);
    const double a = std::atan2((m.y[e.a] + m.y[e.b]) / 2, (m.x[e.a] + m.x[e.b]) / 2);
    const double len = edge_length(m, e.a, e.b);
    const double off_vertical = std::abs(std::abs(a) - kPi / 2);
    if (e.tag == kRim) {
      EXPECT_GT(off_vertical, half);
      rim += len;
    } else {
      EXPECT_LT(off_vertical, half);
      EXPECT_EQ(a > 0, e.tag == kLoadTop);
      (e.tag == kLoadTop ? top : bottom) += len;
    }
  }
  for (double arc : {top, bottom}) {
    EXPECT_LE(arc, 2 * half * r);
    EXPECT_GE(arc, 2 * r * std::sin(half));
  }
  // Chords of angle phi fall short of their arc by R (phi - 2 sin(phi/2)),
  // at most a fraction phi^2 / 24 of it.
  const double phi = 2 * std::asin(1.3 * 0.002 / (2 * r));
  EXPECT_LE(top + bottom + rim, 2 * kPi * r);
  EXPECT_GE(top + bottom + rim, 2 * kPi * r * (1 - phi * phi / 24));
}

TEST(Specimens, bad_dimensions_are_input_errors) {
  MeshSpec s = ucs();
  s.specimen.width = -1;
  EXPECT_THROW(build_mesh(s), InputError);
  s = disc();
  s.specimen.load_arc_deg = 200;
  EXPECT_THROW(build_mesh(s), InputError);
}

}  // namespace
}  // namespace rockfdem::mesh
