// The grout stage's triggers fire at their moment (docs/support.md,
// "Grouting"). grout_trigger.toml removes the core, takes 8 steps (cracks
// break: N0 > 0 when the bolts go in) and installs the bolts; its grout
// stage gets one trigger by --set. Runs are deterministic (-j 1), so a
// trigger fired at the stage's step s is checked at its moment by a second
// run capped at s - 1 steps: there the condition must not hold yet, and in
// the first run it must hold at s (the broken count N after step s).
//   trigger_broken = n                N >= n
//   trigger_broken_since_support = n  N - N0 >= n
//   trigger_broken_growth = g         N - N0 >= g N0 and N > N0
//   trigger_steps = k                 the stage's k-th step
// The stage reports the trigger, its value, the step and time at which it
// fired and N then, in summary.json and in report.md's stage table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "cli_runner.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

const std::string kScene = kTestDir + "/grout_trigger.toml";
constexpr int kGrout = 4;  // stages[4]

struct Run {
  nlohmann::json summary, grout, bolts;
  std::string report;
};

Run run_with(const std::string& name, const std::string& sets) {
  const fs::path out = scratch(name);
  const Result r = run("run " + kScene + " -q -j 1 -o " + out.string() + " " + sets);
  Run result;
  EXPECT_TRUE(r.code == 0 || r.code == 4) << r.output;  // 4: not at equilibrium
  result.summary = read_json(out / "summary.json");
  result.report = read_text(out / "report.md");
  for (const nlohmann::json& s : result.summary.at("fdem").at("stages")) {
    if (s.at("kind") == "grout") result.grout = s;
    if (s.at("kind") == "bolts") result.bolts = s;
  }
  fs::remove_all(out);
  return result;
}

std::string set(const std::string& key, const std::string& value) {
  return "--set stages[" + std::to_string(kGrout) + "]." + key + "=" + value;
}

long broken(const Run& r) { return r.grout.at("changes").at("broken_before").get<long>(); }

// Fires the trigger, then caps the stage one step before its moment.
// `holds(N, N0, steps)` is the trigger's condition after the stage's
// steps-th step. Returns the stage's steps.
long check_moment(const std::string& key, const std::string& value,
                  const std::function<bool(long, long, long)>& holds) {
  const Run fired = run_with(key, set(key, value));
  const nlohmann::json& c = fired.grout.at("changes");
  EXPECT_TRUE(c.at("triggered").get<bool>()) << c;
  EXPECT_EQ(c.at("trigger"), key);
  EXPECT_DOUBLE_EQ(c.at("trigger_value").get<double>(), std::stod(value));
  const long s = fired.grout.at("steps").get<long>();
  const long n0 = fired.bolts.at("changes").at("broken_at_install").get<long>();
  EXPECT_GT(n0, 0) << "cracks broke before the bolts went in";
  if (c.contains("broken_at_support")) {
    EXPECT_EQ(c.at("broken_at_support").get<long>(), n0);
  }
  EXPECT_TRUE(holds(broken(fired), n0, s)) << key << " at step " << s << ": N = " << broken(fired);
  // The rays read the zone broken at some time as well as what is broken
  // now: grouting re-joined cracks, so it reaches at least as deep.
  double deepest = 0;
  for (const auto& [ray, r] : fired.summary.at("broken_zone").at("along_rays").items()) {
    const double ever = r.at("broken_or_grouted_depth_m").get<double>();
    EXPECT_GE(ever, r.at("depth_m").get<double>()) << ray;
    deepest = std::max(deepest, ever);
  }
  EXPECT_GT(deepest, 0.0) << "the grouted cracks lie along no ray";
  // The moment: step and time at the stage's end (the trigger ends it), the
  // run's step count (hand-off step 1 plus every stage's steps).
  long step = 1;
  double time = fired.summary.at("fdem").at("handoff_step").at("simulated_time").get<double>();
  for (const nlohmann::json& st : fired.summary.at("fdem").at("stages")) {
    step += st.at("steps").get<long>();
    time += st.at("simulated_time").get<double>();
    if (st.at("kind") == "grout") break;
  }
  EXPECT_EQ(c.at("trigger_step").get<long>(), step);
  EXPECT_NEAR(c.at("trigger_time").get<double>(), time, 1e-12 * time);
  EXPECT_NE(fired.report.find(key + " = " + value + " at step " + std::to_string(step)),
            std::string::npos)
      << fired.report;
  // One step earlier the condition does not hold, and the stage, capped
  // there, is not triggered (a step trigger beyond its cap is refused: its
  // moment is the stage's step count itself).
  EXPECT_GT(s, 1) << key << " fired at the stage's first step: choose a later value";
  long before_n = -1;
  if (key != "trigger_steps") {
    const Run before =
        run_with(key + "-before", set(key, value) + " " + set("max_steps", std::to_string(s - 1)));
    EXPECT_FALSE(before.grout.at("changes").at("triggered").get<bool>());
    EXPECT_EQ(before.grout.at("steps").get<long>(), s - 1);
    before_n = broken(before);
    EXPECT_FALSE(holds(before_n, n0, s - 1)) << key << " at step " << s - 1 << ": N = " << before_n;
  }
  std::printf(
      "%s = %s: fired at the stage's step %ld (run step %ld), N0 = %ld, N = %ld; "
      "one step before N = %ld\n",
      key.c_str(), value.c_str(), s, step, n0, broken(fired), before_n);
  return s;
}

}  // namespace

