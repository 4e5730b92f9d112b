// A stage kind added outside the library, as a new stage is added: one
// file (this one) with its registration line, its own entry key and the
// typed value it reads it into included. The schema offers the kind and
// its key, the reader accepts it (and refuses its key on another kind's
// entry), and a tunnel run applies it and asks it when to stop, between
// built-in stages. Its own executable, so the kind stays out
// of the scene reference the other tests compare with docs/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands/commands.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "run/run.hpp"
#include "scene/schema_keys.hpp"
#include "stages/registry.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

int applied = 0;  // calls of Mark::apply
int stepped = 0;  // calls of Mark::step

// The entry's own value: stages[].mark_label.
struct MarkValues final : StageValues {
  double label = -1;  ///< -1: not given
};

// Records what the model looked like when it started and its label; stops
// at once. Only after the core's removal, which it checks itself.
class Mark : public StageWithValues<MarkValues> {
 public:
  const char* description() const override { return "test only"; }
  std::vector<KeySpec> entry_keys() const override {
    return {schema::number("stages[].mark_label", "-", "", 0, false, 100, false,
                           "mark: a number the stage writes to its changes.")};
  }
  MarkValues read_values(const StageEntry& e) const override {
    MarkValues v;
    if (e.has(".mark_label")) v.label = e.number(".mark_label");
    return v;
  }
  void check(StageCheck& c) const override {
    if (c.order.alpha > 0) c.refuse(".kind", "marks the open excavation: remove the core first");
  }
  StageChanges apply(StageModel& m, const StageSpec& spec) const override {
    ++applied;
    StageChanges done;
    done.other["core_present"] = m.core_present;
    done.other["label"] = values(spec).label;
    return done;
  }
  bool step(StageDriver&, const StageSpec&, StageChanges& changes) const override {
    ++stepped;
    changes.other["stepped"] = true;
    return true;
  }
};

const bool registered = (register_stage("mark", std::make_unique<Mark>()), true);

const char* const kScene = R"(
[model]
kind = "tunnel"
[domain]
width = 40.0
height = 40.0
[tunnel]
shape = "circular"
radius = 3.0
[mesh]
size_near = 1.0
size_far = 8.0
[materials.rock]
young = 5.0e9
poisson = 0.25
[insitu]
sigma_h = 10e6
sigma_v = 10e6
[output]
vtk = false
plots = false
every_steps = 50
[[stages]]
kind = "remove_core"
max_steps = 0
[[stages]]
kind = "mark"
mark_label = 7.5
[[stages]]
kind = "equilibrium"
max_steps = 100
)";

TEST(StageRegistry, a_registered_kind_runs_between_built_in_stages) {
  ASSERT_TRUE(registered);
  const KeySpec* kind = find_key("stages[].kind");
  ASSERT_NE(kind, nullptr);
  EXPECT_EQ(kind->choices.back(), "mark");
  EXPECT_NE(kind->description.find("`equilibrium`, `load_platens` ("), std::string::npos);
  EXPECT_NE(kind->description.find("), `mark` (test only)"), std::string::npos);
  ASSERT_NE(find_key("stages[].mark_label"), nullptr);

  const Scene scene = parse_scene(kScene, "mark.toml", ".");
  RunContext ctx;
  ctx.output_dir = (std::filesystem::temp_directory_path() / "rockfdem-stage-registry").string();
  ctx.quiet = true;
  ctx.force = true;
  std::filesystem::remove_all(ctx.output_dir);
  EXPECT_EQ(run_tunnel(scene, ctx), 0);
  EXPECT_EQ(applied, 1);
  EXPECT_EQ(stepped, 1);

  std::ifstream in(ctx.output_dir + "/summary.json");
  const nlohmann::json stages = nlohmann::json::parse(in).at("fdem").at("stages");
  ASSERT_EQ(stages.size(), 3u);
  EXPECT_EQ(stages[1]["kind"], "mark");
  // Applied after remove_core, and its step (not the equilibrium loop) ran.
  EXPECT_EQ(stages[1]["changes"]["core_present"], false);
  EXPECT_EQ(stages[1]["changes"]["stepped"], true);
  EXPECT_EQ(stages[1]["changes"]["label"], 7.5);
  EXPECT_EQ(stages[1]["steps"], 0);
  EXPECT_GT(stages[2]["steps"].get<long>(), 0);
  std::filesystem::remove_all(ctx.output_dir);
}

TEST(StageRegistry, a_registered_kind_checks_its_own_entry) {
  ASSERT_TRUE(registered);
  std::string early = kScene;
  const std::string removal = "[[stages]]\nkind = \"remove_core\"\nmax_steps = 0\n";
  early.erase(early.find(removal), removal.size());
  early += removal;
  try {
    parse_scene(early, "mark.toml", ".");
    FAIL() << "a mark stage before the core's removal was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("stages[0].kind"), std::string::npos) << what;
    EXPECT_NE(what.find("remove the core first"), std::string::npos) << what;
  }
}

// Its key on another kind's entry would do nothing: refused, naming the
// key and the kind that reads it.
TEST(StageRegistry, a_registered_kinds_key_is_refused_on_another_kind) {
  ASSERT_TRUE(registered);
  try {
    parse_scene(kScene, "mark.toml", ".", {"stages[2].mark_label=1"});
    FAIL() << "an equilibrium stage with a mark_label was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("stages[2].mark_label"), std::string::npos) << what;
    EXPECT_NE(what.find("\"mark\""), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace rockfdem::workflows
