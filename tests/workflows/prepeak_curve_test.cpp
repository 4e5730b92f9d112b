// The pre-peak modulus of a UCS specimen (stages/prepeak_curve.hpp): the
// least-squares slope over 0.2-0.6 of the peak, from a buffer that halves
// itself when full. Closed forms: a line with a lag recovers its slope
// exactly, whatever the decimation.
#include "stages/prepeak_curve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using rockfdem::workflows::PrePeakCurve;

namespace {

// stress = E (strain - lag) up to 0.7 of the peak, then bending over to
// the peak (a parabola): the straight part is what the fit must read.
constexpr double kE = 4.3e9, kLag = 2e-4, kPeak = 23e6;
double stress_at(double strain) {
  const double knee = kLag + 0.7 * kPeak / kE;
  if (strain <= knee) return std::max(0.0, kE * (strain - kLag));
  const double x = strain - knee, w = 2 * 0.3 * kPeak / kE;  // reaches kPeak at x = w
  return 0.7 * kPeak + kE * x - kE * x * x / (2 * w);
}

}  // namespace

TEST(PrePeakCurve, slope_of_a_lagging_line_is_its_modulus_after_many_halvings) {
  PrePeakCurve c(16);
  const double peak_strain = kLag + 1.3 * kPeak / kE;
  const int n = 1000;
  for (int i = 0; i <= n; ++i) c.add(peak_strain * i / n, stress_at(peak_strain * i / n));
  const auto e = c.modulus(kPeak, peak_strain);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(*e, kE, 1e-9 * kE);
  // The secant at the peak, what a fit must not read: 23/(1.3 * 23 + 0.86) E.
  EXPECT_LT(kPeak / peak_strain, 0.98 * kE);
  // 1001 readings into 16 slots: four halvings, stride 64, the kept
  // strains the readings 0, 64, ..., 960 (an even spacing in steps), five
  // of them on the straight part.
  const auto s = c.state();
  EXPECT_EQ(s["stride"].get<long>(), 64);
  const auto strain = s["strain"].get<std::vector<double>>();
  ASSERT_EQ(strain.size(), 16u);
  for (std::size_t k = 0; k < strain.size(); ++k)
    EXPECT_DOUBLE_EQ(strain[k], peak_strain * double(64 * k) / n);
}

TEST(PrePeakCurve, restored_state_reads_the_same_modulus_and_keeps_its_stride) {
  PrePeakCurve a(64), b(64);
  const double peak_strain = kLag + 1.3 * kPeak / kE;
  for (int i = 0; i < 300; ++i) a.add(peak_strain * i / 500, stress_at(peak_strain * i / 500));
  b.restore(a.state());
  for (int i = 300; i <= 500; ++i) {
    a.add(peak_strain * i / 500, stress_at(peak_strain * i / 500));
    b.add(peak_strain * i / 500, stress_at(peak_strain * i / 500));
  }
  EXPECT_EQ(a.state(), b.state());
  EXPECT_EQ(*a.modulus(kPeak, peak_strain), *b.modulus(kPeak, peak_strain));
}

TEST(PrePeakCurve, too_few_points_on_the_straight_part_give_none) {
  PrePeakCurve c(16);
  c.add(0, 0);
  c.add(1e-3, 0.3 * kPeak);
  c.add(2e-3, 0.5 * kPeak);
  c.add(3e-3, kPeak);
  EXPECT_FALSE(c.modulus(kPeak, 3e-3).has_value());
}
