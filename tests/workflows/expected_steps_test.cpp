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

// On a transit of 100 steps an equilibrium stage at the default ratio
// settles in kSettleTransits transits, rounded up to its outputs (1000
// steps); a ratio of 1e-6 doubles the transits (ln 1e6 / ln 1e3 = 2); a
// cap below either is kept; a stage applied without steps adds none; the
// hand-off adds one step; a grout stage fires after kGroutTransits.
TEST(ExpectedSteps, a_ratio_stage_takes_its_transits_rounded_to_outputs_within_its_cap) {
  const double transit = 100;
  const double n = std::ceil(kSettleTransits * transit / 1000) * 1000;
  EXPECT_DOUBLE_EQ(
      expected_steps(tunnel({stage("lining", 0), stage("equilibrium", 60000)}), transit), 1 + n);
  const double n6 = std::ceil(2 * kSettleTransits * transit / 1000) * 1000;
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("equilibrium", 60000, 1e-6)}), transit), 1 + n6);
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("equilibrium", 1500)}), transit), 1 + 1500);
  EXPECT_DOUBLE_EQ(expected_steps(tunnel({stage("grout", 60000)}), transit),
                   1 + kGroutTransits * transit);
}

// The seed's rock (c 3 MPa, phi 30: UCS 10.4 MPa) under 18.2 / 11.4 MPa
// has a wall stress of 3 x 18.2 - 11.4 = 43.2 MPa: it fails at the
// opening, and its failure's kFailureTransits are spent by the stages in
// order. Four soften stages of 4,000 steps on a transit of 364 steps stop
// at their caps (11 transits each, 44 spent), a grout stage fires after
// kGroutTransits (12 more), and the equilibrium stage settles in
// kSettleTransits plus what is left (65 - 44 - 12 = 9), rounded up to its
// outputs. With c 30 MPa (UCS 104 MPa) the rock holds: the equilibrium
// stage settles alone. Without a soften stage it fails at once.
TEST(ExpectedSteps, a_failing_rocks_transits_are_spent_by_the_stages_in_order) {
  std::vector<StageSpec> stages(4, stage("soften", 4000));
  stages.push_back(stage("grout", 20000));
  stages.push_back(stage("equilibrium", 60000));
  Scene s = tunnel(stages);
  s.mesh.tunnel.fracture_zone = 8;
  s.insitu.sigma_h = 18.2e6;
  s.insitu.sigma_v = 11.4e6;
  MaterialSpec rock;
  rock.cohesion = 3e6;
  rock.friction_angle = 30;
  s.materials[rockfdem::mesh::kRock] = rock;
  const double transit = 364;
  ASSERT_TRUE(rock_fails_at_opening(s));
  EXPECT_FALSE(fails_at_once(s));
  const double grout = kGroutTransits * transit;
  const double left = kFailureTransits - 4 * 4000 / transit - kGroutTransits;
  const double settle = std::ceil((kSettleTransits + left) * transit / 1000) * 1000;
  EXPECT_DOUBLE_EQ(expected_steps(s, transit), 1 + 16000 + grout + settle);
  s.materials[rockfdem::mesh::kRock].cohesion = 30e6;
  EXPECT_FALSE(rock_fails_at_opening(s));
  EXPECT_DOUBLE_EQ(expected_steps(s, transit),
                   1 + 16000 + grout + std::ceil(kSettleTransits * transit / 1000) * 1000);
  s.materials[rockfdem::mesh::kRock].cohesion = 3e6;
  s.stages.erase(s.stages.begin(), s.stages.begin() + 4);
  EXPECT_TRUE(fails_at_once(s));
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
// runs kSettleTransits was fitted on) and a variant the fit never saw (a
// 60 m box, a ratio of 1e-4) each take between half and twice the steps
// check expects.
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
    std::filesystem::remove_all(out);
  }
}