TEST(GroutTrigger, broken_total_fires_at_its_moment) {
  check_moment("trigger_broken", "280", [](long n, long, long) { return n >= 280; });
}

TEST(GroutTrigger, broken_since_support_fires_at_its_moment) {
  check_moment("trigger_broken_since_support", "150",
               [](long n, long n0, long) { return n - n0 >= 150; });
}

TEST(GroutTrigger, broken_growth_fires_at_its_moment) {
  check_moment("trigger_broken_growth", "1.95",
               [](long n, long n0, long) { return n > n0 && double(n - n0) >= 1.95 * double(n0); });
}

TEST(GroutTrigger, steps_fire_at_the_stages_kth_step) {
  const long s = check_moment("trigger_steps", "150", [](long, long, long k) { return k >= 150; });
  EXPECT_EQ(s, 150);
}

// Without a trigger key the stage takes trigger_broken at the schema's
// default, 0: N >= 0 holds at the stage's start, so it grouts at once,
// before any step.
TEST(GroutTrigger, no_trigger_key_grouts_at_once_on_the_default) {
  const rockfdem::workflows::KeySpec* key =
      rockfdem::workflows::find_key("stages[].trigger_broken");
  ASSERT_NE(key, nullptr);
  ASSERT_EQ(key->default_text, "0");
  const auto r = run_with("no-trigger", "");
  const nlohmann::json& c = r.grout.at("changes");
  EXPECT_TRUE(c.at("triggered").get<bool>()) << c;
  EXPECT_EQ(c.at("trigger"), "trigger_broken");
  EXPECT_EQ(c.at("trigger_value").get<double>(), 0.0);
  EXPECT_EQ(r.grout.at("steps").get<long>(), 0);
}

// One trigger per stage, named; a since-support trigger needs a support
// stage before it; a step trigger beyond the stage's cap is refused.
TEST(GroutTrigger, two_triggers_or_a_trigger_that_cannot_fire_are_refused) {
  using rockfdem::workflows::load_scene;
  const auto entry = [](const std::string& k) {
    return "stages[" + std::to_string(kGrout) + "]." + k;
  };
  const std::string two = error_of([&] {
    load_scene(kScene, {entry("trigger_broken=10"), entry("trigger_steps=20")});
  });
  EXPECT_TRUE(has(two, entry("trigger_steps")) && has(two, "trigger_broken and trigger_steps"))
      << two;
  const std::string no_support = error_of([&] {
    load_scene(kScene, {"stages[3].kind=\"equilibrium\"", entry("trigger_broken_growth=0.5")});
  });
  EXPECT_TRUE(has(no_support, entry("trigger_broken_growth")) && has(no_support, "`bolts` stage"))
      << no_support;
  const std::string beyond = error_of([&] { load_scene(kScene, {entry("trigger_steps=301")}); });
  EXPECT_TRUE(has(beyond, entry("trigger_steps")) && has(beyond, "max_steps = 300")) << beyond;
}

// A key one kind alone reads would do nothing in another kind's entry: a
// grout trigger on the equilibrium stage (stages[2]) and a soften alpha on
// the grout stage are refused, each naming the key and the kind that reads it.
TEST(GroutTrigger, another_kinds_keys_are_refused) {
  using rockfdem::workflows::load_scene;
  const std::string trigger = error_of([&] { load_scene(kScene, {"stages[2].trigger_steps=10"}); });
  EXPECT_TRUE(has(trigger, "stages[2].trigger_steps") && has(trigger, "\"grout\"") &&
              has(trigger, "\"equilibrium\""))
      << trigger;
  const std::string alpha =
      error_of([&] { load_scene(kScene, {"stages[" + std::to_string(kGrout) + "].alpha=0.5"}); });
  EXPECT_TRUE(has(alpha, "stages[4].alpha") && has(alpha, "\"soften\"")) << alpha;
  EXPECT_NO_THROW(load_scene(kScene, {"stages[" + std::to_string(kGrout) + "].trigger_steps=10"}));
}
