// The command line's conventions: help per command, `-` for stdin, the
// thread count from OMP_NUM_THREADS, --set errors blamed on the --set,
// snake_case summary keys with a format version, and a run folder whose
// scene.toml repeats the run.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;
using namespace rockfdem;
using rockfdem::test::error_of;
using rockfdem::test::has;
using rockfdem::test::kTestDir;
using rockfdem::test::read_json;
using rockfdem::test::read_text;
using rockfdem::test::Result;
using rockfdem::test::run;
using rockfdem::test::scratch;

namespace {

const std::string& kOneShot = rockfdem::test::kOneShotScene;

// OMP_NUM_THREADS set to `value` (unset for nullopt) for the test's scope.
class ThreadsVariable {
 public:
  explicit ThreadsVariable(std::optional<std::string> value) {
    if (const char* v = std::getenv("OMP_NUM_THREADS")) saved_ = v;
    value ? setenv("OMP_NUM_THREADS", value->c_str(), 1) : unsetenv("OMP_NUM_THREADS");
  }
  ~ThreadsVariable() {
    saved_ ? setenv("OMP_NUM_THREADS", saved_->c_str(), 1) : unsetenv("OMP_NUM_THREADS");
  }

 private:
  std::optional<std::string> saved_;
};

int threads_of(std::vector<const char*> argv) {
  argv.insert(argv.begin(), "rockfdem");
  return workflows::parse_command_line(int(argv.size()), argv.data()).threads;
}

// Lower snake_case, except the unit and fracture-mode parts that keep
// their case (peak_force_N, stress_Pa, mode_II).
bool snake_case(const std::string& key) {
  std::size_t start = 0;
  while (start <= key.size()) {
    const std::size_t end = std::min(key.find('_', start), key.size());
    const std::string part = key.substr(start, end - start);
    const bool lower = !part.empty() && std::all_of(part.begin(), part.end(), [](char c) {
      return std::islower(static_cast<unsigned char>(c)) ||
             std::isdigit(static_cast<unsigned char>(c));
    });
    if (!lower && part != "Pa" && part != "N" && part != "I" && part != "II") return false;
    start = end + 1;
  }
  return true;
}

void expect_snake_case_keys(const nlohmann::json& j, const std::string& where) {
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) {
      EXPECT_TRUE(snake_case(it.key())) << where << "." << it.key();
      expect_snake_case_keys(it.value(), where + "." + it.key());
    }
  if (j.is_array())
    for (const auto& item : j) expect_snake_case_keys(item, where + "[]");
}

}  // namespace

TEST(CliConventions, each_command_prints_its_own_help) {
  struct Case {
    const char* command;
    std::vector<const char*> present, absent;
  };
  const Case cases[] = {
      {"run",
       {"Usage: rockfdem run", "--checkpoint-every", "--restart", "--force-dt", "--set",
        "Example:\n  rockfdem run "},
       {}},
      {"check",
       {"Usage: rockfdem check", "--set", "--threads", "Example:\n  rockfdem check "},
       {"--restart", "--force", "--output"}},
      {"mesh",
       {"Usage: rockfdem mesh", "preview.png", "--output", "--force", "--set"},
       {"--restart", "--checkpoint-every"}},
      {"insitu", {"Usage: rockfdem insitu", "--output", "--set"}, {"--restart", "--force-dt"}},
      {"sweep", {"rockfdem sweep", "--vary", "--realisations", "ensemble.csv"}, {"--target"}},
      {"calibrate", {"rockfdem calibrate", "--free", "--realisations"}, {"--vary", "--samples"}}};
  for (const Case& c : cases) {
    const Result r = run(std::string(c.command) + " --help");
    EXPECT_EQ(r.code, 0) << r.output;
    for (const char* p : c.present) EXPECT_TRUE(has(r.output, p)) << c.command << ": " << p;
    for (const char* a : c.absent) EXPECT_FALSE(has(r.output, a)) << c.command << ": " << a;
  }
  const Result global = run("--help");
  EXPECT_EQ(global.code, 0);
  for (const char* p : {"--scene-reference", "COMMAND --help", "rockfdem check", "stdin"})
    EXPECT_TRUE(has(global.output, p)) << p << " in " << global.output;
}

TEST(CliConventions, omp_num_threads_is_the_default_thread_count) {
  {
    const ThreadsVariable unset(std::nullopt);
    EXPECT_EQ(threads_of({"check", "x.toml"}), 0);  // all cores
  }
  {
    const ThreadsVariable three("3");
    EXPECT_EQ(threads_of({"check", "x.toml"}), 3);
    EXPECT_EQ(threads_of({"check", "x.toml", "-j", "1"}), 1);  // -j wins
    EXPECT_EQ(threads_of({"check", "x.toml", "-j", "0"}), 0);
  }
  for (const char* bad : {"two", "0", "-1", "4,2", "5000", "3 "}) {
    const ThreadsVariable wrong(bad);
    const std::string msg = error_of([] { threads_of({"check", "x.toml"}); });
    EXPECT_TRUE(has(msg, std::string("OMP_NUM_THREADS=") + bad + ": not a thread count")) << msg;
    EXPECT_TRUE(has(msg, "allowed: a whole number from 1 to 4096")) << msg;
    EXPECT_EQ(threads_of({"check", "x.toml", "-j", "2"}), 2);  // not read with -j
  }
  // Through the binary: the summary records it; a bad value exits 2.
  const fs::path out = scratch("omp");
  Result r =
      run("mesh " + kTestDir + "/good_circular.toml -q --set output.plots=false -o " + out.string(),
          "env OMP_NUM_THREADS=3");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(out / "summary.json")["threads"].get<int>(), 3);
  fs::remove_all(out);
  r = run("check " + kTestDir + "/good_circular.toml", "env OMP_NUM_THREADS=many");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "rockfdem: error: environment: OMP_NUM_THREADS=many")) << r.output;
}

