// The statistics of ensemble.csv (study/ensemble_stats.hpp) on samples
// with known answers, the grouping of a sweep's variants into realisations
// of one rock (study/ensemble_table.hpp) and the merging of a calibration
// point's realisations (study/realisations.hpp).
#include "study/ensemble_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "study/ensemble_table.hpp"
#include "study/realisations.hpp"

namespace study = rockfdem::workflows::study;

namespace {

study::VariantResult result(const std::string& status, double peak, const std::string& name = "") {
  return {name, status, "why", 1.0, false, {{"peak_stress_MPa", peak}, {"broken_I", 3}}};
}

}  // namespace

// Student's t 0.975 quantiles to 13 digits (mpmath, 30 digits: the root of
// the regularised incomplete beta function; the printed tables, e.g.
// Abramowitz & Stegun 26.10, agree to their digits), on both sides of the
// switch from the exact sums to the expansion (df 200 | 201), and the
// symmetry of the lower quantiles.
TEST(Ensemble, t_quantile_matches_tabulated_values) {
  const std::pair<long, double> table[] = {
      {1, 12.70620473617},   {2, 4.302652729749},   {5, 2.570581835636},   {7, 2.364624251593},
      {10, 2.228138851986},  {30, 2.042272456301},  {100, 1.983971518524}, {200, 1.971896223634},
      {201, 1.971836506780}, {1000, 1.962339080826}};
  for (const auto& [df, t] : table) {
    EXPECT_NEAR(study::student_t_quantile(0.975, df) / t, 1.0, 1e-11) << "df " << df;
    EXPECT_NEAR(study::student_t_quantile(0.025, df) / t, -1.0, 1e-11) << "df " << df;
  }
  EXPECT_NEAR(study::student_t_quantile(0.5, 9), 0.0, 1e-15);
  EXPECT_NEAR(study::student_t_quantile(0.95, 4), 2.131846786326649, 1e-12);
}

// 1..8: mean 4.5, s = sqrt(6) = 2.449489743, t_{0.975,7} = 2.364624252,
// so the interval's half-width is 2.364624252 s / sqrt(8) = 2.0478247.
TEST(Ensemble, sample_statistics_of_one_to_eight) {
  const study::SampleStats s = study::describe_sample({3, 1, 2, 8, 4, 5, 7, 6});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 4.5);
  EXPECT_NEAR(s.std, std::sqrt(6.0), 1e-12);
  const double half = 2.364624251592785 * std::sqrt(6.0) / std::sqrt(8.0);
  EXPECT_NEAR(half, 2.0478247, 1e-6);
  EXPECT_NEAR(s.ci95_low, 4.5 - half, 1e-9);
  EXPECT_NEAR(s.ci95_high, 4.5 + half, 1e-9);
  EXPECT_EQ(s.min, 1.0);
  EXPECT_EQ(s.max, 8.0);
  const study::SampleStats one = study::describe_sample({2.5});
  EXPECT_EQ(one.n, 1u);
  EXPECT_EQ(one.mean, 2.5);
  EXPECT_TRUE(std::isnan(one.std) && std::isnan(one.ci95_low) && std::isnan(one.ci95_high));
  const study::SampleStats none = study::describe_sample({});
  EXPECT_EQ(none.n, 0u);
  EXPECT_TRUE(std::isnan(none.mean) && std::isnan(none.min));
}

TEST(Ensemble, seed_keys_are_named_by_their_last_component) {
  for (const char* key : {"materials.rock.heterogeneity_seed", "materials.grout.heterogeneity_seed",
                          "heterogeneity_seed"})
    EXPECT_TRUE(study::is_seed_key(key)) << key;
  for (const char* key : {"materials.rock.heterogeneity", "materials.rock.xheterogeneity_seed",
                          "materials.rock.heterogeneity_seed.x", "engine.seed"})
    EXPECT_FALSE(study::is_seed_key(key)) << key;
}

