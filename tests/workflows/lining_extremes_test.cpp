// The ring's design extremes leave its corner segments out and report
// them apart (outputs/lining_extremes.hpp), on constructed forces.
#include "outputs/lining_extremes.hpp"

#include <gtest/gtest.h>

using namespace rockfdem::workflows;

namespace {

// Six segments, those listed as corners marked; forces [N/m, N m/m].
LiningGeometry ring(std::initializer_list<std::size_t> corners) {
  LiningGeometry g;
  g.segments.resize(6);
  for (std::size_t i : corners) g.segments[i].corner = true;
  return g;
}

std::vector<SectionForces> forces(const std::vector<double>& n, const std::vector<double>& m) {
  std::vector<SectionForces> f;
  for (std::size_t i = 0; i < n.size(); ++i) f.push_back({n[i], m[i], 0.1 * n[i]});
  return f;
}

}  // namespace

// A horseshoe's floor corners (segments 2 and 4) carry 900 kN/m and a
// tension of -233 kN/m, the sections at most 300 kN/m (segment 1): the
// design's largest thrust is 300 at segment 1, its smallest 50 at
// segment 5, its largest |M| 40 at segment 1 (its sign dropped); the
// corners' are 900 (segment 2), -233 (segment 4) and 80 (segment 2), and
// pass the sections'.
TEST(LiningExtremes, corner_segments_are_reported_apart) {
  const auto f =
      forces({100e3, 300e3, 900e3, 250e3, -233e3, 50e3}, {10e3, -40e3, 80e3, 30e3, -5e3, 20e3});
  const LiningExtremes x = lining_extremes(ring({2, 4}), f);
  EXPECT_EQ(x.sections.max_thrust.value, 300e3);
  EXPECT_EQ(x.sections.max_thrust.segment, 1u);
  EXPECT_EQ(x.sections.min_thrust.value, 50e3);
  EXPECT_EQ(x.sections.min_thrust.segment, 5u);
  EXPECT_EQ(x.sections.max_abs_moment.value, 40e3);
  EXPECT_EQ(x.sections.max_abs_moment.segment, 1u);
  EXPECT_EQ(x.sections.max_abs_shear.value, 30e3);
  ASSERT_TRUE(x.corners);
  EXPECT_EQ(x.corners->max_thrust.value, 900e3);
  EXPECT_EQ(x.corners->max_thrust.segment, 2u);
  EXPECT_EQ(x.corners->min_thrust.value, -233e3);
  EXPECT_EQ(x.corners->min_thrust.segment, 4u);
  EXPECT_EQ(x.corners->max_abs_moment.value, 80e3);
  EXPECT_TRUE(x.corners_exceed);
}

// Corners that carry less than the sections (and no tension) say nothing
// the sections do not: reported, not flagged.
TEST(LiningExtremes, quiet_corners_do_not_exceed) {
  const auto f =
      forces({100e3, 300e3, 120e3, 250e3, 90e3, 50e3}, {10e3, -40e3, 8e3, 30e3, -5e3, 20e3});
  const LiningExtremes x = lining_extremes(ring({2, 4}), f);
  EXPECT_EQ(x.sections.max_thrust.value, 300e3);
  ASSERT_TRUE(x.corners);
  EXPECT_EQ(x.corners->max_thrust.value, 120e3);
  EXPECT_FALSE(x.corners_exceed);
}

// A ring without corners (a circle) has its extremes over every segment;
// one of corners only keeps them too (nothing else to design with).
TEST(LiningExtremes, without_corners_every_segment_counts) {
  const auto f =
      forces({100e3, 300e3, 900e3, 250e3, -233e3, 50e3}, {10e3, -40e3, 80e3, 30e3, -5e3, 20e3});
  for (const LiningGeometry& g : {ring({}), ring({0, 1, 2, 3, 4, 5})}) {
    const LiningExtremes x = lining_extremes(g, f);
    EXPECT_FALSE(x.corners);
    EXPECT_EQ(x.sections.max_thrust.value, 900e3);
    EXPECT_EQ(x.sections.max_thrust.segment, 2u);
    EXPECT_EQ(x.sections.min_thrust.value, -233e3);
    EXPECT_EQ(x.sections.max_abs_moment.value, 80e3);
  }
}
