// A user's .msh read by gmsh in a forked child (see msh_child.hpp). The
// child has its own copy of the process: gmsh's global state, the heap
// gmsh may corrupt and the gmsh session it opens and closes are its own,
// so neither a crash nor gmsh::initialize/finalize there touches the
// parent. The child runs only the reader (gmsh and our checks, one thread)
// and leaves by _exit, so no atexit handler, static destructor or stdio
// buffer of the parent runs or is flushed twice.
#include "msh_child.hpp"

#include <fcntl.h>
#include <omp.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "rockfdem/error.hpp"
#include "rockfdem/printable.hpp"

namespace rockfdem::mesh::detail {
namespace {

constexpr std::uint32_t kMagic = 0x434d4652;  // "RFMC" in little-endian bytes
constexpr std::uint32_t kVersion = 2;         // 2: joint edges among the edges
constexpr std::size_t kHeadBytes = 12;        // magic, version, kind
constexpr std::size_t kMeshCountBytes = 24;   // vertices, triangles, edges

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
T get(const std::string& in, std::size_t at) {
  T v;
  std::memcpy(&v, in.data() + at, sizeof v);
  return v;
}

std::string head(std::uint32_t kind) {
  std::string out;
  put(out, kMagic), put(out, kVersion), put(out, kind);
  return out;
}

// The bytes of a mesh record after its counts.
std::uint64_t mesh_body_bytes(std::uint64_t nv, std::uint64_t nt, std::uint64_t ne) {
  return nv * 16 + nt * (12 + 4 + 1) + ne * 12;
}

std::string count_text(std::uint64_t n) { return std::to_string(n); }

}  // namespace

RecordLimits record_limits(std::uint64_t file_bytes, std::set<int> zones) {
  RecordLimits l;
  l.file_bytes = file_bytes;
  l.vertices = std::min<std::uint64_t>(file_bytes, 2147483647u);
  l.triangles = file_bytes;
  l.edges = 16 * file_bytes;
  l.zones = std::move(zones);
  return l;
}

std::string encode_mesh(const Mesh& m) {
  std::string out = head(0);
  const std::uint64_t nv = m.x.size(), nt = m.triangles.size();
  const std::uint64_t ne = m.edges.size() + m.joint_edges.size();
  put(out, nv), put(out, nt), put(out, ne);
  out.reserve(out.size() + mesh_body_bytes(nv, nt, ne));
  out.append(reinterpret_cast<const char*>(m.x.data()), nv * sizeof(double));
  out.append(reinterpret_cast<const char*>(m.y.data()), nv * sizeof(double));
  for (const auto& t : m.triangles)
    for (int v : t) put(out, std::int32_t(v));
  for (int z : m.zone) put(out, std::int32_t(z));
  out.append(reinterpret_cast<const char*>(m.fracture.data()), nt);
  for (const TaggedEdge& e : m.edges)
    put(out, std::int32_t(e.a)), put(out, std::int32_t(e.b)), put(out, std::int32_t(e.tag));
  for (const JointEdge& j : m.joint_edges)
    put(out, std::int32_t(j.a)), put(out, std::int32_t(j.b)), put(out, std::int32_t(-1 - j.trace));
  return out;
}

std::string encode_error(std::uint32_t kind, const std::string& message) {
  std::string out = head(kind);
  const std::string text = message.substr(0, 65536);
  put(out, std::uint64_t(text.size()));
  out += text;
  return out;
}

std::optional<std::string> RecordReceiver::check_header() {
  if (get<std::uint32_t>(buffer_, 0) != kMagic || get<std::uint32_t>(buffer_, 4) != kVersion)
    return "an answer that is not a mesh record";
  const auto kind = get<std::uint32_t>(buffer_, 8);
  if (kind > 5) return "an answer of unknown kind " + count_text(kind);
  if (kind != 0) {
    if (buffer_.size() < kHeadBytes + 8) return std::nullopt;
    const auto n = get<std::uint64_t>(buffer_, kHeadBytes);
    if (n > limits_.message_bytes)
      return "an error message of " + count_text(n) + " bytes (at most " +
             count_text(limits_.message_bytes) + ")";
    expected_ = kHeadBytes + 8 + n;
    return std::nullopt;
  }
  if (buffer_.size() < kHeadBytes + kMeshCountBytes) return std::nullopt;
  const auto nv = get<std::uint64_t>(buffer_, kHeadBytes);
  const auto nt = get<std::uint64_t>(buffer_, kHeadBytes + 8);
  const auto ne = get<std::uint64_t>(buffer_, kHeadBytes + 16);
  const auto beyond = [](const char* what, std::uint64_t n, std::uint64_t limit,
                         const char* per) -> std::optional<std::string> {
    if (n <= limit) return std::nullopt;
    return "a mesh of " + count_text(n) + " " + what + ", more than the " + count_text(limit) +
           " the file can describe (" + per + ")";
  };
  if (auto p = beyond("vertices", nv, limits_.vertices, "one per byte")) return p;
  if (auto p = beyond("triangles", nt, limits_.triangles, "one per byte")) return p;
  if (auto p = beyond("edges", ne, limits_.edges, "16 per byte")) return p;
  expected_ = kHeadBytes + kMeshCountBytes + mesh_body_bytes(nv, nt, ne);
  return std::nullopt;
}

std::optional<std::string> RecordReceiver::take(const char* data, std::size_t n) {
  // Grows by what has arrived only, never by a declared size.
  buffer_.append(data, n);
  if (expected_ == 0 && buffer_.size() >= kHeadBytes)
    if (auto p = check_header()) return p;
  if (expected_ != 0 && buffer_.size() > expected_)
    return "more bytes than its record declares (" + count_text(buffer_.size()) + " of " +
           count_text(expected_) + ")";
  return std::nullopt;
}

RecordReceiver::Answer RecordReceiver::finish() {
  Answer a;
  if (buffer_.empty()) {
    a.problem = "no answer";
    return a;
  }
  if (expected_ == 0 && buffer_.size() >= kHeadBytes) {
    if (auto p = check_header()) {
      a.problem = *p;
      return a;
    }
  }
  if (expected_ == 0 || buffer_.size() != expected_) {
    a.problem = "an incomplete answer (" + count_text(buffer_.size()) + " bytes of " +
                (expected_ ? count_text(expected_) : std::string("a record")) + ")";
    return a;
  }
  a.kind = get<std::uint32_t>(buffer_, 8);
  if (a.kind != 0) {
    a.message = buffer_.substr(kHeadBytes + 8);
    return a;
  }
  std::size_t at = kHeadBytes;
  const auto nv = get<std::uint64_t>(buffer_, at);
  const auto nt = get<std::uint64_t>(buffer_, at + 8);
  const auto ne = get<std::uint64_t>(buffer_, at + 16);
  at += kMeshCountBytes;
  Mesh& m = a.mesh;
  m.x.resize(nv), m.y.resize(nv);
  std::memcpy(m.x.data(), buffer_.data() + at, nv * 8), at += nv * 8;
  std::memcpy(m.y.data(), buffer_.data() + at, nv * 8), at += nv * 8;
  for (std::uint64_t i = 0; i < nv; ++i)
    if (!std::isfinite(m.x[i]) || !std::isfinite(m.y[i])) {
      a.problem = "a mesh with vertex " + count_text(i) + " not at a finite position";
      return a;
    }
  const auto vertex = [&](std::int32_t v) { return v >= 0 && std::uint64_t(v) < nv; };
  m.triangles.resize(nt);
  for (std::uint64_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k, at += 4) {
      m.triangles[t][k] = get<std::int32_t>(buffer_, at);
      if (!vertex(m.triangles[t][k])) {
        a.problem = "a mesh whose triangle " + count_text(t) + " names vertex " +
                    std::to_string(m.triangles[t][k]) + " of " + count_text(nv);
        return a;
      }
    }
  m.zone.resize(nt);
  for (std::uint64_t t = 0; t < nt; ++t, at += 4) {
    m.zone[t] = get<std::int32_t>(buffer_, at);
    if (!limits_.zones.empty() && !limits_.zones.count(m.zone[t])) {
      a.problem = "a mesh whose triangle " + count_text(t) + " is in zone " +
                  std::to_string(m.zone[t]) + ", which no zone group maps to";
      return a;
    }
  }
  m.fracture.assign(buffer_.begin() + long(at), buffer_.begin() + long(at + nt)), at += nt;
  for (std::uint64_t t = 0; t < nt; ++t)
    if (m.fracture[t] > 1) {
      a.problem = "a mesh whose triangle " + count_text(t) + " has fracture flag " +
                  std::to_string(m.fracture[t]) + " (0 or 1)";
      return a;
    }
  m.edges.reserve(ne);
  for (std::uint64_t e = 0; e < ne; ++e, at += 12) {
    const TaggedEdge edge{get<std::int32_t>(buffer_, at), get<std::int32_t>(buffer_, at + 4),
                          get<std::int32_t>(buffer_, at + 8)};
    if (!vertex(edge.a) || !vertex(edge.b)) {
      a.problem =
          "a mesh whose edge " + count_text(e) + " names a vertex beyond its " + count_text(nv);
      return a;
    }
    // A trace has a line at least: its number is below the edges' count.
    if (edge.tag < 0 && std::uint64_t(-1 - std::int64_t(edge.tag)) >= ne) {
      a.problem = "a mesh whose joint edge " + count_text(e) + " names trace " +
                  std::to_string(-1 - std::int64_t(edge.tag)) + " of at most " + count_text(ne);
      return a;
    }
    if (edge.tag >= 0)
      m.edges.push_back(edge);
    else
      m.joint_edges.push_back({edge.a, edge.b, -1 - edge.tag});
  }
  std::string().swap(buffer_);
  return a;
}

double child_time_limit_s(std::uint64_t file_bytes) {
  return 60.0 + 4.0 * double(file_bytes) / double(1 << 20);
}

std::uint64_t child_memory_budget(std::uint64_t file_bytes) {
  return (std::uint64_t(1) << 30) + 32 * file_bytes;
}

namespace {

// A test hook: ROCKFDEM_TEST_MSH_CHILD=hang (the child never answers; the
// time limit is then 2 s), exit (it exits with status 3 before reading),
// truncate (it sends half its record) or allocate (it takes memory in 64
// MiB blocks, up to 4 GiB, before reading).
std::string test_hook() {
  const char* v = std::getenv("ROCKFDEM_TEST_MSH_CHILD");
  return v ? v : "";
}

bool write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w, n -= std::size_t(w);
  }
  return true;
}

