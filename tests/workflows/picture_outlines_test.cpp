// The outlines drawn over a tunnel's pictures: the dashes of the fracture
// zone's edge and the magnification of the deformed opening.
#include "outputs/picture_outlines.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace rockfdem::workflows {
namespace {

double length(const std::array<double, 4>& s) { return std::hypot(s[2] - s[0], s[3] - s[1]); }

// 1 m in dashes of 0.1 m: five dashes, 0.5 m drawn, each starting 0.2 m
// after the last; the phase runs on into the next segment.
TEST(PictureOutlines, dashes_alternate_with_gaps_of_their_length) {
  const auto d = dashed({{0, 0, 1, 0}}, 0.1);
  ASSERT_EQ(d.size(), 5u);
  double drawn = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    drawn += length(d[i]);
    EXPECT_NEAR(d[i][0], 0.2 * double(i), 1e-12);
  }
  EXPECT_NEAR(drawn, 0.5, 1e-12);
  // 0.15 m then 0.15 m: a dash, half a gap; the second starts in the gap.
  const auto two = dashed({{0, 0, 0.15, 0}, {0, 1, 0.15, 1}}, 0.1);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(length(two[0]), 0.1, 1e-12);
  EXPECT_NEAR(two[1][0], 0.05, 1e-12);
}

// The largest displacement drawn as about a tenth of the span, the factor
// a round number, never below 1.
TEST(PictureOutlines, magnification_is_round_and_draws_a_tenth_of_the_span) {
  EXPECT_EQ(outline_magnification(0.012, 6.0), 50.0);   // 0.6 m / 12 mm = 50
  EXPECT_EQ(outline_magnification(0.035, 10.0), 20.0);  // 28.6 -> 20
  EXPECT_EQ(outline_magnification(2.0, 10.0), 1.0);     // already large
  EXPECT_EQ(outline_magnification(0.0, 10.0), 1.0);
}

}  // namespace
}  // namespace rockfdem::workflows
