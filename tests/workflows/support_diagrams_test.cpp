// support_forces.png's diagrams: a round scale that draws the largest
// ordinate within its length, ordinates offset along the member's normal
// and split by sign, and the ring's thrust and moment drawn inward for
// compression and for the opening's face in tension.
#include "outputs/support_diagrams.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockfdem::workflows;

namespace {

// 1, 2 or 5 times a power of ten.
bool round_value(double s) {
  const double f = s / std::pow(10.0, std::floor(std::log10(s) + 1e-12));
  return std::abs(f - 1) < 1e-9 || std::abs(f - 2) < 1e-9 || std::abs(f - 5) < 1e-9;
}

}  // namespace

TEST(SupportDiagrams, scale_is_round_and_draws_the_largest_value_within_its_length) {
  for (const double max_abs : {0.37, 1.0, 2400.0, 1714.3, 5e4, 9.99e5})
    for (const double length : {0.3, 1.4, 2.0}) {
      const double s = diagram_scale(max_abs, length);
      EXPECT_TRUE(round_value(s)) << s;
      EXPECT_LE(max_abs / s, length * (1 + 1e-12)) << max_abs << " " << length;
      EXPECT_GE(max_abs / s, 0.4 * length * (1 - 1e-12)) << max_abs << " " << length;
    }
  EXPECT_EQ(diagram_scale(2400, 1.4), 2000);  // 1714 kN/m per metre rounded up
  EXPECT_EQ(diagram_scale(0, 1.4), 1);
}

// A bar along x from 0 to 3 with normal +y: values 2, 1, -1, -2 at scale
// 2 per metre. Ordinates at y = v / 2; hatching and outline pieces by sign
// (the piece from 1 to -1 has mean 0: positive).
TEST(SupportDiagrams, ordinates_lie_along_the_normal_split_by_sign) {
  const std::vector<DiagramPoint> bar{
      {0, 0, 0, 1, 2}, {1, 0, 0, 1, 1}, {2, 0, 0, 1, -1}, {3, 0, 0, 1, -2}};
  rockfdem::plots::PictureLines pos, neg;
  diagram_lines(bar, 2.0, false, pos, neg);
  // Hatching: 2 positive, 2 negative; outline: 3 pieces, 2 with mean >= 0.
  EXPECT_EQ(pos.segments.size(), 4u);
  EXPECT_EQ(neg.segments.size(), 3u);
  EXPECT_EQ(pos.segments[0], (std::array<double, 4>{0, 0, 0, 1}));       // hatch at x = 0
  EXPECT_EQ(pos.segments[1], (std::array<double, 4>{0, 1, 1, 0.5}));     // outline to x = 1
  EXPECT_EQ(neg.segments.back(), (std::array<double, 4>{3, 0, 3, -1}));  // hatch at x = 3
  // Closed (a ring): one more outline piece, the last point back to the first.
  rockfdem::plots::PictureLines cpos, cneg;
  diagram_lines(bar, 2.0, true, cpos, cneg);
  EXPECT_EQ(cpos.segments.size() + cneg.segments.size(), 8u);
  EXPECT_EQ(cpos.segments.back(), (std::array<double, 4>{3, -1, 0, 1}));
}

// A ring of radius 5 about the origin, four segments (normals outward):
// a thrust of 1000 kN/m is drawn towards the centre, a moment of -50 kNm/m
// (the rock's face in tension) away from it; a corner segment is left out.
TEST(SupportDiagrams, ring_thrust_compression_and_opening_side_tension_are_drawn_inward) {
  LiningGeometry g;
  for (int k = 0; k < 4; ++k) {
    const double a = k * M_PI / 2;
    LiningSegment s;
    s.angle_deg = 90.0 * k;
    s.x = 5 * std::cos(a), s.y = 5 * std::sin(a);
    s.nx = std::cos(a), s.ny = std::sin(a);
    s.tx = -std::sin(a), s.ty = std::cos(a);
    g.segments.push_back(s);
  }
  std::vector<SectionForces> f(4);
  for (SectionForces& s : f) s.thrust = 1000e3, s.moment = -50e3;
  const std::vector<std::vector<DiagramPoint>> runs = lining_diagram(g, f, false);
  ASSERT_EQ(runs.size(), 1u);
  const std::vector<DiagramPoint>& n = runs[0];
  const std::vector<DiagramPoint> m = lining_diagram(g, f, true).at(0);
  ASSERT_EQ(n.size(), 4u);
  rockfdem::plots::PictureLines comp, tens, mp, mn;
  diagram_lines(n, 1000.0, true, comp, tens);  // 1 m per 1000 kN/m
  diagram_lines(m, 100.0, true, mp, mn);       // 1 m per 100 kNm/m
  EXPECT_TRUE(tens.segments.empty());
  EXPECT_TRUE(mp.segments.empty());
  // The crown's segment (k = 1): thrust ordinate at radius 4, moment's at 5.5.
  EXPECT_NEAR(comp.segments[2][3], 4.0, 1e-12);
  EXPECT_NEAR(mn.segments[2][3], 5.5, 1e-12);
  EXPECT_NEAR(n[1].value, 1000.0, 1e-9);
  EXPECT_NEAR(m[1].value, -50.0, 1e-9);
  // A corner at segment 2 (a horseshoe's floor corner: no beam section)
  // is left out; the run after it goes on through segment 0: 3, 0, 1.
  g.segments[2].corner = true;
  const auto cut = lining_diagram(g, f, false);
  ASSERT_EQ(cut.size(), 1u);
  ASSERT_EQ(cut[0].size(), 3u);
  EXPECT_NEAR(cut[0][0].y, -5.0, 1e-12);
  EXPECT_NEAR(cut[0][1].x, 5.0, 1e-12);
}
