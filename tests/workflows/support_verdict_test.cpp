// The support verdict (run/support_verdict.hpp) on constructed figures: an
// overstressed lining and broken steel are named with their figures and
// where; a ring within its capacity and intact bars hold; a ring without a
// capacity to check is said to be unchecked.
#include "record/support_verdict.hpp"

#include <gtest/gtest.h>

using namespace rockfdem::workflows;

namespace {

LiningRecord ring(double min_sf, bool in_invert, long below_1) {
  LiningForceFigures f;
  f.segments = 98;
  f.capacity = "plain section";
  LiningCapacityFigures c;
  c.compressive_strength_Pa = 11.5e6;
  c.invert_compressive_strength_Pa = 30e6;
  c.invert_tensile_strength_Pa = 2.9e6;
  c.min_safety_factor = min_sf;
  c.min_safety_factor_in_invert = in_invert;
  c.min_safety_factor_angle_deg = 238;
  c.segments_below_1 = below_1;
  f.check = c;
  LiningRecord r;
  r.forces = f;
  r.interface = std::make_pair(98L, 93L);
  return r;
}

BoltFigures bar(const std::string& name, const std::string& kind, bool broken) {
  BoltFigures b;
  b.name = name;
  b.kind = kind;
  b.installed = true;
  BoltPeak p;
  p.file = name + ".csv";
  p.yielded = p.broken = broken;
  b.peak = p;
  return b;
}

}  // namespace

TEST(SupportVerdict, names_an_overstressed_invert_and_broken_bolts) {
  BoltRecord bolts;
  bolts.each = {bar("bolt_00", "bolt", false), bar("bolt_01", "bolt", true),
                bar("bolt_02", "bolt", true), bar("bolt_03", "cable", false)};
  const auto v = support_verdict(ring(0.56, true, 34), bolts);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->verdict, "overstressed");
  ASSERT_EQ(v->findings.size(), 2u);
  EXPECT_EQ(v->findings[0], "lining invert SF 0.56 at 238 deg, 34 of 98 segments below 1");
  EXPECT_EQ(v->findings[1], "2 of 3 bolts with broken steel (bolt_01, bolt_02)");
  EXPECT_EQ(v->line(),
            "support overstressed: lining invert SF 0.56 at 238 deg, 34 of 98 segments below 1; "
            "2 of 3 bolts with broken steel (bolt_01, bolt_02)");
  ASSERT_EQ(v->notes.size(), 1u);
  EXPECT_NE(v->notes[0].find("93 of 98 bond elements broken"), std::string::npos);
}

TEST(SupportVerdict, a_ring_within_capacity_and_intact_bars_hold) {
  BoltRecord bolts;
  bolts.each = {bar("bolt_00", "bolt", false), bar("bolt_01", "cable", false)};
  const auto v = support_verdict(ring(1.4, false, 0), bolts);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->verdict, "holds");
  EXPECT_TRUE(v->findings.empty());
  EXPECT_EQ(v->line(), "support holds");
  // SF exactly 1 is at capacity, not over it.
  EXPECT_EQ(support_verdict(ring(1.0, false, 0), std::nullopt)->verdict, "holds");
  EXPECT_EQ(support_verdict(ring(0.999, false, 1), std::nullopt)->verdict, "overstressed");
}

TEST(SupportVerdict, an_unchecked_ring_is_said_to_be_unchecked) {
  LiningRecord r = ring(0.5, false, 10);
  r.forces->check.reset();
  r.forces->capacity = "not checked: materials.lining.compressive_strength not given";
  const auto v = support_verdict(r, std::nullopt);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->verdict, "not checked");
  EXPECT_EQ(v->notes.at(0), "lining not checked: materials.lining.compressive_strength not given");
  EXPECT_FALSE(support_verdict(LiningRecord{}, std::nullopt));
}