// The child's address space: what it maps at the fork (libraries, the
// parent's heap) plus child_memory_budget(), so that a count forged in a
// file ends in std::bad_alloc, which the parent reports as running out of
// memory, instead of taking the machine's memory.
void limit_address_space(std::uint64_t file_bytes) {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  const bool known = f && std::fscanf(f, "%lu", &pages) == 1;
  if (f) std::fclose(f);
  if (!known) return;  // no /proc: the machine's memory bounds it
  rlimit r{};
  r.rlim_cur = r.rlim_max =
      rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + rlim_t(child_memory_budget(file_bytes));
  ::setrlimit(RLIMIT_AS, &r);
}

// The allocate hook: memory taken and touched until it is refused.
void take_memory() {
  std::vector<std::vector<char>> held;
  for (int i = 0; i < 64; ++i) held.emplace_back(std::size_t(64) << 20, char(1));
}

[[noreturn]] void child_main(int fd, pid_t parent, const std::string& hook,
                             std::uint64_t file_bytes, const std::function<Mesh()>& read) {
  // Dies with the parent (a SIGKILL of the run must not leave it reading);
  // the parent may have gone before the request took effect.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) _exit(120);
  // The parent decides what SIGINT and SIGTERM do to the run; the child
  // would otherwise inherit a handler that prints the run's last words. A
  // crash is left to kill the child (not a sanitizer's or any handler's
  // report, so the parent always sees the signal).
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGTERM, SIG_IGN);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGPIPE}) std::signal(sig, SIG_DFL);
  omp_set_num_threads(1);
  if (hook == "hang")
    for (;;) ::pause();
  if (hook == "exit") _exit(3);
  limit_address_space(file_bytes);
  std::string record;
  try {
    if (hook == "allocate") take_memory();
    record = encode_mesh(read());
  } catch (const InputError& e) {
    record = encode_error(1, e.what());
  } catch (const std::bad_alloc&) {
    record = encode_error(4, "");
  } catch (const std::logic_error& e) {
    record = encode_error(3, e.what());
  } catch (const std::runtime_error& e) {
    record = encode_error(2, e.what());
  } catch (const std::exception& e) {
    record = encode_error(5, e.what());
  } catch (...) {
    record = encode_error(5, "an exception of unknown type");
  }
  if (hook == "truncate") record.resize(record.size() / 2);
  _exit(write_all(fd, record.data(), record.size()) ? 0 : 121);
}

