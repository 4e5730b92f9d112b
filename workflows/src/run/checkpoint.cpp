#include "run/checkpoint.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <vector>

#include "record/summary.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "rockfdem/printable.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows {
namespace {

constexpr char kMagic[8] = {'R', 'F', 'D', 'M', 'C', 'K', 'P', 'T'};
constexpr const char* kPrefix = "checkpoint_";
constexpr const char* kSuffix = ".rfck";
constexpr std::size_t kMaxNesting = 32;    ///< a written run state nests 5
constexpr std::size_t kMaxMessage = 4096;  ///< a written message: under 1000 characters

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void put_block(std::string& out, const std::string& block) {
  put<std::uint64_t>(out, block.size());
  out += block;
}

// Reads from a byte buffer, naming the file and offset when it runs out.
class Reader {
 public:
  Reader(const std::string& path, const std::string& bytes, std::size_t end)
      : path_(path), bytes_(bytes), end_(end) {}
  template <class T>
  T get() {
    T value;
    need(sizeof value);
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string block() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string b = bytes_.substr(at_, n);
    at_ += n;
    return b;
  }

 private:
  void need(std::uint64_t n) const {
    if (n > end_ - at_)
      throw InputError("checkpoint " + path_ + ": truncated or corrupt at byte " +
                       std::to_string(at_) + "; use the previous checkpoint");
  }
  const std::string& path_;
  const std::string& bytes_;
  std::size_t end_;
  std::size_t at_ = 0;
};

// Checkpoints in `dir` (and temporary files of interrupted writes), oldest first.
void prune(const fs::path& dir, std::size_t keep) {
  std::vector<fs::path> done, temps;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kPrefix, 0) == 0 && name.size() > std::strlen(kSuffix) &&
        name.compare(name.size() - std::strlen(kSuffix), std::string::npos, kSuffix) == 0)
      done.push_back(entry.path());
    else if (name.rfind(std::string(".") + kPrefix, 0) == 0)
      temps.push_back(entry.path());
  }
  std::sort(done.begin(), done.end());  // zero-padded step numbers sort in time
  for (std::size_t i = 0; i + keep < done.size(); ++i) fs::remove(done[i], ec);
  for (const fs::path& t : temps) fs::remove(t, ec);
}

}  // namespace

std::uint64_t scene_key(const Scene& scene) {
  return fdem::fnv1a(scene.restart_key.data(), scene.restart_key.size());
}

std::string write_checkpoint(const std::string& output_dir, long step, const Scene& scene,
                             const Checkpoint& checkpoint) {
  const fs::path dir = fs::path(output_dir) / "checkpoints";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());
  std::string bytes(kMagic, sizeof kMagic);
  put<std::uint32_t>(bytes, kCheckpointVersion);
  put<std::uint64_t>(bytes, scene_key(scene));
  put_block(bytes, checkpoint.run.dump());
  put_block(bytes, checkpoint.engine_state);
  put<std::uint64_t>(bytes, fdem::fnv1a(bytes.data(), bytes.size()));
  char name[64];
  std::snprintf(name, sizeof name, "%s%012ld%s", kPrefix, step, kSuffix);
  const std::string path = (dir / name).string();
  coupling::atomic_write_text(path, bytes);
  prune(dir, 2);
  return path;
}

namespace {

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw InputError("checkpoint " + path + ": " + why);
}

// What stat() says a path is, for a message: "a directory", "a FIFO".
std::string file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// An open file descriptor, closed by scope.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Reads exactly n bytes at `offset`; false when the file ends first.
bool read_at(int fd, std::uint64_t offset, char* into, std::size_t n) {
  while (n > 0) {
    const ssize_t got = ::pread(fd, into, n, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    into += got, offset += std::uint64_t(got), n -= std::size_t(got);
  }
  return true;
}

// Opens `path` only if it is a regular file: a FIFO, a device (/dev/urandom,
// /dev/zero) or a directory is refused by stat() before it is opened, and
// O_NONBLOCK with fstat() after the open closes the gap in between (a FIFO
// put in its place then neither blocks the open nor gets read).
int open_regular(const std::string& path, std::uint64_t& size) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    refuse(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode))
    refuse(path, "is " + file_kind(st.st_mode) + ", not a regular file; give a checkpoint_<step>" +
                     kSuffix + " file that `rockfdem run --checkpoint-every` wrote");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) refuse(path, std::string("cannot open the file (") + std::strerror(errno) + ")");
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    refuse(path, "is not a regular file (it changed while being opened)");
  }
  size = std::uint64_t(st.st_size);
  return fd;
}

