// What a command leaves in OUTDIR: nothing at all when it refuses its input
// (exit 2), and after --force the new run's outputs beside the user's own
// files, with none of an earlier run's left over.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

const std::string kCircular = kTestDir + "/good_circular.toml";

// Every file under `dir` with a hash of its bytes, to compare a folder
// before and after.
std::map<std::string, std::size_t> snapshot(const fs::path& dir) {
  std::map<std::string, std::size_t> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      files[fs::relative(e.path(), dir).string()] = std::hash<std::string>{}(read_text(e.path()));
  return files;
}

std::set<std::string> names_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// The frames fdem_NNNN.vtu in `dir`.
std::set<std::string> frames_in(const fs::path& dir) {
  std::set<std::string> frames;
  for (const std::string& n : names_in(dir))
    if (n.rfind("fdem_", 0) == 0 && n.size() == 13 && n.substr(9) == ".vtu") frames.insert(n);
  return frames;
}

}  // namespace

// engine.dt is checked against the engine's stability limit, known only once
// the mesh and the implicit stage exist; the refused run still writes
// nothing, tunnel or specimen.
TEST(OutputDir, run_refusing_dt_leaves_no_directory) {
  const fs::path out = scratch("refused-dt");
  for (const std::string& scene :
       {kCircular + " --set engine.dt=1", kTestDir + "/ucs_small.toml --set engine.dt=2e-6"}) {
    const Result r = run("run " + scene + " -q -o " + out.string());
    EXPECT_EQ(r.code, 2) << scene << ": " << r.output;
    EXPECT_NE(r.output.find("engine.dt"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << scene;
  }
}

// An explicit dt below the limit of the engine as built but above the one
// the stages' local damping brings (0.8: sqrt(1.8) lower) was refused only
// at the first stage step, after the outputs were written. It is refused
// up front now; a dt that only a later stage's stiffening makes too large
// can still only be found there, and then leaves a summary naming the key.
// The seed scene is run with local damping 0.8 alone (it ships 0.3 with
// kinetic damping): limit 0.000651 s with the stages' damping, 0.000590 s
// after the lining (its 30 GPa invert) and bolts stiffen it; its four
// soften stages cut to a step each bring the lining in at step 5.
TEST(OutputDir, dt_above_the_damped_limit_is_refused_before_writing) {
  const fs::path out = scratch("damped-dt");
  const std::string seed = rockfdem::test::kSeedScene +
                           " --set engine.local_damping=0.8 --set engine.kinetic_damping=false"
                           " --set stages[1].max_steps=1 --set stages[2].max_steps=1"
                           " --set stages[3].max_steps=1 --set stages[4].max_steps=1";
  Result r = run("run " + seed + " -j 1 -q --set engine.dt=0.0008 -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("with the stages' damping"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  r = run("run " + seed + " -j 1 -q --set engine.dt=0.00062 --set output.plots=false -o " +
          out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("key 'engine.dt' = 0.00062 s"), std::string::npos) << r.output;
  const std::string summary = read_text(out / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"failed\""), std::string::npos) << summary;
  fs::remove_all(out);
}

// A refused run into an existing results folder leaves every file as it
// was: into the same scene's folder, and with --force into another's (whose
// .rockfdem-scene must still match the summary.json beside it).
TEST(OutputDir, refused_run_leaves_an_existing_directory_untouched) {
  const fs::path out = scratch("untouched");
  const std::string dt = " --set engine.dt=1";
  ASSERT_EQ(run("mesh " + kCircular + dt + " -q -o " + out.string()).code, 0);
  const auto before = snapshot(out);
  for (const std::string& args : {dt, dt + " --set tunnel.radius=2.5 --force"}) {
    const Result r = run("run " + kCircular + args + " -q -o " + out.string());
    EXPECT_EQ(r.code, 2) << args << ": " << r.output;
    EXPECT_NE(r.output.find("engine.dt"), std::string::npos) << r.output;
    EXPECT_EQ(snapshot(out), before) << args;
  }
  fs::remove_all(out);
}

// The owner record is a line or two this program wrote. In its place a
// FIFO (read, it would block the command for good), a link to /dev/zero
// (read whole, memory without bound) or a file beyond any record's size is
// exit 2 naming the record and what it is, at once and with nothing
// written; `timeout` ends a command that waits or grows instead.
TEST(OutputDir, an_owner_record_that_is_not_a_small_file_is_refused_unread) {
  const fs::path out = scratch("owner-forged");
  const fs::path owner = out / ".rockfdem-scene";
  const std::vector<std::pair<std::function<void()>, std::string>> cases{
      {[&] { ASSERT_EQ(mkfifo(owner.c_str(), 0644), 0); }, "is a FIFO, not a regular file"},
      {[&] { fs::create_symlink("/dev/zero", owner); }, "is a device, not a regular file"},
      {[&] {
         std::ofstream(owner) << "sparse";
         fs::resize_file(owner, std::uintmax_t(1) << 30);
       },
       "has 1073741824 bytes"}};
  for (const auto& [make, expect] : cases) {
    fs::remove_all(out);
    fs::create_directories(out);
    make();
    const Result r = run("mesh " + kCircular + " -q -o " + out.string(), "timeout 60");
    EXPECT_EQ(r.code, 2) << expect << ": " << r.output;
    EXPECT_TRUE(has(r.output, owner.string() + " " + expect)) << r.output;
    EXPECT_EQ(names_in(out), std::set<std::string>{".rockfdem-scene"}) << expect;
  }
  fs::remove_all(out);
}

// --force clears what an earlier, longer run wrote (frames the new fdem.pvd
// does not list) and keeps every file rockfdem does not write.
// --force cleans only a folder an earlier run claimed (its owner record):
// in a user's own folder, files that merely look like outputs stay.
TEST(OutputDir, force_leaves_a_folder_no_run_claimed_untouched) {
  const fs::path out = scratch("unclaimed");
  fs::create_directories(out / "checkpoints");
  const char* mine[] = {"notes.txt",         "bolt_01.csv",
                        "fdem_0042.vtu",     "convergence.png",
                        "stress_strain.png", "checkpoints/checkpoint_00000100.rfck"};
  for (const char* f : mine) std::ofstream(out / f) << "mine\n";
  const Result r = run("mesh " + kCircular + " -q --force -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : mine) EXPECT_TRUE(fs::exists(out / f)) << f;
  fs::remove_all(out);
}

TEST(OutputDir, force_removes_an_earlier_runs_outputs_and_nothing_else) {
  const fs::path out = scratch("force");
  const std::string run_args = " -q --set output.every_steps=100 --set output.plots=false";
  ASSERT_EQ(run("run " + kCircular + run_args + " --set engine.steps=400 -o " + out.string()).code,
            0);
  const std::set<std::string> long_frames = frames_in(out);
  std::ofstream(out / "notes.txt") << "mine\n";
  std::ofstream(out / "fdem_notes.vtu") << "mine\n";
  fs::create_directories(out / "sub");
  std::ofstream(out / "sub" / "fdem_0009.vtu") << "mine\n";

  const Result again =
      run("run " + kCircular + run_args + " --set engine.steps=100 --force -o " + out.string());
  ASSERT_EQ(again.code, 0) << again.output;
  const std::string pvd = read_text(out / "fdem.pvd");
  std::size_t listed = 0;
  for (std::size_t at = pvd.find("fdem_"); at != std::string::npos; at = pvd.find("fdem_", at + 1))
    ++listed;
  ASSERT_LT(listed, long_frames.size());  // the second run is the shorter one
  for (const std::string& f : frames_in(out))
    EXPECT_NE(pvd.find("\"" + f + "\""), std::string::npos) << f << " is not in fdem.pvd";
  for (const char* mine : {"notes.txt", "fdem_notes.vtu", "sub/fdem_0009.vtu"})
    EXPECT_TRUE(fs::exists(out / mine)) << mine;

  // A supported run writes bolt tables and checkpoints too; `mesh --force`
  // of another scene leaves its three outputs and the user's files alone.
  const Result supported = run("run " + kTestDir +
                               "/restart_support.toml -q --force"
                               " --set stages[4].max_steps=200 --set stages[5].max_steps=200"
                               " --set output.every_steps=100 --checkpoint-every 100 -o " +
                               out.string());
  ASSERT_EQ(supported.code, 0) << supported.output;
  ASSERT_TRUE(fs::exists(out / "bolt_00.csv"));
  ASSERT_TRUE(fs::exists(out / "checkpoints"));
  ASSERT_EQ(
      run("mesh " + kCircular + " -q --set output.plots=false --force -o " + out.string()).code, 0);
  // .rockfdem-lock: the folder's run lock (one run per folder).
  const std::set<std::string> left{".rockfdem-lock", ".rockfdem-scene", "mesh.msh",
                                   "mesh.vtu",       "summary.json",    "scene.toml",
                                   "notes.txt",      "fdem_notes.vtu",  "sub"};
  EXPECT_EQ(names_in(out), left);
  fs::remove_all(out);
}

// The same scene spelled relative to another folder, with ./, or by its
// absolute path is the same scene: a second command into the folder the
// first claimed is not refused as "another scene" (a restart was).
TEST(OutputDir, same_scene_under_another_spelling_is_the_same_scene) {
  const fs::path out = scratch("spelling");
  ASSERT_EQ(run("mesh " + kCircular + " -q -o " + out.string()).code, 0);
  const std::string dir = fs::path(kCircular).parent_path().string();
  for (const std::string& spelled :
       {std::string("good_circular.toml"), std::string("./good_circular.toml")}) {
    const Result r = run("mesh " + spelled + " -q -o " + out.string(), "cd '" + dir + "' &&");
    EXPECT_EQ(r.code, 0) << spelled << ": " << r.output;
  }
  // Another scene still is another scene.
  EXPECT_EQ(run("mesh " + kTestDir + "/elastic_circular.toml -q -o " + out.string()).code, 2);
  fs::remove_all(out);
}

// One run per folder: while another process holds the folder's lock, a
// run into it is refused with exit 2 naming the holder's PID, and writes
// nothing; once the holder is gone (the kernel drops the lock) it runs.
TEST(OutputDir, a_folder_in_use_by_another_run_is_refused_naming_its_pid) {
  const fs::path out = scratch("locked");
  fs::create_directories(out);
  const int fd = ::open((out / ".rockfdem-lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string pid = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, pid.data(), pid.size()), ssize_t(pid.size()));
  Result r = run("mesh " + kCircular + " -q -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("in use by another rockfdem run (PID " + pid + ")"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  ::close(fd);
  r = run("mesh " + kCircular + " -q -o " + out.string());
  EXPECT_EQ(r.code, 0) << r.output;
  fs::remove_all(out);
}

// `-o "a/../x"` with no folder a: creating x also made a (as mkdir -p
// does), and it stayed behind empty. The folders made only on the way are
// removed when the command ends; x and its outputs stay.
TEST(OutputDir, folders_made_only_on_the_way_to_the_output_are_removed) {
  const fs::path base = scratch("detour");
  fs::create_directories(base);
  const std::string out = (base / "out put" / ".." / "x").string();
  const Result r = run("mesh " + kCircular + " -q -o '" + out + "'");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::exists(base / "x" / "mesh.msh"));
  EXPECT_FALSE(fs::exists(base / "out put")) << "the detour's folder is left behind";
  fs::remove_all(base);
}
