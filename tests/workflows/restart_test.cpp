// Checkpoint and restart as a user meets them: a run restarted
// from a checkpoint ends bit-identical to an uninterrupted one, with
// fracture, contact, bolts and grouting active and another thread count;
// SIGTERM writes outputs and a checkpoint and exits 143; SIGKILL at any
// moment leaves a readable checkpoint; bad checkpoints are refused with
// exit 2 and nothing written.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <thread>
#include <vector>

#include "cli_runner.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/checkpoint.hpp"

namespace fs = std::filesystem;
using namespace rockfdem::test;
using rockfdem::InputError;
using rockfdem::workflows::Checkpoint;
using rockfdem::workflows::read_checkpoint;
using rockfdem::workflows::write_checkpoint;

namespace {

const std::string kScene = kTestDir + "/restart_support.toml";

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

// ---- Bounded checkpoint reads -----------------------------------------------
// read_checkpoint refuses what is not a regular file before opening it for
// reading, checks the header's declared sizes against the file's size
// before reading the body, and checks the run state's structure before
// anything restores it. It used to read the whole file first: /dev/urandom
// grew without bound, a FIFO hung, a 1 GiB sparse file took 15 s and 3.3 GB
// before the refusal; and a run state forged to {} (checksum recomputed)
// exited 1 with nlohmann's raw out_of_range.
namespace {

const rockfdem::workflows::Scene& restart_scene() {
  static const rockfdem::workflows::Scene s = rockfdem::workflows::load_scene(kScene);
  return s;
}

std::string refusal(const std::string& path) {
  try {
    read_checkpoint(path, restart_scene());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A run state as run.cpp writes one for restart_support.toml: its first
// stage (lining, no step) finished, one frame, one bolt.
nlohmann::json valid_run_state() {
  const nlohmann::json report = {
      {"kind", "lining"},
      {"stage", 1},
      {"changes", nlohmann::json::object()},
      {"steps", 0},
      {"simulated_time", 0.0},
      {"dt", 2.5e-5},
      {"unbalanced_ratio", 1e-4},
      {"settle", nullptr},
      {"converged", true},
      {"max_steps", 0},
      {"criteria", {{"ratio", 1e-3}, {"settle", 1e-3}, {"hold", 3}, {"unstable_fraction", 0.1}}},
      {"moving_most", {{"key_point", "crown"}, {"mm_per_1000_steps", 0.5}}},
      {"support_pressure_ratio", 0.0}};
  return {{"stages",
           {{"stage_index", 1},
            {"stage_started", true},
            {"stage_first_step", 1},
            {"stage_t0", 2.5e-5},
            {"stage_changes", nlohmann::json::object()},
            {"stage_monitor_u", {0.0, 1e-4}},
            {"stage_held", 0},
            {"stage_rates", {0.1, 0.2}},
            {"alpha", 0.5},
            {"core_present", false},
            {"lining_installed", true},
            {"report", nlohmann::json::array({report})},
            {"last_checkpoint", 800},
            {"unstable", ""}}},
          {"outputs",
           {{"history", {{0.0, 1.0}, {1.0, 2.0}}},
            {"stages", {"handoff", "equilibrium"}},
            {"frames", nlohmann::json::array({nlohmann::json::array({0.01, "fdem_0000.vtu"})})},
            {"handoff_dt", 2.5e-5},
            {"max_rotation_deg", 0.0}}},
          {"bolts",
           {{"installed", {1, 0}},
            {"installed_stress",
             nlohmann::json::array({nlohmann::json::array({nlohmann::json::array({1.0, 2.0, 3.0})}),
                                    nlohmann::json::array()})}}},
          {"start_ratio", 0.2}};
}

}  // namespace

class Restart : public ::testing::Test {
 protected:
  // The uninterrupted reference: 2 threads, a checkpoint every 400 steps.
  static void SetUpTestSuite() {
    reference_dir_ = new fs::path(scratch("restart-reference"));
    const Result r =
        run("run " + kScene + " -q -j 2 --checkpoint-every 400 -o " + reference_dir_->string());
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
  const Result r =
      run("run " + kScene + " -q -j 1 --restart " + older.string() + " -o " + out.string());
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
  // So does what the grout stage wrote before the checkpoint.
  ASSERT_TRUE(fs::exists(out / "grouted_cracks.csv"));
  EXPECT_EQ(read_text(out / "grouted_cracks.csv"),
            read_text(*reference_dir_ / "grouted_cracks.csv"));
  // The bolt profiles and their frames continue as if never interrupted.
  EXPECT_EQ(read_text(out / "bolts.csv"), read_text(*reference_dir_ / "bolts.csv"));
  EXPECT_EQ(read_text(out / "bolts.pvd"), read_text(*reference_dir_ / "bolts.pvd"));
  EXPECT_TRUE(fs::exists(out / "bolts_0001.vtp")) << "earlier bolt frames come along";
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

// A checkpoint whose run state is {} with a recomputed checksum (a
// forgery): exit 2 naming the file and the field, nothing written.
TEST_F(Restart, forged_empty_run_state_is_refused_with_exit_2) {
  const Checkpoint good =
      read_checkpoint(checkpoints(*reference_dir_).back().string(), restart_scene());
  const fs::path dir = scratch("restart-forged");
  const std::string forged = write_checkpoint(dir.string(), 1, restart_scene(),
                                              {nlohmann::json::object(), good.engine_state});
  const fs::path out = dir / "out";
  const Result r = run("run " + kScene + " -q --restart " + forged + " -o " + out.string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(
      r.output.find("checkpoint " + forged + ": corrupt run state: field 'stages' is missing"),
      std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("json.exception"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out)) << "nothing written";
  fs::remove_all(dir);
}

// Forgeries that pass the run state's structural check but do not fit the
// scene, the mesh or the files beside the checkpoint (checksum recomputed):
// each is exit 2 naming the checkpoint, and the new -o folder is never
// created. They used to be found while restoring, after the first outputs
// were written.
TEST_F(Restart, forgeries_that_do_not_fit_the_run_leave_no_output_folder) {
  const Checkpoint good =
      read_checkpoint(checkpoints(*reference_dir_).back().string(), restart_scene());
  const fs::path dir = scratch("restart-misfit");
  struct Case {
    std::string name;
    std::function<void(Checkpoint&)> forge;
    std::string field = "";  // named in the message ("": not checked)
  };
  const std::vector<Case> cases = {
      {"engine-garbage", [](Checkpoint& c) { c.engine_state = "ENGINE"; }},
      {"engine-half",
       [](Checkpoint& c) { c.engine_state = c.engine_state.substr(0, c.engine_state.size() / 2); }},
      {"bolt-count",
       [](Checkpoint& c) {
         c.run["bolts"] = {{"installed", {1}},
                           {"installed_stress", nlohmann::json::array({nlohmann::json::array()})}};
       }},
      {"history-width",
       [](Checkpoint& c) {
         c.run["outputs"]["history"] = {{0.0, 1.0}, {1.0, 2.0}};
       }},
      {"monitor-u",
       [](Checkpoint& c) {
         c.run["stages"]["stage_monitor_u"] = {0.0, 0.0};
       }},
      // Consistent among themselves, but not with the engine state's step:
      // the first stage again, from the hand-off step.
      {"stage-zero",
       [](Checkpoint& c) {
         nlohmann::json& s = c.run["stages"];
         s["stage_index"] = 0;
         s["report"] = nlohmann::json::array();
         s["stage_first_step"] = 1;
         s["stage_t0"] = c.run["outputs"]["handoff_dt"];
       },
       "field 'stages.stage_first_step' = 1 is not a step at most 0 (stage 1's max_steps) before "
       "the engine state's step"},
      {"last-checkpoint", [](Checkpoint& c) { c.run["stages"]["last_checkpoint"] = 5; },
       "field 'stages.last_checkpoint' = 5 is not the engine state's step"},
      {"history-beyond",
       [](Checkpoint& c) {
         nlohmann::json& h = c.run["outputs"]["history"];
         h.back()[1] = 1e6;
       },
       "is not a step from the row before's"},
  };
  for (const Case& c : cases) {
    Checkpoint forged = good;
    c.forge(forged);
    const fs::path from = dir / c.name;
    const std::string path = write_checkpoint(from.string(), 1, restart_scene(), forged);
    const fs::path out = dir / ("out-" + c.name);
    const Result r = run("run " + kScene + " -q --restart " + path + " -o " + out.string());
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(path), std::string::npos) << c.name << ": " << r.output;
    if (!c.field.empty()) {
      EXPECT_NE(r.output.find(c.field), std::string::npos) << c.name << ": " << r.output;
    }
    EXPECT_FALSE(fs::exists(out)) << c.name << ": the output folder was created";
  }
  fs::remove_all(dir);
}

// Whether process `pid` catches SIGTERM (its SigCgt mask in /proc).
bool catches_sigterm(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (SIGTERM - 1)) & 1;
  return false;
}

// SIGTERM while a command that installs no run handlers works (here
// `mesh` of a fine tunnel, several seconds of gmsh) used to end the
// process without a word; the handlers installed first thing in main()
// print one line naming the signal, and the exit code stays 143.
TEST(Signals, sigterm_before_a_run_handles_it_names_the_signal) {
  const fs::path out = scratch("early-signal");
  const fs::path log = scratch("early-signal.log");
  const pid_t pid =
      spawn("mesh " + std::string(ROCKFDEM_SOURCE_DIR) +
                "/scenes/tunnel-seed.toml --set mesh.size_near=0.05 -q -o " + out.string(),
            log);
  wait_for([&] { return catches_sigterm(pid); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  kill(pid, SIGTERM);
  EXPECT_EQ(wait_exit_code(pid), 143);
  const std::string text = read_text(log);
  EXPECT_NE(text.find("rockfdem: stopped by signal 15 (SIGTERM)"), std::string::npos) << text;
  fs::remove_all(out);
  fs::remove(log);
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
  const Result r =
      run("run " + kScene + " -q -j 1 --restart " + kept[0].string() + " -o " + again.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(again / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
  fs::remove_all(again);
}

// SIGKILL cannot be caught: whatever moment it lands (here while a
// checkpoint is written at every output step), the checkpoints left are
// whole files (the atomic rename) and the newest restarts to the
// uninterrupted result. The half-written temporary files a kill leaves
// (planted here as well, since the kill may land between writes) are
// removed by the restart into the same folder; a user's files with
// similar names stay.
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
  const std::string half(115 * 1024, 'x');
  for (const fs::path& stale : {out / ".fdem_0009.tmp-4242-69.vtu", out / ".history.tmp-4242-3.csv",
                                out / ".mesh.msh.tmp4242.msh",
                                out / "checkpoints" / ".checkpoint_000000000400.tmp-4242-7.rfck"})
    std::ofstream(stale) << half;
  const std::vector<fs::path> users{out / ".notes.tmp-1-1.txt", out / "notes.txt"};
  for (const fs::path& mine : users) std::ofstream(mine) << "the user's\n";
  // Continue in the same directory, as after a crash.
  const Result r =
      run("run " + kScene + " -q -j 1 --restart " + kept.back().string() + " -o " + out.string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(out / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  EXPECT_EQ(history_rows(out), history_rows(*reference_dir_));
  for (const fs::path& dir : {out, out / "checkpoints"})
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      EXPECT_TRUE(name.find(".tmp") == std::string::npos || name == ".notes.tmp-1-1.txt")
          << "left after the restart: " << e.path();
    }
  for (const fs::path& mine : users) EXPECT_TRUE(fs::exists(mine)) << mine;
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
  const Result r =
      run("run " + kScene + " -q --restart " + kept.back().string() + " -o " + again.string());
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_json(again / "summary.json")["state_hash"].get<std::string>(), reference_hash());
  fs::remove_all(again);
  fs::remove_all(out);
  fs::remove(out.string() + ".log");
}

TEST(CheckpointRead, fifo_is_refused_without_blocking) {
  const fs::path dir = scratch("ckpt-fifo");
  fs::create_directories(dir);
  const std::string fifo = (dir / "checkpoint.rfck").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << std::strerror(errno);
  restart_scene();
  auto reading = std::async(std::launch::async, [&] { return refusal(fifo); });
  if (reading.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
    ADD_FAILURE() << "read_checkpoint blocked on a FIFO";
    // Unblock it: a writer that opens and closes gives the reader an end of file.
    while (reading.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
      if (fd >= 0) ::close(fd);
    }
  }
  const std::string msg = reading.get();
  EXPECT_NE(msg.find("checkpoint " + fifo + ": is a FIFO (named pipe), not a regular file"),
            std::string::npos)
      << msg;
  fs::remove_all(dir);
}

TEST(CheckpointRead, directories_and_devices_are_refused_before_reading) {
  const fs::path dir = scratch("ckpt-dir");
  fs::create_directories(dir);
  // (On the old reader this case fails first and ends the test before the
  // devices, which it would read without end.)
  const std::string msg = refusal(dir.string());
  ASSERT_NE(msg.find("is a directory, not a regular file"), std::string::npos) << msg;
  for (const std::string device : {"/dev/urandom", "/dev/zero"}) {
    if (!fs::exists(device)) continue;
    // A reader that read the device would never end: the test's timeout
    // catches that; the refusal is decided from the file's type alone.
    const std::string m = refusal(device);
    EXPECT_NE(m.find("checkpoint " + device + ": is a character device, not a regular file"),
              std::string::npos)
        << m;
  }
  fs::remove_all(dir);
}

TEST(CheckpointRead, declared_sizes_beyond_the_file_are_refused_before_the_body_is_read) {
  const fs::path dir = scratch("ckpt-sizes");
  const std::string good =
      read_text(write_checkpoint(dir.string(), 7, restart_scene(), {valid_run_state(), "ENGINE"}));
  ASSERT_EQ(refusal((dir / "checkpoints" / "checkpoint_000000000007.rfck").string()), "");
  const auto put_u64 = [](std::string& b, std::size_t at, std::uint64_t v) {
    std::memcpy(&b[at], &v, sizeof v);
  };
  // A sparse 64 MiB file whose header claims a 1 TiB run state: refused
  // from its first 28 bytes, whatever follows.
  const std::string sparse = (dir / "sparse.rfck").string();
  {
    std::string header = good.substr(0, 28);
    put_u64(header, 20, std::uint64_t(1) << 40);
    std::ofstream(sparse, std::ios::binary) << header;
    fs::resize_file(sparse, std::uintmax_t(64) << 20);
  }
  std::string msg = refusal(sparse);
  EXPECT_NE(msg.find("checkpoint " + sparse +
                     ": truncated or corrupt: the header declares a run "
                     "state of 1099511627776 bytes, but the file holds 67108864 bytes"),
            std::string::npos)
      << msg;
  // An engine state's size that does not fill the file exactly.
  std::uint64_t n_run = 0;
  std::memcpy(&n_run, good.data() + 20, sizeof n_run);
  for (const std::uint64_t n_engine : {std::uint64_t(5), std::uint64_t(7), ~std::uint64_t(0)}) {
    std::string bytes = good;
    put_u64(bytes, 28 + n_run, n_engine);
    const std::string path = (dir / "engine.rfck").string();
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    msg = refusal(path);
    EXPECT_NE(msg.find("an engine state of " + std::to_string(n_engine) + " bytes"),
              std::string::npos)
        << msg;
  }
  fs::remove_all(dir);
}

TEST(CheckpointRead, forged_run_states_name_the_checkpoint_and_the_field) {
  const fs::path dir = scratch("ckpt-forged");
  struct Case {
    std::string pointer;   // JSON pointer to change ("" for the whole state)
    nlohmann::json value;  // null: remove the field
    std::string expect;
  };
  const nlohmann::json removed;  // null
  nlohmann::json deep = 1;       // 1,000 arrays deep (a written run state nests 5)
  for (int i = 0; i < 1000; ++i) deep = nlohmann::json::array({std::move(deep)});
  const std::vector<Case> cases = {
      {"", nlohmann::json::object(), "field 'stages' is missing (expected an object)"},
      {"/stages/stage_index", "3", "field 'stages.stage_index' = \"3\" is not a stage index"},
      {"/stages/stage_index", -1, "field 'stages.stage_index' = -1 is not a stage index"},
      {"/stages/stage_index", 99, "field 'stages.stage_index' = 99 is not a stage index from 0 to"},
      {"/stages/stage_started", 1, "field 'stages.stage_started' = 1 is not true or false"},
      {"/stages/stage_first_step", 1.5, "field 'stages.stage_first_step' = 1.5 is not an integer"},
      {"/stages/stage_monitor_u/1", "x",
       "field 'stages.stage_monitor_u[1]' = \"x\" is not a number"},
      {"/stages/stage_held", "2", "field 'stages.stage_held' = \"2\" is not an integer"},
      {"/stages/stage_changes/rejoined", "70",
       "field 'stages.stage_changes[\"rejoined\"]' = \"70\" is not an integer"},
      {"/stages/stage_changes/triggered", 1,
       "field 'stages.stage_changes[\"triggered\"]' = 1 is not true or false"},
      {"/stages/stage_changes/\x1b[2J", nlohmann::json::array(),
       "field 'stages.stage_changes[\"\\u001b[2J\"]' = [] is not true, false, a number or a "
       "string"},
      {"/stages/report/0/changes", removed,
       "field 'stages.report[0].changes' is missing (expected an object)"},
      {"/stages/report/0/changes/positions_file", 3,
       "field 'stages.report[0].changes[\"positions_file\"]' = 3 is not a string"},
      {"/stages/unstable", false, "field 'stages.unstable' = false is not a string"},
      {"/stages/alpha", removed, "field 'stages.alpha' is missing (expected a number)"},
      {"/stages/report/0/steps", removed, "field 'stages.report[0].steps' is missing"},
      {"/stages/report/0/stage", "1", "field 'stages.report[0].stage' = \"1\" is not an integer"},
      {"/stages/report/0/criteria", 1, "field 'stages.report[0].criteria' = 1 is not an object"},
      {"/stages/report/0/simulated_time", removed,
       "field 'stages.report[0].simulated_time' is missing (expected a number)"},
      {"/stages/report/0/dt", "x", "field 'stages.report[0].dt' = \"x\" is not a number or null"},
      {"/stages/report/0/criteria/hold", 1.5,
       "field 'stages.report[0].criteria.hold' = 1.5 is not an integer"},
      {"/stages/report/0/criteria/unstable_fraction", removed,
       "field 'stages.report[0].criteria.unstable_fraction' is missing (expected a number)"},
      {"/stages/report/0/support_pressure_ratio", "0",
       "field 'stages.report[0].support_pressure_ratio' = \"0\" is not a number"},
      {"/stages/report/0/moving_most/key_point", 7,
       "field 'stages.report[0].moving_most.key_point' = 7 is not a string"},
      {"/stages/last_checkpoint", removed, "field 'stages.last_checkpoint' is missing"},
      {"/outputs/history/1", nlohmann::json::array({1.0}),
       "field 'outputs.history[1]' = [1.0] is not a row of 2 numbers"},
      {"/outputs/stages/0", nullptr, "field 'outputs.stages[0]' = null is not a string"},
      {"/outputs/frames/0", nlohmann::json::array({0.0}),
       "field 'outputs.frames[0]' = [0.0] is not a [time, file name] pair"},
      {"/outputs/frames/0/1", "../../etc/passwd",
       "field 'outputs.frames[0][1]' = \"../../etc/passwd\" is not a plain file name"},
      {"/outputs/frames/0/1", "\x1b[2J",
       "field 'outputs.frames[0][1]' = \"\\u001b[2J\" is not a plain file name"},
      {"/bolts/installed/0", 2, "field 'bolts.installed[0]' = 2 is not 0 or 1"},
      {"/bolts/installed_stress/0/0", nlohmann::json::array({1.0, 2.0}),
       "field 'bolts.installed_stress[0][0]' = [1.0,2.0] is not an [xx, yy, xy] stress"},
      {"/bolts/installed_stress", nlohmann::json::array({nlohmann::json::array()}),
       "field 'bolts.installed_stress' = [[]] is not an array of 2 entries, one per bolt"},
      {"/start_ratio", "0.2", "field 'start_ratio' = \"0.2\" is not a number"},
      {"/stages/stage_changes/deep", deep, "nested more than 32 levels deep"},
      // Strings that reach the terminal, report.md or a CSV file raw.
      {"/stages/unstable", "closing\x1b[2J",
       "field 'stages.unstable' = \"closing\\u001b[2J\" is not a string without control "
       "characters"},
      {"/outputs/bolts",
       {{"csv", "step,time_s\n1,\x1b]0;pwned\x07\n"}, {"frames", nlohmann::json::array()}},
       "field 'outputs.bolts.csv' = \"step,time_s\\n1,\\u001b]0;pwned\\u0007\\n\" is not text "
       "without control characters but line breaks"},
      {"/outputs/bolts",
       {{"csv", "step\n"},
        {"frames", nlohmann::json::array({nlohmann::json::array({0.0, "../x"})})}},
       "field 'outputs.bolts.frames[0][1]' = \"../x\" is not a plain file name"},
      // Values of the right type that the restart would run on, checked
      // each against the scene and the other fields.
      {"/stages/stage_first_step", std::int64_t(9000000000000000000),
       "field 'stages.stage_first_step' = 9000000000000000000 is not 1, the hand-off step and "
       "the finished stages' steps"},
      {"/stages/stage_t0", 1e308,
       "field 'stages.stage_t0' = 1e+308 is not the simulated time at the stage's start, 2.5e-05 "
       "s"},
      {"/stages/stage_t0", -1.0, "field 'stages.stage_t0' = -1.0 is not the simulated time"},
      {"/stages/stage_index", 0,
       "field 'stages.report' = "
       "[{\"changes\":{},\"converged\":true,\"criteria\":{\"hold\":3,\"rat... "
       "(1 reports) is not an array of 0 stage reports, one per finished stage"},
      {"/stages/report", nlohmann::json::array(),
       "field 'stages.report' = [] (0 reports) is not an array of 1 stage reports"},
      {"/stages/report/0/kind", "equilibrium",
       "field 'stages.report[0].kind' = \"equilibrium\" is not \"lining\", the scene's stage 1"},
      {"/stages/report/0/steps", 400,
       "field 'stages.report[0].steps' = 400 is not a step count from 0 to the stage's max_steps "
       "0"},
      {"/outputs/history", nlohmann::json::array(),
       "field 'outputs.history' = [] is not an array of at least one row"},
      {"/outputs/handoff_dt", 0.0,
       "field 'outputs.handoff_dt' = 0.0 is not a positive time step in seconds"},
      {"/outputs/handoff_dt", -1e308,
       "field 'outputs.handoff_dt' = -1e+308 is not a positive time step in seconds"},
      {"/stages/unstable", std::string(5 << 20, 'u'),
       "field 'stages.unstable' = \"" + std::string(56, 'u') +
           "... (5242880 characters) is not a string of at most 4096 characters"},
  };
  for (const Case& c : cases) {
    nlohmann::json run = valid_run_state();
    if (c.pointer.empty())
      run = c.value;
    else if (c.value.is_null() && c.expect.find("missing") != std::string::npos)
      run[nlohmann::json::json_pointer(c.pointer).parent_pointer()].erase(
          nlohmann::json::json_pointer(c.pointer).back());
    else
      run[nlohmann::json::json_pointer(c.pointer)] = c.value;
    const std::string path = write_checkpoint(dir.string(), 1, restart_scene(), {run, "ENGINE"});
    const std::string msg = refusal(path);
    EXPECT_NE(msg.find("checkpoint " + path + ": corrupt run state: " + c.expect),
              std::string::npos)
        << c.pointer << ": " << msg.substr(0, 2000);
    EXPECT_EQ(msg.find('\x1b'), std::string::npos) << msg.substr(0, 2000);
    EXPECT_LT(msg.size(), 1000u) << c.pointer << ": a message of " << msg.size() << " bytes";
  }
  // The valid state itself passes: each case above fails on its own field.
  const std::string path =
      write_checkpoint(dir.string(), 1, restart_scene(), {valid_run_state(), "ENGINE"});
  EXPECT_EQ(refusal(path), "");
  fs::remove_all(dir);
}

// A checkpoint whose run state is the text `run` (not necessarily JSON),
// with a correct header and checksum: a forgery the checksum cannot catch.
std::string forge_raw(const fs::path& dir, const std::string& run) {
  fs::create_directories(dir);
  std::string bytes = "RFDMCKPT";
  const auto put = [&bytes](auto v) { bytes.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(rockfdem::workflows::kCheckpointVersion);
  put(rockfdem::workflows::scene_key(restart_scene()));
  put(std::uint64_t(run.size()));
  bytes += run;
  put(std::uint64_t(6));
  bytes += "ENGINE";
  put(rockfdem::fdem::fnv1a(bytes.data(), bytes.size()));
  const fs::path path = dir / "checkpoint_000000000001.rfck";
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// Run state text that is not the JSON a run writes:
// 100,000 nested '[' crashed the reader (SIGSEGV, the nesting was checked
// after the parse and a message dumped the value recursively); NaN, an
// infinity and trailing text were refused with the JSON library's raw
// message. Each is now refused while parsing, naming the checkpoint, the
// byte and the field being read.
TEST(CheckpointRead, run_state_text_that_is_not_json_names_the_field) {
  const fs::path dir = scratch("ckpt-raw");
  const std::string good = valid_run_state().dump();
  const auto with = [&good](const std::string& from, const std::string& to) {
    const std::size_t at = good.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return good.substr(0, at) + to + good.substr(at + from.size());
  };
  struct Case {
    std::string name, text, expect;
  };
  const std::vector<Case> cases = {
      {"deep-open", std::string(100000, '['),
       "nested more than 32 levels deep at field '[0][0][0]"},
      {"deep-closed", std::string(100000, '[') + std::string(100000, ']'),
       "nested more than 32 levels deep"},
      {"deep-in-field",
       with("\"stage_changes\":{}", "\"stage_changes\":" + std::string(50000, '[')),
       "nested more than 32 levels deep at field 'stages.stage_changes[0][0]"},
      {"nan", with("\"stage_t0\":2.5e-05", "\"stage_t0\":NaN"),
       "NaN or an infinity, which a checkpoint never holds (JSON has no such number) at byte"},
      {"nan-field", with("\"stage_t0\":2.5e-05", "\"stage_t0\":NaN"), ", field 'stages.stage_t0'"},
      {"infinity", with("\"stage_rates\":[0.1,0.2]", "\"stage_rates\":[0.1,-Infinity]"),
       "NaN or an infinity, which a checkpoint never holds (JSON has no such number) at byte"},
      {"infinity-field", with("\"stage_rates\":[0.1,0.2]", "\"stage_rates\":[0.1,-Infinity]"),
       ", field 'stages.stage_rates[1]'"},
      {"huge", with("\"stage_t0\":2.5e-05", "\"stage_t0\":1e400"),
       "a number beyond the range of a double (1.8e308) at field 'stages.stage_t0'"},
      {"trailing", good + " trailing\x1b[2J", "text after the end of the JSON value at byte "},
      {"cut", good.substr(0, good.size() / 2), "field '"},
  };
  for (const Case& c : cases) {
    const std::string path = forge_raw(dir / c.name, c.text);
    const std::string msg = refusal(path);
    EXPECT_NE(msg.find("checkpoint " + path + ": corrupt run state: "), std::string::npos)
        << c.name << ": " << msg.substr(0, 2000);
    EXPECT_NE(msg.find(c.expect), std::string::npos) << c.name << ": " << msg.substr(0, 2000);
    EXPECT_EQ(msg.find("json.exception"), std::string::npos) << c.name << ": " << msg;
    EXPECT_EQ(msg.find('\x1b'), std::string::npos) << c.name << ": " << msg;
    EXPECT_LT(msg.size(), 600u) << c.name << ": " << msg.substr(0, 2000);
  }
  fs::remove_all(dir);
}
