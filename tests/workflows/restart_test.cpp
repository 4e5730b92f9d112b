// Checkpoint and restart as a user meets them (issue 9): a run restarted
// from a checkpoint ends bit-identical to an uninterrupted one, with
// fracture, contact, bolts and grouting active and another thread count;
// SIGTERM writes outputs and a checkpoint and exits 143; SIGKILL at any
// moment leaves a readable checkpoint; bad checkpoints are refused with
// exit 2 and nothing written.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

#include "cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;

namespace {

const std::string kScene = kTestDir + "/restart_support.toml";

std::vector<fs::path> checkpoints(const fs::path& run_dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(run_dir / "checkpoints", ec))
    if (e.path().extension() == ".rfck") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

long checkpoint_step(const fs::path& p) {
  const std::string name = p.stem().string();  // checkpoint_000000001200
  return std::stol(name.substr(name.find('_') + 1));
}

// Starts `rockfdem ARGS` without waiting; its output goes to `log`.
pid_t spawn(const std::string& args, const fs::path& log) {
  const std::string cmd = "exec " + std::string(ROCKFDEM_BINARY) + " " + args + " > " +
                          log.string() + " 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Polls until `ready` holds (true) or 120 s pass (false).
template <class Pred>
bool wait_for(Pred ready) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

std::size_t history_rows(const fs::path& run_dir) {
  const std::string h = read_text(run_dir / "history.csv");
  return h.empty() ? 0 : std::count(h.begin(), h.end(), '\n') - 1;
}

}  // namespace

class Restart : public ::testing::Test {
 protected:
  // The uninterrupted reference: 2 threads, a checkpoint every 400 steps.
  static void SetUpTestSuite() {
    reference_dir_ = new fs::path(scratch("restart-reference"));
    const Result r = run("run " + kScene + " -q -j 2 --checkpoint-every 400 -o " +
                         reference_dir_->string());
    ASSERT_EQ(r.code, 0) << r.output;
    reference_ = new nlohmann::json(read_json(*reference_dir_ / "summary.json"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*reference_dir_);
    delete reference_dir_;
    delete reference_;
  }
  static std::string reference_hash() { return (*reference_)["state_hash"].get<std::string>(); }
  static fs::path* reference_dir_;
  static nlohmann::json* reference_;
};
fs::path* Restart::reference_dir_ = nullptr;
nlohmann::json* Restart::reference_ = nullptr;

TEST_F(Restart, continues_bit_identically_with_another_thread_count) {
  const auto kept = checkpoints(*reference_dir_);
  ASSERT_EQ(kept.size(), 2u) << "the newest two checkpoints are kept";
  const fs::path older = kept.front();
  const long at = checkpoint_step(older);
  // At the checkpoint the model has fractured, bolts are installed and
  // contact is on: read the reference history's row at that step.
  const nlohmann::json& j = *reference_;
  EXPECT_EQ(j["counts"]["bolts"].get<int>(), 8);
  EXPECT_GT(j["contact"]["last_touching"].get<long>(), 0);
  const std::string kernel = j["contact"]["kernel"].get<std::string>();
  EXPECT_TRUE(kernel == "avx512" || kernel == "avx2" || kernel == "sse2" || kernel == "baseline")
      << kernel;
  EXPECT_GT(j["fdem"]["stages"][3]["changes"]["rejoined"].get<long>(), 0) << "grouted";
  const std::string history = read_text(*reference_dir_ / "history.csv");
  const auto row = history.find("," + std::to_string(at) + ",");
  ASSERT_NE(row, std::string::npos) << "no history row at step " << at;
  EXPECT_GT(at, j["fdem"]["stages"][3]["steps"].get<long>()) << "after grouting";

  const fs::path out = scratch("restart-j1");
  const Result r = run("run " + kScene + " -q -j 1 --restart " + older.string() + " -o " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json k = read_json(out / "summary.json");
  EXPECT_EQ(k["state_hash"].get<std::string>(), reference_hash());
  EXPECT_EQ(k["steps"].get<long>(), j["steps"].get<long>());
  EXPECT_EQ(k["broken"], j["broken"]);
  // The time step figures carry over too: the hand-off's, each stage's, the range.
  EXPECT_EQ(k["fdem"]["handoff_step"], j["fdem"]["handoff_step"]);
  for (std::size_t s = 0; s < j["fdem"]["stages"].size(); ++s)
    EXPECT_EQ(k["fdem"]["stages"][s]["dt"], j["fdem"]["stages"][s]["dt"]) << "stage " << s;
  EXPECT_EQ(k["dt_min"], j["dt_min"]);
  EXPECT_EQ(k["dt_max"], j["dt_max"]);
  EXPECT_EQ(k["restarted_from"]["step"].get<long>(), at);
  EXPECT_EQ(history_rows(out), history_rows(*reference_dir_));
  EXPECT_TRUE(fs::exists(out / "fdem_0000.vtu")) << "earlier frames come along";
  fs::remove_all(out);
}

TEST_F(Restart, refuses_truncated_corrupt_foreign_and_other_version_checkpoints) {
  const fs::path good = checkpoints(*reference_dir_).back();
  const std::string bytes = read_text(good);
  const fs::path dir = scratch("restart-bad");
  fs::create_directories(dir);
  struct Case {
    std::string name, content, extra, expect;
  };
  std::string flipped = bytes, version = bytes;
  flipped[bytes.size() / 2] ^= 0x5a;
  version[8] = 99;
  const std::vector<Case> cases = {
      {"truncated", bytes.substr(0, bytes.size() / 3), "", "truncated or corrupt"},
      {"flipped", flipped, "", "checksum"},
      {"version", version, "", "format version 99"},
      {"foreign", bytes, "--set insitu.sigma_h=18.0e6", "another scene"},
      {"not-a-checkpoint", "hello", "", "not a rockfdem checkpoint"}};
  for (const Case& c : cases) {
    const fs::path file = dir / (c.name + ".rfck");
    std::ofstream(file, std::ios::binary) << c.content;
    const fs::path out = dir / ("out-" + c.name);
    const Result r = run("run " + kScene + " -q --restart " + file.string() + " " + c.extra +
                         " -o " + out.string());
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(file.string()), std::string::npos) << "names the file";
    EXPECT_FALSE(fs::exists(out)) << c.name << ": nothing written";
  }
  fs::remove_all(dir);
}

TEST_F(Restart, sigterm_writes_outputs_and_a_checkpoint_then_exit_143_and_restarts) {
  const fs::path out = scratch("restart-sigterm");
  const pid_t pid = spawn("run " + kScene + " -q -j 2 -o " + out.string(), out.string() + ".log");
  ASSERT_TRUE(wait_for([&] { return history_rows(out) >= 4; })) << read_text(out.string() + ".log");
  kill(pid, SIGTERM);
  EXPECT_EQ(wait_exit_code(pid), 143) << read_text(out.string() + ".log");
  const nlohmann::json j = read_json(out / "summary.json");
  EXPECT_EQ(j["status"].get<std::string>(), "interrupted");
  const auto kept = checkpoints(out);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_LT(checkpoint_step(kept[0]), (*reference_)["steps"].get<long>());

  const fs::path again = scratch("restart-after-sigterm");
  const Result r = run("run " + kScene + " -q -j 1 --restart " + kept[0].string() + " -o " +
                       again.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(again / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
  fs::remove_all(again);
}

// SIGKILL cannot be caught: whatever moment it lands (here while a
// checkpoint is written at every output step), the checkpoints left are
// whole files (the atomic rename) and the newest restarts to the
// uninterrupted result.
TEST_F(Restart, sigkill_leaves_a_restartable_checkpoint) {
  const fs::path out = scratch("restart-sigkill");
  const pid_t pid = spawn("run " + kScene + " -q -j 2 --checkpoint-every 1 -o " + out.string(),
                          out.string() + ".log");
  ASSERT_TRUE(wait_for([&] { return checkpoints(out).size() >= 2; }));
  std::this_thread::sleep_for(std::chrono::milliseconds(37));
  kill(pid, SIGKILL);
  EXPECT_EQ(wait_exit_code(pid), 128 + SIGKILL);
  const auto kept = checkpoints(out);
  ASSERT_GE(kept.size(), 1u);
  ASSERT_LE(kept.size(), 3u) << "a third only while the newest is being pruned";
  // Continue in the same directory, as after a crash.
  const Result r = run("run " + kScene + " -q -j 1 --restart " + kept.back().string() + " -o " +
                       out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(out / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  EXPECT_EQ(history_rows(out), history_rows(*reference_dir_));
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}

// Two SIGINTs in a row: the second exits at once (130), and every output
// file left is complete (each was written atomically): summary.json and
// history.csv parse, and every checkpoint left is readable.
TEST_F(Restart, second_sigint_exits_at_once_leaving_complete_files) {
  const fs::path out = scratch("restart-sigint2");
  const pid_t pid = spawn("run " + kScene + " -q -j 2 --checkpoint-every 1 -o " + out.string(),
                          out.string() + ".log");
  // Once a checkpoint exists: a second signal may cut the interrupt's own
  // checkpoint short, so only an earlier one is sure to be there.
  ASSERT_TRUE(wait_for([&] { return !checkpoints(out).empty(); }));
  kill(pid, SIGINT);
  kill(pid, SIGINT);
  EXPECT_EQ(wait_exit_code(pid), 130) << read_text(out.string() + ".log");
  if (fs::exists(out / "summary.json")) {
    EXPECT_NO_THROW(read_json(out / "summary.json"));
  }
  const std::string h = read_text(out / "history.csv");
  ASSERT_FALSE(h.empty());
  EXPECT_EQ(h.back(), '\n') << "no half-written row";
  const auto kept = checkpoints(out);
  ASSERT_FALSE(kept.empty());
  const fs::path again = scratch("restart-sigint2-again");
  const Result r = run("run " + kScene + " -q --restart " + kept.back().string() + " -o " +
                       again.string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(again / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  fs::remove_all(again);
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}