// ---- The run state's structure ---------------------------------------------
// run.cpp (bolts, start_ratio), RunOutputs::restore and
// SpecimenOutputs::restore (outputs) and StageRunner::restore and
// verdict() (stages) read the run state with
// .at() and .get<T>(), which throw nlohmann's own exceptions (exit 1, a
// raw message) or, for operator[] on a const object, assert. A forged or
// damaged checkpoint whose checksum was recomputed would reach them: every
// field they read is checked here first, with its type, so nothing
// downstream sees a malformed run state.

using nlohmann::json;

bool specimen(const Scene& scene) {
  return scene.mesh.kind == mesh::ModelKind::kUcs || scene.mesh.kind == mesh::ModelKind::kBrazilian;
}

class RunStateCheck {
 public:
  RunStateCheck(const std::string& path, const Scene& scene) : path_(path), scene_(scene) {}

  void all(const json& run) {
    object(run, "run state");
    // nlohmann parses without recursion but dumps (the summary, a message)
    // with it: a run state nested deeper than any the writer makes is
    // refused before anything dumps it.
    if (nesting(run) > kMaxNesting)
      refuse(path_, "corrupt run state: nested more than " + std::to_string(kMaxNesting) +
                        " levels deep (a written run state nests 5); use the previous checkpoint");
    stages(member(run, "", "stages"));
    if (specimen(scene_))
      specimen_outputs(member(run, "", "outputs"));
    else {
      outputs(member(run, "", "outputs"));
      bolts(member(run, "", "bolts"));
      number(member(run, "", "start_ratio"), "start_ratio");
    }
    consistent(run);
  }

  // The fields that count steps or time, against the engine state saved
  // with them (its step count and simulated time).
  void against_engine(const json& run, long step, double time) const {
    const json& s = run["stages"];
    const std::string now = "the engine state's step " + std::to_string(step);
    if (s["last_checkpoint"] != step) bad("stages.last_checkpoint", &s["last_checkpoint"], now);
    const std::size_t index = s["stage_index"].get<std::size_t>();
    if (s["stage_started"].get<bool>() && index < scene_.stages.size()) {
      const std::int64_t first = s["stage_first_step"].get<std::int64_t>();
      const long cap = scene_.stages[index].max_steps;
      if (first > step || step - first > cap)
        bad("stages.stage_first_step", &s["stage_first_step"],
            "a step at most " + std::to_string(cap) + " (stage " + std::to_string(index + 1) +
                "'s max_steps) before " + now);
      if (s["stage_t0"].get<double>() > time * (1 + 1e-9))
        bad("stages.stage_t0", &s["stage_t0"],
            "a time at most the engine state's simulated time " + detail_number(time) + " s");
    }
    // The step column: history.csv's "step" (a tunnel's second, a specimen's first).
    const std::size_t k = specimen(scene_) ? 0 : 1;
    const json& history = run["outputs"]["history"];
    double last = 0;
    for (std::size_t i = 0; i < history.size(); ++i) {
      const std::string at =
          "outputs.history[" + std::to_string(i) + "][" + std::to_string(k) + "]";
      if (history[i].size() <= k || !history[i][k].is_number()) bad(at, nullptr, "a step");
      const double row = history[i][k].get<double>();
      if (row < last || row > double(step))
        bad(at, &history[i][k],
            "a step from the row before's (" + detail_number(last) + ") to " + now);
      last = row;
    }
    if (specimen(scene_)) {
      const json& peak = run["outputs"]["load"]["peak_step"];
      if (peak.get<std::int64_t>() < 0 || peak.get<std::int64_t>() > step)
        bad("outputs.load.peak_step", &peak, "a step from 0 to " + now);
    }
  }

