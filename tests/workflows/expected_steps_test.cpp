// The explicit steps check expects a run to take (commands/expected_steps.hpp):
// the stage arithmetic on constructed scenes, and the count check prints
// against the steps a small tunnel's run took. Step counts only: they do
// not depend on the machine's load, run times do.
#include "commands/expected_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "cli_runner.hpp"

using namespace rockfdem::workflows;
using namespace rockfdem::test;

namespace {

StageSpec stage(const std::string& kind, long max_steps, double ratio = 1e-3) {
  StageSpec st;
  st.kind = kind;
  st.max_steps = max_steps;
  st.ratio = ratio;
  st.every_steps = 1000;
  st.hold = 2;
  return st;
}

Scene tunnel(std::vector<StageSpec> stages) {
  Scene s;
  s.mesh.kind = rockfdem::mesh::ModelKind::kTunnel;
  s.stages = std::move(stages);
  return s;
}

}  // namespace

// On a transit of 100 steps an equilibrium stage of an elastic model at the
// default ratio takes kElasticTransits transits, one of a model that
// fractures (a fracture zone) kFractureTransits, rounded up to its outputs
// (1000 steps);
// a ratio of 1e-6 doubles the transits (ln 1e6 / ln 1e3 = 2); a cap below
// either is kept; a stage applied without steps adds none; the hand-off
// adds one step.
TEST(ExpectedSteps, a_ratio_stage_takes_its_transits_rounded_to_outputs_within_its_cap) {
  const double transit = 100;
  const double n = std::ceil(kElasticTransits * transit / 1000) * 1000;
  EXPECT_DOUBLE_EQ(
      expected_steps(tunnel({stage("lining", 0), stage("equilibrium", 60000)}), transit), 1 + n);
  Scene fracturing = tunnel({stage("equilibrium", 60000)});
  fracturing.mesh.tunnel.fracture_zone = 4;
  EXPECT_DOUBLE_EQ(expected_steps(fracturing, transit),
                   1 + std::ceil(kFractureTransits * transit / 1000) * 1000);
  const double n6 = std::ceil(2 * kElasticTransits * transit / 1000) * 1000;
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("equilibrium", 60000, 1e-6)}), transit), 1 + n6);
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("equilibrium", 1500)}), transit), 1 + 1500);
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("grout", 60000)}), transit),
                   1 + kGroutTransits * transit);
}

// No stage ends before `hold` outputs have met its criterion: on a transit
// of one step an equilibrium stage still takes two output intervals.
TEST(ExpectedSteps, a_ratio_stage_takes_at_least_its_held_outputs) {
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("equilibrium", 60000)}), 1.0), 1 + 2000);
}

// Where the transit is not known (a .msh model), a stage that ends at a
// criterion is expected at half its cap; the bound's caps are unchanged.
TEST(ExpectedSteps, without_a_transit_a_criterion_stage_is_expected_at_half_its_cap) {
  const Scene s =
      tunnel({stage("equilibrium", 60000), stage("soften", 4000), stage("grout", 20000)});
  EXPECT_DOUBLE_EQ(expected_steps(s, 0), 1 + 30000 + 2000 + 10000);
  EXPECT_DOUBLE_EQ(explicit_steps(s), 1 + 84000);
}

// The transit in steps scales with the box: the same tunnel in a box twice
// as wide and high (the graded mesh's layers outside the grading distance
// at the far size) takes longer, and on half the step twice as many steps.
TEST(ExpectedSteps, the_transit_grows_with_the_box_and_with_a_shorter_step) {
  Scene s = tunnel({});
  s.mesh.tunnel.shape = rockfdem::mesh::TunnelShape::kCircular;
  s.mesh.tunnel.radius = 3;
  s.mesh.domain.width = s.mesh.domain.height = 50;
  s.mesh.size.size_near = 0.3;
  s.mesh.size.size_far = 6;
  s.mesh.size.grading_distance = 25;
  s.engine.mass_scaling = true;
  const double small = transit_steps(s, 1e-4, 1500);
  EXPECT_NEAR(transit_steps(s, 0.5e-4, 1500), 2 * small, 1e-9 * small);
  s.mesh.domain.width = s.mesh.domain.height = 100;
  EXPECT_GT(transit_steps(s, 1e-4, 1500), small);
}

// The count check prints against runs: the elastic circular tunnel (its
// equilibrium stage at a ratio of 1e-5, 20,000 steps at most; one of the
// two elastic runs kElasticTransits was fitted on) and a variant the fit
// never saw (a 60 m box, a ratio of 1e-4) each take between half and
// twice the steps check expects.
TEST(ExpectedSteps, a_small_tunnels_run_takes_within_twice_the_steps_check_expects) {
  const std::string scene = kTestDir + "/elastic_circular.toml";
  for (const std::string sets :
       {"", " --set stages[2].ratio=1e-4 --set domain.width=60 --set domain.height=60"}) {
    const Result check = run("check " + scene + sets + " -j 2");
    ASSERT_EQ(check.code, 0) << check.output;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(check.output, m,
                                  std::regex(R"(explicit steps \(expected\):\s+([0-9]+))")))
        << check.output;
    const double expected = std::stod(m[1]);
    const auto out = scratch("expected-steps");
    const Result r = run("run " + scene + sets + " -q -j 2 --force -o " + out.string());
    ASSERT_EQ(r.code, 0) << r.output;
    const double steps = read_json(out / "summary.json")["steps"].get<double>();
    EXPECT_GE(steps, 0.5 * expected) << sets << ": expected " << expected;
    EXPECT_LE(steps, 2.0 * expected) << sets << ": expected " << expected;
  }
}