// "signal 11, SIGSEGV".
std::string signal_name(int sig) {
  const char* abbrev = sigabbrev_np(sig);
  return "signal " + std::to_string(sig) + (abbrev ? ", SIG" + std::string(abbrev) : "");
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { close(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

}  // namespace

Mesh read_in_child(const std::string& path, const RecordLimits& limits,
                   const std::function<Mesh()>& read) {
  const std::string hook = test_hook();
  const double limit_s = hook == "hang" ? 2.0 : child_time_limit_s(limits.file_bytes);
  const auto fail = [&](const std::string& what) -> InputError {
    return InputError(printable(path + ": " + what));
  };
  const std::string allowed =
      "; nothing was read from it; allowed: a well-formed .msh file as gmsh writes it (MSH 2.2 "
      "or 4.1, ASCII or binary)";

  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(
        path + ": cannot start a process to read it (pipe: " + std::strerror(errno) + ")");
  Fd in(fds[0]), out(fds[1]);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0)
    throw std::runtime_error(
        path + ": cannot start a process to read it (fork: " + std::strerror(errno) + ")");
  if (pid == 0) {
    in.close();
    child_main(out.get(), parent, hook, limits.file_bytes, read);
  }
  out.close();

  // Reads until the child closes its end (it exits), the record proves
  // implausible or the time is up; then collects the child.
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(limit_s);
  const auto left_ms = [&] {
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return int(std::max<long long>(0, std::min<long long>(ms, 1 << 30)));
  };
  RecordReceiver receiver(limits);
  std::optional<std::string> implausible;
  bool timed_out = false;
  std::string buf(1 << 16, '\0');
  for (;;) {
    pollfd p{in.get(), POLLIN, 0};
    const int ready = ::poll(&p, 1, left_ms());
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) {
      timed_out = true;
      break;
    }
    const ssize_t n = ::read(in.get(), buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of the record (or a read error: judged below)
    if ((implausible = receiver.take(buf.data(), std::size_t(n)))) break;
  }
  in.close();
  int status = 0;
  bool collected = false;
  for (auto pause = std::chrono::microseconds(200);;) {
    if (timed_out || implausible) ::kill(pid, SIGKILL);
    const pid_t w = ::waitpid(pid, &status, timed_out || implausible ? 0 : WNOHANG);
    if (w == pid) {
      collected = true;
      break;
    }
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) break;  // ECHILD: SIGCHLD ignored, the child reaped already
    if (left_ms() == 0) {
      timed_out = true;
      continue;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }

  if (timed_out) {
    char s[32];
    std::snprintf(s, sizeof s, "%.0f", limit_s);
    throw fail("gmsh did not finish reading it within " + std::string(s) +
               " s (the limit for its " + std::to_string(limits.file_bytes) +
               " bytes: 60 s + 4 s per MiB) and was stopped" + allowed);
  }
  if (collected && WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGKILL && !implausible)
      throw fail("the process reading it with gmsh was killed (" + signal_name(sig) +
                 "), perhaps by the system for lack of memory" + allowed);
    if (!implausible)
      throw fail("gmsh crashed reading it (" + signal_name(sig) +
                 "): the file is malformed in a way gmsh's reader does not check" + allowed);
  }
  if (implausible)
    throw fail("the process reading it with gmsh sent " + *implausible +
               " (its memory was likely corrupted by the file)" + allowed);
  if (collected && WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw fail("the process reading it with gmsh ended with exit status " +
               std::to_string(WEXITSTATUS(status)) + " before it answered" + allowed);
  RecordReceiver::Answer a = receiver.finish();
  if (!a.problem.empty())
    throw fail("the process reading it with gmsh sent " + a.problem + allowed);
  switch (a.kind) {
    case 0:
      return std::move(a.mesh);
    case 1:
      throw InputError(a.message);
    case 3:
      throw std::logic_error(a.message);
    case 4:  // the child's memory, limited for this file, not the run's
      throw fail("gmsh ran out of memory reading it (the reading process may take " +
                 std::to_string(child_memory_budget(limits.file_bytes) >> 20) +
                 " MiB): a count in the file is larger than the file holds" + allowed);
    default:
      throw std::runtime_error(a.message);
  }
}

}  // namespace rockfdem::mesh::detail