 private:
  // The fields that follow from one another, as the run writes them: one
  // report per finished stage, of the scene's stage at its place; the
  // current stage's first step after the hand-off step (tunnels) and the
  // finished stages' steps; its start time their simulated time (each
  // stage's time is the difference of two engine times, so the sum holds
  // within rounding). A forgery that changes one of them alone (a stage
  // index of 0 with a later engine state, report = [], a first step of
  // 9e18, a start time of 1e308) would run on with a silently wrong
  // record, or stop a stage early.
  void consistent(const json& run) const {
    const json& s = run["stages"];
    const json& report = s["report"];
    const std::size_t index = s["stage_index"].get<std::size_t>();
    if (report.size() != index)
      bad("stages.report", &report,
          "an array of " + std::to_string(index) +
              " stage reports, one per finished stage (stages.stage_index = " +
              std::to_string(index) + ")",
          " (" + std::to_string(report.size()) + " reports)");
    const bool tunnel = !specimen(scene_);
    std::int64_t steps = tunnel ? 1 : 0;  // the hand-off step
    const json& handoff_dt =
        run["outputs"].contains("handoff_dt") ? run["outputs"]["handoff_dt"] : json();
    double time = handoff_dt.is_number() ? handoff_dt.get<double>() : 0.0;
    for (std::size_t i = 0; i < index; ++i) {
      const std::string at = "stages.report[" + std::to_string(i) + "]";
      const StageSpec& spec = scene_.stages[i];
      if (report[i]["kind"] != spec.kind)
        bad(at + ".kind", &report[i]["kind"],
            "\"" + spec.kind + "\", the scene's stage " + std::to_string(i + 1));
      if (report[i]["max_steps"] != spec.max_steps)
        bad(at + ".max_steps", &report[i]["max_steps"],
            std::to_string(spec.max_steps) + ", the scene's stage " + std::to_string(i + 1));
      const std::int64_t n = report[i]["steps"].get<std::int64_t>();
      if (n < 0 || n > spec.max_steps)
        bad(at + ".steps", &report[i]["steps"],
            "a step count from 0 to the stage's max_steps " + std::to_string(spec.max_steps));
      non_negative(report[i]["simulated_time"], at + ".simulated_time");
      steps += n;
      time += report[i]["simulated_time"].get<double>();
    }
    if (!s["stage_started"].get<bool>() || index >= scene_.stages.size()) return;
    if (s["stage_first_step"].get<std::int64_t>() != steps)
      bad("stages.stage_first_step", &s["stage_first_step"],
          std::to_string(steps) + (tunnel ? ", the hand-off step and" : ",") +
              " the finished stages' steps");
    const double t0 = s["stage_t0"].get<double>();
    // Checkpoints from before handoff_dt was kept: only the stages' times.
    const bool known = !tunnel || handoff_dt.is_number();
    if (t0 < 0 || (known && std::abs(t0 - time) > 1e-6 * std::max(std::abs(t0), time)) ||
        (!known && t0 < time * (1 - 1e-6)))
      bad("stages.stage_t0", &s["stage_t0"],
          "the simulated time at the stage's start, " + detail_number(time) + " s (" +
              (tunnel ? "the hand-off step's dt and " : "") + "the finished stages' times)");
  }