TEST(CliConventions, a_scene_of_dash_is_read_from_stdin) {
  const fs::path out = scratch("stdin");
  Result r = run("mesh - -q --set output.plots=false -o " + out.string(),
                 "cat " + kTestDir + "/good_circular.toml |");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(out / "summary.json")["scene"], "<stdin>");
  EXPECT_EQ(
      workflows::load_scene((out / "scene.toml").string()).canonical,
      workflows::load_scene(kTestDir + "/good_circular.toml", {"output.plots=false"}).canonical);
  fs::remove_all(out);
  // Bounded as a file is: one byte over 1 MiB is refused.
  r = run("check -", "head -c 1048577 /dev/zero | tr '\\0' '#' |");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "<stdin>: the scene holds more than 1048576 bytes")) << r.output;
  // Errors name <stdin> and the line.
  r = run("check -", "printf '[model]\\nkind = \"cave\"\\n' |");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_TRUE(has(r.output, "<stdin>:2: key 'model.kind' = \"cave\"")) << r.output;
}

TEST(CliConventions, set_errors_are_blamed_on_the_set) {
  // A value refused by the schema or a check of its own key.
  std::string msg = error_of([] { workflows::load_scene(kOneShot, {"insitu.alpha=[0.5,0.7]"}); });
  EXPECT_EQ(msg.find("--set insitu.alpha=[0.5,0.7]: must be strictly decreasing"), 0u) << msg;
  // A check of another key, in the file, that fails only with the override:
  // alpha ending at 0 removes the core the one-shot scene's stages[3]
  // removes (the default hands over at its first crack, known only when
  // it runs, so there the scene cannot tell).
  msg = error_of([] { workflows::load_scene(kOneShot, {"insitu.alpha=[1.0, 0.0]"}); });
  EXPECT_EQ(msg.find("--set insitu.alpha=[1.0, 0.0]: makes the scene invalid: "), 0u) << msg;
  EXPECT_TRUE(has(msg, "key 'stages[3].kind' = \"remove_core\": the core is already removed"))
      << msg;
  // Of several, the one that breaks the scene is named.
  msg = error_of([] {
    workflows::load_scene(kOneShot,
                          {"engine.steps=100", "insitu.alpha=[1.0, 0.0]", "output.every_steps=10"});
  });
  EXPECT_EQ(msg.find("--set insitu.alpha=[1.0, 0.0]: "), 0u) << msg;
  // A fault of the file stays the file's, whatever --set is given.
  std::string text = read_text(kOneShot);
  text.replace(text.find("alpha = [1.0,"), 13, "alpha = [0.0,");
  msg = error_of([&] { workflows::parse_scene(text, "file.toml", ".", {"engine.steps=100"}); });
  EXPECT_EQ(msg.find("file.toml:"), 0u) << msg;
  // On the command line: exit 2, the --set first.
  const Result r = run("check " + kOneShot + " --set 'insitu.alpha=[1.0, 0.0]'");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.output.find("rockfdem: error: --set insitu.alpha=[1.0, 0.0]: "), 0u) << r.output;
}

// A small tunnel run with overrides; its folder's scene.toml, run without
// any, gives the same state bit for bit. The summary lists the overrides,
// has format_version 3 and only snake_case keys.
TEST(RunFolder, scene_toml_repeats_the_run_with_its_overrides) {
  const std::vector<std::string> sets = {"insitu.alpha=[1.0,0.2]", "engine.steps=300",
                                         "output.every_steps=100", "output.plots=false",
                                         "output.vtk=false"};
  std::string args;
  for (const std::string& s : sets) args += " --set " + s;
  const fs::path first = scratch("folder1"), second = scratch("folder2");
  Result r =
      run("run " + kTestDir + "/good_circular.toml -q -j 1" + args + " -o " + first.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = read_json(first / "summary.json");
  EXPECT_EQ(j["format_version"], 3);
  EXPECT_EQ(j["overrides"], nlohmann::json(sets));
  expect_snake_case_keys(j, "summary");
  EXPECT_TRUE(j["timings"].contains("fdem_setup")) << j["timings"];
  const std::string scene = read_text(first / "scene.toml");
  EXPECT_TRUE(has(scene, "#   --set engine.steps=300\n")) << scene;
  EXPECT_TRUE(has(scene, "steps = 300\n")) << scene;  // applied, not only noted

  r = run("run " + (first / "scene.toml").string() + " -q -j 2 -o " + second.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json again = read_json(second / "summary.json");
  EXPECT_EQ(again["overrides"], nlohmann::json::array());
  EXPECT_EQ(again["steps"], j["steps"]);
  EXPECT_EQ(again["state_hash"], j["state_hash"]);
  fs::remove_all(first);
  fs::remove_all(second);
}

// A .msh scene's scene.toml names its mesh file by an absolute path, so it
// runs from any folder.
TEST(RunFolder, a_msh_scene_reruns_from_anywhere) {
  const fs::path dir = scratch("folder-msh");
  const fs::path scene = rockfdem::test::msh_scene(dir);
  const fs::path out = dir / "out";
  Result r = run("mesh " + scene.string() + " -q -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const fs::path moved = scratch("folder-msh-moved");
  fs::create_directories(moved);
  fs::copy_file(out / "scene.toml", moved / "s.toml");
  r = run("check " + (moved / "s.toml").string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(has(read_text(moved / "s.toml"), "file = '" + (dir / "mesh/mesh.msh").string() + "'"))
      << read_text(moved / "s.toml");
  fs::remove_all(dir);
  fs::remove_all(moved);
}