// Two strengths, three and four seeds each. The second group's third seed
// stopped before equilibrium (its peak of 100 must not count) and its
// fourth has not run yet: n = 2 there, peaks 10 and 14.
TEST(Ensemble, variants_group_by_the_keys_that_are_not_seeds) {
  const std::vector<std::string> keys{"materials.rock.tensile_strength",
                                      "materials.rock.heterogeneity_seed"};
  std::vector<study::Variant> variants;
  for (const auto& [ft, seeds] : {std::pair{"4e6", 3}, std::pair{"5e6", 4}})
    for (int s = 1; s <= seeds; ++s)
      variants.push_back({"", {{keys[0], ft}, {keys[1], std::to_string(s)}}});
  const std::vector<study::VariantResult> results{
      result("completed", 1),           result("completed", 2),  result("completed", 3),
      result("completed", 10),          result("completed", 14), result("not_at_equilibrium", 100),
      {"", "pending", "", 0, false, {}}};
  const auto rows = study::ensemble_rows(keys, variants, results, {"peak_stress_MPa", "broken_I"});
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].group, std::vector<std::string>{"4e6"});
  EXPECT_EQ(rows[0].figure, "peak_stress_MPa");
  EXPECT_EQ(rows[0].realisations, 3u);
  EXPECT_EQ(rows[0].stats.n, 3u);
  EXPECT_EQ(rows[0].excluded + rows[0].pending, 0u);
  EXPECT_DOUBLE_EQ(rows[0].stats.mean, 2.0);
  EXPECT_DOUBLE_EQ(rows[0].stats.std, 1.0);
  EXPECT_NEAR(rows[0].stats.ci95_high, 2 + 4.302652729749464 / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(rows[1].figure, "broken_I");
  EXPECT_EQ(rows[1].stats.std, 0.0);
  const study::EnsembleRow& second = rows[2];
  EXPECT_EQ(second.group, std::vector<std::string>{"5e6"});
  EXPECT_EQ(second.realisations, 4u);
  EXPECT_EQ(second.stats.n, 2u);
  EXPECT_EQ(second.excluded, 1u);
  EXPECT_EQ(second.pending, 1u);
  EXPECT_DOUBLE_EQ(second.stats.mean, 12.0);
  EXPECT_DOUBLE_EQ(second.stats.std, std::sqrt(8.0));
  EXPECT_EQ(second.stats.min, 10.0);
  EXPECT_EQ(second.stats.max, 14.0);
  EXPECT_EQ(study::ensemble_figures({"peak_stress_MPa", "steps", "state_hash"}),
            (std::vector<std::string>{"peak_stress_MPa", "steps"}));
}

// A point's realisations: the figures are the mean over the completed ones
// (a run stopped short is left out, and makes the point's status its own);
// where none completed, over the ones stopped short, as a single run's
// figures would be taken; a failed run never counts. One run is itself.
TEST(Ensemble, realisations_merge_into_the_mean_of_the_completed_ones) {
  const study::Realisations three = study::merge_realisations(
      "p", {result("completed", 10, "s1"), result("not_at_equilibrium", 100, "s2"),
            result("completed", 14, "s3")});
  EXPECT_EQ(three.n, 2u);
  EXPECT_EQ(three.result.name, "p");
  EXPECT_EQ(three.result.status, "not_at_equilibrium");
  EXPECT_EQ(three.result.message, "realisation s2: why");
  EXPECT_DOUBLE_EQ(three.result.figures["peak_stress_MPa"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(three.stats.at("peak_stress_MPa").std, std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(three.result.wall_s, 3.0);
  const study::Realisations whole =
      study::merge_realisations("p", {result("completed", 1), result("completed", 2)});
  EXPECT_EQ(whole.result.status, "completed");
  EXPECT_EQ(whole.n, 2u);
  const study::Realisations short_ =
      study::merge_realisations("p", {result("failed", 7), result("unstable", 5)});
  EXPECT_EQ(short_.n, 1u);
  EXPECT_EQ(short_.result.status, "failed");
  EXPECT_DOUBLE_EQ(short_.result.figures["peak_stress_MPa"].get<double>(), 5.0);
  EXPECT_EQ(study::merge_realisations("p", {result("failed", 7), result("refused", 1)}).n, 0u);
  const study::Realisations one = study::merge_realisations("p", {result("failed", 7, "only")});
  EXPECT_EQ(one.n, 0u);
  EXPECT_EQ(one.result.name, "only");
  EXPECT_EQ(one.result.figures["peak_stress_MPa"], 7);
}