  static std::string detail_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
  }

  [[noreturn]] void bad(const std::string& field, const json* value, const std::string& expected,
                        const std::string& note = "") const {
    std::string msg = "corrupt run state: field '" + field + "'";
    if (value)
      msg += " = " + shown(*value) + note + " is not " + expected;
    else
      msg += " is missing (expected " + expected + ")";
    refuse(path_, msg + "; use the previous checkpoint");
  }

  // The deepest nesting of arrays and objects in `v`, without recursion.
  static std::size_t nesting(const json& v) {
    std::size_t deepest = 0;
    std::vector<std::pair<const json*, std::size_t>> todo{{&v, 1}};
    while (!todo.empty()) {
      const auto [node, depth] = todo.back();
      todo.pop_back();
      if (!node->is_structured()) continue;
      deepest = std::max(deepest, depth);
      if (depth > kMaxNesting) break;
      for (const json& child : *node) todo.push_back({&child, depth + 1});
    }
    return deepest;
  }

  // A value for a message: JSON with every control character and non-ASCII
  // byte escaped, cut to 60 characters (a long string is cut before it is
  // dumped); a non-finite number as "inf" or "nan" (JSON would say null).
  static std::string shown(const json& v) {
    if (v.is_number_float() && !std::isfinite(v.get<double>()))
      return std::isnan(v.get<double>()) ? "nan" : v.get<double>() > 0 ? "inf" : "-inf";
    const json small = v.is_string() && v.get_ref<const std::string&>().size() > 60
                           ? json(v.get_ref<const std::string&>().substr(0, 60))
                           : json();
    std::string text =
        (small.is_null() ? v : small).dump(-1, ' ', true, json::error_handler_t::replace);
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    return text;
  }

  static std::string join(const std::string& at, const std::string& key) {
    return at.empty() ? key : at + "." + key;
  }

  const json& member(const json& obj, const std::string& at, const char* key) const {
    const auto it = obj.find(key);
    if (it == obj.end()) bad(join(at, key), nullptr, expected_of(key));
    return *it;
  }

  // The expected kind of a missing field, for its message.
  static std::string expected_of(const std::string& key) {
    static const std::map<std::string, std::string> kinds = {
        {"stages", "an object"},
        {"outputs", "an object"},
        {"bolts", "an object"},
        {"stage_index", "an unsigned integer"},
        {"stage_started", "true or false"},
        {"stage_first_step", "an integer"},
        {"stage_t0", "a number"},
        {"stage_changes", "an object"},
        {"changes", "an object"},
        {"stage_monitor_u", "an array of numbers"},
        {"alpha", "a number"},
        {"core_present", "true or false"},
        {"lining_installed", "true or false"},
        {"report", "an array of stage reports"},
        {"last_checkpoint", "an integer"},
        {"history", "an array of rows of numbers"},
        {"frames", "an array of [time, file name] pairs"},
        {"csv", "text (the bolts.csv table)"},
        {"installed", "an array of 0 and 1"},
        {"installed_stress", "an array of arrays of [xx, yy, xy] stresses"},
        {"kind", "a string"},
        {"stage", "an integer"},
        {"steps", "an integer"},
        {"simulated_time", "a number"},
        {"max_steps", "an integer"},
        {"unbalanced_ratio", "a number"},
        {"criteria", "an object"},
        {"ratio", "a number"},
        {"hold", "an integer"},
        {"unstable_fraction", "a number"},
        {"settle", "a number or null"},
        {"broken_growth", "a number or null"},
        {"broken_settle", "a number"},
        {"converged", "true, false or null"},
        {"moving_most", "an object or null"},
        {"key_point", "a string"},
        {"mm_per_1000_steps", "a number"},
        {"support_pressure_ratio", "a number"},
        {"start_ratio", "a number"},
        {"load", "an object"},
        {"peak_stress", "a number"},
        {"peak_strain", "a number"},
        {"peak_step", "an integer"},
        {"stopped", "true or false"}};
    const auto it = kinds.find(key);
    return it == kinds.end() ? "a value" : it->second;
  }

  void object(const json& v, const std::string& f) const {
    if (!v.is_object()) bad(f, &v, "an object");
  }
  void array(const json& v, const std::string& f, const std::string& of) const {
    if (!v.is_array()) bad(f, &v, of);
  }
  void boolean(const json& v, const std::string& f) const {
    if (!v.is_boolean()) bad(f, &v, "true or false");
  }
  void integer(const json& v, const std::string& f) const {
    if (!v.is_number_integer()) bad(f, &v, "an integer");
  }
  // Every number a run writes is finite (nlohmann writes NaN and the
  // infinities as null); a parsed 1e400 is an infinity.
  void number(const json& v, const std::string& f) const {
    if (!v.is_number()) bad(f, &v, "a number");
    if (!std::isfinite(v.get<double>())) bad(f, &v, "a finite number");
  }
  // A count or a time that cannot be negative.
  void non_negative(const json& v, const std::string& f) const {
    if (v.is_number_integer() ? v.get<std::int64_t>() < 0 : v.get<double>() < 0)
      bad(f, &v, "zero or more");
  }
  // Strings of a run state reach the terminal, summary.json, report.md
  // and CSV files: no control characters (a forged ESC would reach them
  // raw), and in a CSV text (`text`) none but line breaks.
  static bool has_control(const std::string& s, bool line_breaks) {
    return printable(s, line_breaks) != s;
  }
  // A name or a message: what the run writes is under 1000 characters, and
  // it is echoed to the terminal and summary.json.
  void string(const json& v, const std::string& f) const {
    if (!v.is_string()) bad(f, &v, "a string");
    const std::string& s = v.get_ref<const std::string&>();
    if (s.size() > kMaxMessage)
      bad(f, &v, "a string of at most " + std::to_string(kMaxMessage) + " characters",
          " (" + std::to_string(s.size()) + " characters)");
    if (has_control(s, false)) bad(f, &v, "a string without control characters");
  }
  void text(const json& v, const std::string& f) const {
    if (!v.is_string()) bad(f, &v, "a string");
    if (has_control(v.get_ref<const std::string&>(), true))
      bad(f, &v, "text without control characters but line breaks");
  }
  void numbers(const json& v, const std::string& f) const {
    array(v, f, "an array of numbers");
    for (std::size_t i = 0; i < v.size(); ++i) number(v[i], f + "[" + std::to_string(i) + "]");
  }

  void stages(const json& s) {
    const std::string at = "stages";
    object(s, at);
    const json& index = member(s, at, "stage_index");
    const std::size_t n_stages = scene_.stages.size();
    if (!index.is_number_unsigned() || index.get<std::uint64_t>() > n_stages)
      bad(at + ".stage_index", &index,
          "a stage index from 0 to " + std::to_string(n_stages) + " (the scene's stages)");
    boolean(member(s, at, "stage_started"), at + ".stage_started");
    integer(member(s, at, "stage_first_step"), at + ".stage_first_step");
    number(member(s, at, "stage_t0"), at + ".stage_t0");
    changes(member(s, at, "stage_changes"), at + ".stage_changes");
    numbers(member(s, at, "stage_monitor_u"), at + ".stage_monitor_u");
    // Optional: checkpoints from before they were kept lack them.
    if (s.contains("stage_held")) integer(s["stage_held"], at + ".stage_held");
    if (s.contains("stage_rates")) numbers(s["stage_rates"], at + ".stage_rates");
    if (s.contains("stage_broken")) integer(s["stage_broken"], at + ".stage_broken");
    if (s.contains("unstable")) string(s["unstable"], at + ".unstable");
    number(member(s, at, "alpha"), at + ".alpha");
    boolean(member(s, at, "core_present"), at + ".core_present");
    boolean(member(s, at, "lining_installed"), at + ".lining_installed");
    const json& report = member(s, at, "report");
    array(report, at + ".report", "an array of stage reports");
    for (std::size_t i = 0; i < report.size(); ++i)
      stage_report(report[i], at + ".report[" + std::to_string(i) + "]");
    integer(member(s, at, "last_checkpoint"), at + ".last_checkpoint");
  }

  // What stage_changes_from_json reads: each entry of the kind its name
  // asks for (a key from the file is shown escaped, as a value is).
  void changes(const json& c, const std::string& at) const {
    object(c, at);
    for (auto it = c.begin(); it != c.end(); ++it) {
      const std::string want = stage_change_mismatch(it.key(), it.value());
      if (!want.empty()) bad(at + "[" + shown(it.key()) + "]", &it.value(), want);
    }
  }

  void criteria(const json& c, const std::string& at) const {
    object(c, at);
    number(member(c, at, "ratio"), at + ".ratio");
    number(member(c, at, "settle"), at + ".settle");
    if (c.contains("broken_settle")) number(c["broken_settle"], at + ".broken_settle");
    integer(member(c, at, "hold"), at + ".hold");
    number(member(c, at, "unstable_fraction"), at + ".unstable_fraction");
  }

  // The fields stage_records_from_json reads from each finished stage.
  void stage_report(const json& r, const std::string& at) {
    object(r, at);
    string(member(r, at, "kind"), at + ".kind");
    integer(member(r, at, "stage"), at + ".stage");
    changes(member(r, at, "changes"), at + ".changes");
    integer(member(r, at, "steps"), at + ".steps");
    number(member(r, at, "simulated_time"), at + ".simulated_time");
    // Optional: a stage that took no step may leave it out.
    if (r.contains("dt") && !r["dt"].is_number() && !r["dt"].is_null())
      bad(at + ".dt", &r["dt"], "a number or null");
    integer(member(r, at, "max_steps"), at + ".max_steps");
    number(member(r, at, "unbalanced_ratio"), at + ".unbalanced_ratio");
    const json& converged = member(r, at, "converged");
    if (!converged.is_boolean() && !converged.is_null())
      bad(at + ".converged", &converged, "true, false or null");
    const json& settle = member(r, at, "settle");
    if (!settle.is_number() && !settle.is_null()) bad(at + ".settle", &settle, "a number or null");
    if (r.contains("broken_growth") && !r["broken_growth"].is_number() &&
        !r["broken_growth"].is_null())
      bad(at + ".broken_growth", &r["broken_growth"], "a number or null");
    number(member(r, at, "support_pressure_ratio"), at + ".support_pressure_ratio");
    criteria(member(r, at, "criteria"), at + ".criteria");
    const json& moving = member(r, at, "moving_most");
    if (moving.is_null()) return;
    if (!moving.is_object()) bad(at + ".moving_most", &moving, "an object or null");
    string(member(moving, at + ".moving_most", "key_point"), at + ".moving_most.key_point");
    number(member(moving, at + ".moving_most", "mm_per_1000_steps"),
           at + ".moving_most.mm_per_1000_steps");
  }

  void outputs(const json& o) {
    const std::string at = "outputs";
    object(o, at);
    history_rows(member(o, at, "history"), at + ".history");
    const json& names = member(o, at, "stages");
    array(names, at + ".stages", "an array of stage names");
    for (std::size_t i = 0; i < names.size(); ++i)
      string(names[i], at + ".stages[" + std::to_string(i) + "]");
    // The hand-off step's dt: positive (it is in the summary and the
    // report as the first step's dt, and in the start time of each stage).
    if (o.contains("handoff_dt")) {
      number(o["handoff_dt"], at + ".handoff_dt");
      if (!(o["handoff_dt"].get<double>() > 0))
        bad(at + ".handoff_dt", &o["handoff_dt"], "a positive time step in seconds");
    }
    if (o.contains("max_rotation_deg")) number(o["max_rotation_deg"], at + ".max_rotation_deg");
    frame_list(member(o, at, "frames"), at + ".frames");
    // BoltResults::restore writes the table as bolts.csv and copies the frames.
    if (o.contains("bolts") && !o["bolts"].is_null()) {
      const json& b = o["bolts"];
      object(b, at + ".bolts");
      text(member(b, at + ".bolts", "csv"), at + ".bolts.csv");
      frame_list(member(b, at + ".bolts", "frames"), at + ".bolts.frames");
    }
  }

  void frame_list(const json& frames, const std::string& at) const {
    array(frames, at, "an array of [time, file name] pairs");
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const std::string f = at + "[" + std::to_string(i) + "]";
      const json& frame = frames[i];
      if (!frame.is_array() || frame.size() != 2 || !frame[0].is_number() || !frame[1].is_string())
        bad(f, &frame, "a [time, file name] pair");
      // The frame is copied from beside the checkpoint into the output
      // directory by this name: a path would reach outside both.
      // It is written into the .pvd's XML too.
      const std::string name = frame[1].get<std::string>();
      const bool plain = !name.empty() && name.size() <= 255 && name[0] != '.' &&
                         std::all_of(name.begin(), name.end(), [](char ch) {
                           return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' ||
                                  ch == '-' || ch == '.';
                         });
      if (!plain)
        bad(f + "[1]", &frame[1],
            "a plain file name (letters, digits, '_', '-' and '.', not starting with '.')");
    }
  }

  // A run records a row at its start (step 0, or the hand-off step) before
  // any checkpoint: an empty history would drop the rows written before.
  void history_rows(const json& history, const std::string& at) const {
    array(history, at, "an array of rows of numbers");
    if (history.empty()) bad(at, &history, "an array of at least one row (the run's first)");
    for (std::size_t i = 0; i < history.size(); ++i) {
      const std::string row = at + "[" + std::to_string(i) + "]";
      // null: no value at that step (JSON's NaN: "nan" in history.csv, such
      // as the lining's columns before the ring is installed).
      array(history[i], row, "an array of numbers");
      for (std::size_t k = 0; k < history[i].size(); ++k)
        if (!history[i][k].is_null()) number(history[i][k], row + "[" + std::to_string(k) + "]");
      if (history[i].size() != history[0].size())
        bad(row, &history[i],
            "a row of " + std::to_string(history[0].size()) + " numbers like the first row");
    }
  }

  // What SpecimenOutputs::restore and PlatenLoad::restore read.
  void specimen_outputs(const json& s) const {
    const std::string at = "outputs";
    object(s, at);
    history_rows(member(s, at, "history"), at + ".history");
    frame_list(member(s, at, "frames"), at + ".frames");
    const json& load = member(s, at, "load");
    object(load, at + ".load");
    for (const char* key : {"peak_stress", "peak_strain"})
      number(member(load, at + ".load", key), at + ".load." + key);
    integer(member(load, at + ".load", "peak_step"), at + ".load.peak_step");
    boolean(member(load, at + ".load", "stopped"), at + ".load.stopped");
  }

  void bolts(const json& b) {
    const std::string at = "bolts";
    object(b, at);
    const json& installed = member(b, at, "installed");
    array(installed, at + ".installed", "an array of 0 and 1");
    for (std::size_t i = 0; i < installed.size(); ++i) {
      const json& v = installed[i];
      if (!v.is_number_integer() || (v.get<std::int64_t>() != 0 && v.get<std::int64_t>() != 1))
        bad(at + ".installed[" + std::to_string(i) + "]", &v, "0 or 1");
    }
    const json& stress = member(b, at, "installed_stress");
    array(stress, at + ".installed_stress", "an array of arrays of [xx, yy, xy] stresses");
    if (stress.size() != installed.size())
      bad(at + ".installed_stress", &stress,
          "an array of " + std::to_string(installed.size()) + " entries, one per bolt");
    for (std::size_t i = 0; i < stress.size(); ++i) {
      const std::string f = at + ".installed_stress[" + std::to_string(i) + "]";
      array(stress[i], f, "an array of [xx, yy, xy] stresses");
      for (std::size_t k = 0; k < stress[i].size(); ++k) {
        const json& s = stress[i][k];
        const std::string g = f + "[" + std::to_string(k) + "]";
        if (!s.is_array() || s.size() != 3) bad(g, &s, "an [xx, yy, xy] stress");
        for (std::size_t c = 0; c < 3; ++c) number(s[c], g + "[" + std::to_string(c) + "]");
      }
    }
  }

  const std::string& path_;
  const Scene& scene_;
};

}  // namespace

