// Bit-identical results for any thread count: a small fracturing UCS run with
// 1 and 2 threads must give the same state hash (and the same broken counts).
#include <gtest/gtest.h>

#include "test_models.hpp"

namespace rockfdem::fdem {
namespace {

struct RunSummary {
  std::string hash;
  BrokenCounts broken;
  double unbalanced, kinetic;
};

RunSummary run_ucs(int threads) {
  RectangleSpec grid = ucs_grid(0.02, 0.04, 1600);
  Material m = test::rock();
  m.damping_ratio = 0.1;
  ModelInput in = ucs_specimen(grid, m, 2.0);
  in.threads = threads;
  in.damping.local = 0.05;
  Engine e(in);
  e.run(6000);
  return {e.state_hash(), e.broken_counts(), e.unbalanced_force_ratio(), e.kinetic_energy()};
}

TEST(Determinism, fracturing_ucs_same_hash_with_1_and_2_threads) {
  const RunSummary one = run_ucs(1), two = run_ucs(2);
  EXPECT_GT(one.broken.total(), 0) << "the run must fracture to test anything";
  EXPECT_EQ(one.hash, two.hash);
  EXPECT_EQ(one.broken.mode_I, two.broken.mode_I);
  EXPECT_EQ(one.broken.mode_II, two.broken.mode_II);
  EXPECT_EQ(one.broken.mixed, two.broken.mixed);
  EXPECT_EQ(one.unbalanced, two.unbalanced);
  EXPECT_EQ(one.kinetic, two.kinetic);
}

}  // namespace
}  // namespace rockfdem::fdem
