// What the workflow benches share: running the rockfdem binary (or another
// bench) as a child with its output in a log, quoting its command line for
// the report, and reading numbers back from its summary.json.
#pragma once

#include <fcntl.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/utsname.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {

// A bad option: the bench prints it with its usage and exits with 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A size as it appears in folder names and in --set: the shortest %g form.
inline std::string size_text(double h) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", h);
  return buf;
}

inline std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// A word as a POSIX shell would need it to read it back unchanged.
inline std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-+=.,/:@%") == std::string::npos;
  if (plain) return word;
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline std::string join_quoted(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + shell_quote(w);
  return s;
}

// A child's end: its exit code (128 + signal for one killed by a signal,
// 127 when it could not start) and its peak resident set.
struct ChildEnd {
  int exit_code = 1;
  double peak_rss_mib = 0;
};

// Runs args[0] with args, stdout and stderr to `log`.
inline ChildEnd run_logged(const std::vector<std::string>& args, const std::string& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    execv(argv[0], argv.data());
    std::fprintf(stderr, "exec %s: %s\n", argv[0], std::strerror(errno));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR) throw std::runtime_error(std::string("wait4: ") + std::strerror(errno));
  ChildEnd end;
  end.peak_rss_mib = double(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
  if (WIFEXITED(status)) end.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) end.exit_code = 128 + WTERMSIG(status);
  return end;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The last non-empty line of a file: what a failed run said last.
inline std::string last_line(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line, last = "(no output; see " + path.string() + ")";
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

// A number at a path of keys, or nothing where a key is missing or null
// (older summaries lack some of them).
inline std::optional<double> number_at(const nlohmann::json& j,
                                       std::initializer_list<const char*> path) {
  const nlohmann::json* p = &j;
  for (const char* key : path) {
    if (!p->is_object() || !p->contains(key)) return std::nullopt;
    p = &(*p)[key];
  }
  if (!p->is_number()) return std::nullopt;
  return p->get<double>();
}

// Where and when a bench ran, for its report's header.
struct Machine {
  std::string date;  // local time
  std::string host;
  int cpus = 1;          // as nproc counts them (the affinity mask)
  double load_1min = 0;  // the load average when asked
};

inline Machine this_machine() {
  Machine m;
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M %Z", std::localtime(&now));
  m.date = date;
  utsname host{};
  uname(&host);
  m.host = host.nodename;
  cpu_set_t cpus;
  CPU_ZERO(&cpus);
  m.cpus = sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus)
                                                         : int(sysconf(_SC_NPROCESSORS_ONLN));
  double load[1] = {0};
  if (getloadavg(load, 1) == 1) m.load_1min = load[0];
  return m;
}

}  // namespace bench