void validate_run_state(const std::string& path, const nlohmann::json& run, const Scene& scene) {
  RunStateCheck(path, scene).all(run);
}

void check_run_state_against_engine(const std::string& path, const nlohmann::json& run,
                                    const Scene& scene, long step, double time) {
  RunStateCheck(path, scene).against_engine(run, step, time);
}

namespace {

[[noreturn]] void truncated(const std::string& path, std::uint64_t size, const std::string& what) {
  refuse(path, "truncated or corrupt: " + what + ", but the file holds " + std::to_string(size) +
                   " bytes; use the previous checkpoint");
}

// The fixed header (magic, version) and the declared section sizes, which
// must add up to the file's size exactly before the body is read: a header
// that claims more than the file holds (a sparse or damaged file) is
// refused after 36 bytes.
void check_header(int fd, const std::string& path, std::uint64_t size) {
  constexpr std::uint64_t kFixed = sizeof kMagic + sizeof(std::uint32_t) + sizeof(std::uint64_t);
  constexpr std::uint64_t kSize = sizeof(std::uint64_t);
  char magic[sizeof kMagic];
  if (size < sizeof kMagic + kSize || !read_at(fd, 0, magic, sizeof magic) ||
      std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    refuse(path, "not a rockfdem checkpoint (no RFDMCKPT header)");
  std::uint32_t version = 0;
  if (!read_at(fd, sizeof kMagic, reinterpret_cast<char*>(&version), sizeof version))
    truncated(path, size, "the header ends within the format version");
  if (version != kCheckpointVersion)
    refuse(path, "format version " + std::to_string(version) + "; this build reads version " +
                     std::to_string(kCheckpointVersion));
  std::uint64_t n_run = 0, n_engine = 0;
  if (size < kFixed + kSize || !read_at(fd, kFixed, reinterpret_cast<char*>(&n_run), kSize))
    truncated(path, size, "the header ends before the run state's size");
  const std::uint64_t after_run_size = kFixed + kSize;
  // Room for the run state, the engine state's size and the checksum.
  if (n_run > size - after_run_size || size - after_run_size - n_run < 2 * kSize)
    truncated(path, size, "the header declares a run state of " + std::to_string(n_run) + " bytes");
  const std::uint64_t engine_size_at = after_run_size + n_run;
  if (!read_at(fd, engine_size_at, reinterpret_cast<char*>(&n_engine), kSize))
    truncated(path, size, "the file ends within the engine state's size");
  const std::uint64_t room = size - engine_size_at - 2 * kSize;
  if (n_engine != room)
    truncated(path, size,
              "the header declares a run state of " + std::to_string(n_run) +
                  " bytes and an engine state of " + std::to_string(n_engine) + " bytes (" +
                  (n_engine > room ? "more than" : "less than") + " the " + std::to_string(room) +
                  " bytes left for it)");
}

// ---- Parsing the run state --------------------------------------------------
// nlohmann's parser is iterative, but a value nested deeper than the stack
// allows is dumped recursively (a message, the summary): 100,000 nested
// '[' ended in SIGSEGV. The parser's callback sees every level as it opens,
// so the depth is bounded while parsing, before such a value exists; and it
// keeps the path of the field being read, so that a syntax error (NaN, an
// infinity, text after the end) is named by its field instead of by the
// JSON library's raw message (which quotes the file's bytes).

// Text from a file for a message: escaped and cut to `n` characters.
std::string cut(const std::string& text, std::size_t n) {
  const std::string shown = printable(text);
  return shown.size() > n ? shown.substr(0, n - 3) + "..." : shown;
}

class RunStatePath {
 public:
  // The parser's callback: follows the levels and keys, and stops the
  // parse (Deep) at a level beyond kMaxNesting.
  bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, const nlohmann::json& v) {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start:
        if (levels_.size() >= kMaxNesting) throw Deep{where()};
        levels_.push_back({event == E::array_start, "", 0});
        break;
      case E::key:
        levels_.back().key = v.get<std::string>();
        break;
      case E::object_end:
      case E::array_end:
        levels_.pop_back();
        value_done();
        break;
      case E::value:
        value_done();
        break;
    }
    return true;
  }
  struct Deep {
    std::string field;
  };
  // The field being read: "stages.stage_rates[1]".
  std::string where() const {
    std::string at;
    for (const Level& l : levels_)
      at += l.array ? "[" + std::to_string(l.index) + "]" : (at.empty() ? "" : ".") + l.key;
    return at;
  }
  // The whole top-level value is read (what follows is extra text).
  bool complete() const { return complete_; }

