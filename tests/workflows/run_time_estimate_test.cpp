// check's run time from its probe (commands/run_time_estimate.hpp) on a
// constructed case, and its note on a busy machine; no wall time is
// measured or asserted here.
#include "commands/run_time_estimate.hpp"

#include <gtest/gtest.h>

#include "commands/check_probe.hpp"

using namespace rockfdem::workflows;

// 10 s of fixed costs, 2 ms a step, 50,000 steps at the caps and 25,000
// expected, 60% of the triangles in the fracture zone: the estimate raises
// the expected steps' 50 s by
// 1 + 0.6 (c_expected - 1), the bound the caps' 100 s by 1 + 0.6 (4 - 1)
// = 2.8 with the margin on the whole; the least is the fixed costs (every stage ended
// at once by its criterion).
TEST(RunTimeEstimate, estimate_lies_between_the_fixed_costs_and_the_bound) {
  const RunTimeFigures t = run_time({10.0, 2e-3, 50000, 25000, 0.6, false});
  const double expected = 1 + 0.6 * (kExpectedFractureCost - 1);
  EXPECT_DOUBLE_EQ(t.expected_step_factor, expected);
  EXPECT_DOUBLE_EQ(t.worst_step_factor, 2.8);
  EXPECT_DOUBLE_EQ(t.estimate, 10 + 50 * expected);  // the 25,000 steps expected
  EXPECT_DOUBLE_EQ(t.bound, kRunTimeMargin * (10 + 100 * 2.8));
  EXPECT_DOUBLE_EQ(t.least, 10);
  EXPECT_LT(t.least, t.estimate);
  EXPECT_LT(t.estimate, t.bound);
}

// A model that cannot fracture runs at the probe's cost: estimate and
// bound differ by the margin alone.
TEST(RunTimeEstimate, intact_model_is_estimated_at_the_probes_cost) {
  const RunTimeFigures t = run_time({3.0, 1e-3, 12000, 12000, 0.0, false});
  EXPECT_DOUBLE_EQ(t.estimate, 15.0);
  EXPECT_DOUBLE_EQ(t.bound, kRunTimeMargin * 15.0);
}

// Joints multiply a step's cost on top of fracture: the same model with
// joints has its steps' share of the estimate and of the bound raised by
// the joints' expected and worst costs, its fixed costs unchanged.
TEST(RunTimeEstimate, joints_raise_the_steps_not_the_fixed_costs) {
  const RunTimeFigures plain = run_time({4.0, 0.5e-3, 12000, 6000, 0.5, false});
  const RunTimeFigures jointed = run_time({4.0, 0.5e-3, 12000, 6000, 0.5, true});
  EXPECT_DOUBLE_EQ(jointed.estimate - 4.0, (plain.estimate - 4.0) * kExpectedJointCost);
  EXPECT_DOUBLE_EQ(jointed.bound / kRunTimeMargin - 4.0,
                   (plain.bound / kRunTimeMargin - 4.0) * kWorstJointCost);
  EXPECT_DOUBLE_EQ(jointed.least, plain.least);
}

// A rock that fails at once (expected_steps.hpp) is expected to cost
// kFailsAtOnceCost per fracturing step, not kExpectedFractureCost: on a
// share of 0.5 the steps' part of the estimate is 1 + 0.5 (c - 1) times
// theirs; the bound and the fixed costs do not change. With joints, the
// joints' cost alone.
TEST(RunTimeEstimate, a_rock_that_fails_at_once_costs_more_per_step) {
  RunTimeInputs in{4.0, 0.5e-3, 12000, 6000, 0.5, false};
  const RunTimeFigures crack_by_crack = run_time(in);
  in.fails_at_once = true;
  const RunTimeFigures at_once = run_time(in);
  EXPECT_DOUBLE_EQ(at_once.expected_step_factor, 1 + 0.5 * (kFailsAtOnceCost - 1));
  EXPECT_DOUBLE_EQ(at_once.estimate - 4.0, 3.0 * at_once.expected_step_factor);
  EXPECT_DOUBLE_EQ(crack_by_crack.estimate - 4.0, 3.0 * (1 + 0.5 * (kExpectedFractureCost - 1)));
  EXPECT_DOUBLE_EQ(at_once.bound, crack_by_crack.bound);
  // With joints their cost, measured on such a rock, stands alone.
  in.joints = true;
  EXPECT_DOUBLE_EQ(run_time(in).expected_step_factor,
                   (1 + 0.5 * (kExpectedFractureCost - 1)) * kExpectedJointCost);
}

// The probe's CPU share below one half (its threads descheduled by other
// work) adds a note naming the share and the threads; at or above, none.
TEST(RunTimeEstimate, a_busy_machine_is_named_beside_the_figures) {
  Probe p;
  p.threads = 2;
  p.cpu_share = 0.5;
  EXPECT_EQ(busy_machine_note(p), "");
  p.cpu_share = 0.28;
  const std::string note = busy_machine_note(p);
  EXPECT_NE(note.find("28% of 2 threads' time"), std::string::npos) << note;
  EXPECT_NE(note.find("read high"), std::string::npos) << note;
  p.threads = 1;
  EXPECT_NE(busy_machine_note(p).find("of 1 thread's time"), std::string::npos);
}

// Threads that spin while they wait keep the CPU share near 1 on a busy
// machine (a probe read 25 ms per step against 1.3 ms a minute later, at
// a share above one half): other work beyond half the cores, by the load
// average less the probe's own threads, is named too.
TEST(RunTimeEstimate, other_work_in_the_load_average_is_named) {
  Probe p;
  p.threads = 2;
  p.cores = 2;
  p.cpu_share = 0.95;
  p.load_average = 3.7;  // 1.7 beyond the probe's 2 threads: above 1 core
  const std::string note = busy_machine_note(p);
  EXPECT_NE(note.find("load average was 3.7 on 2 cores"), std::string::npos) << note;
  p.load_average = 2.9;  // 0.9 beyond: under half the cores
  EXPECT_EQ(busy_machine_note(p), "");
  p.load_average = -1;  // unknown
  EXPECT_EQ(busy_machine_note(p), "");
}