 private:
  void value_done() {
    if (levels_.empty())
      complete_ = true;
    else if (levels_.back().array)
      ++levels_.back().index;
  }
  struct Level {
    bool array;
    std::string key;
    std::size_t index;
  };
  std::vector<Level> levels_;
  bool complete_ = false;
};

// What a syntax error at byte `at` of `text` is, in words.
std::string syntax_error(const std::string& text, std::size_t at, bool complete) {
  if (complete) return "text after the end of the JSON value";
  std::string near = text.substr(at > 3 ? at - 3 : 0, 12);
  std::transform(near.begin(), near.end(), near.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  if (near.find("nan") != std::string::npos || near.find("inf") != std::string::npos)
    return "NaN or an infinity, which a checkpoint never holds (JSON has no such number)";
  if (at >= text.size()) return "the JSON ends before its value is complete";
  return "not valid JSON";
}

nlohmann::json parse_run_state(const std::string& path, const std::string& text) {
  RunStatePath reading;
  try {
    return nlohmann::json::parse(text, std::ref(reading));
  } catch (const RunStatePath::Deep& d) {
    refuse(path, "corrupt run state: nested more than " + std::to_string(kMaxNesting) +
                     " levels deep at field '" + cut(d.field, 80) +
                     "' (a written run state nests 5); use the previous checkpoint");
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    const std::string field = reading.where();
    refuse(path, "corrupt run state: " + syntax_error(text, at, reading.complete()) + " at byte " +
                     std::to_string(at) + " of " + std::to_string(text.size()) +
                     (field.empty() ? "" : ", field '" + cut(field, 80) + "'") + " (near \"" +
                     cut(text.substr(at > 8 ? at - 8 : 0, 24), 40) +
                     "\"); use the previous checkpoint");
  } catch (const nlohmann::json::exception& e) {
    // out_of_range.406: a number beyond a double's range (1e400).
    const std::string field = reading.where();
    refuse(path, std::string("corrupt run state: ") +
                     (e.id == 406 ? "a number beyond the range of a double (1.8e308)"
                                  : "not valid JSON") +
                     (field.empty() ? "" : " at field '" + cut(field, 80) + "'") + " (" +
                     std::to_string(text.size()) + " bytes); use the previous checkpoint");
  }
}

}  // namespace

Checkpoint read_checkpoint(const std::string& path, const Scene& scene) {
  // 1. A regular file, or nothing is read at all.
  std::uint64_t size = 0;
  const Fd fd(open_regular(path, size));
  // 2. The header and the sections' sizes.
  check_header(fd.get(), path, size);

  // 3. The body, now known to be what the header says, and its checksum.
  std::string bytes(size, '\0');
  if (!read_at(fd.get(), 0, bytes.data(), bytes.size()))
    truncated(path, size, "the file became shorter while being read");
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  if (stored != fdem::fnv1a(bytes.data(), body))
    refuse(path, "checksum mismatch (" + std::to_string(bytes.size()) +
                     " bytes, truncated or corrupt); use the previous checkpoint");
  Reader r(path, bytes, body);
  r.get<std::uint64_t>();  // magic
  r.get<std::uint32_t>();  // version, checked above
  if (r.get<std::uint64_t>() != scene_key(scene))
    refuse(path,
           "written for another scene (or other --set values); restart with the scene "
           "and overrides of the original run");
  Checkpoint c;
  c.run = parse_run_state(path, r.block());
  validate_run_state(path, c.run, scene);
  c.engine_state = r.block();
  return c;
}

}  // namespace rockfdem::workflows
