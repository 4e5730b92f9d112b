#include "run/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <string>

namespace rockfdem::workflows {
namespace {

// Lock-free, so reading and writing it in a signal handler is allowed.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int sig) {
  if (g_signal.exchange(sig) != 0) _exit(128 + sig);  // second signal: leave now
}

// Before a command's own handling: one line saying what stopped it, then
// the usual 128 + signal. write(2) and _exit are async-signal-safe.
extern "C" void on_early_signal(int sig) {
  static const char term[] =
      "rockfdem: stopped by signal 15 (SIGTERM) before a run's stages; no checkpoint (files "
      "written so far are whole)\n";
  static const char intr[] =
      "rockfdem: stopped by signal 2 (SIGINT) before a run's stages; no checkpoint (files "
      "written so far are whole)\n";
  const bool is_term = sig == SIGTERM;
  [[maybe_unused]] const ssize_t n =
      ::write(STDERR_FILENO, is_term ? term : intr, is_term ? sizeof term - 1 : sizeof intr - 1);
  _exit(128 + sig);
}

extern "C" void on_closing_signal(int sig) {
  static const char term[] =
      "rockfdem: stopped by signal 15 (SIGTERM) as the command ended; its outputs are written\n";
  static const char intr[] =
      "rockfdem: stopped by signal 2 (SIGINT) as the command ended; its outputs are written\n";
  const bool is_term = sig == SIGTERM;
  [[maybe_unused]] const ssize_t n =
      ::write(STDERR_FILENO, is_term ? term : intr, is_term ? sizeof term - 1 : sizeof intr - 1);
  _exit(128 + sig);
}

void install(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

void install_early_handlers() { install(on_early_signal); }

void install_closing_handlers() { install(on_closing_signal); }

void install_interrupt_handlers() { install(on_signal); }

int interrupt_requested() { return g_signal.load(std::memory_order_relaxed); }

std::string signal_text(int sig) {
  const char* name = sig == SIGTERM ? " (SIGTERM)" : sig == SIGINT ? " (SIGINT)" : "";
  return "signal " + std::to_string(sig) + name;
}

void throw_if_interrupted(const std::string& state) {
  const int sig = interrupt_requested();
  if (sig != 0) throw Interrupted(sig, "stopped by " + signal_text(sig) + " " + state);
}

void signal_point(const char* moment) {
  const char* spec = std::getenv("ROCKFDEM_TEST_SIGNAL_AT");
  if (spec == nullptr) return;
  std::string text(spec);
  int sig = SIGTERM;
  const std::size_t colon = text.find(':');
  if (colon != std::string::npos) {
    if (text.substr(colon + 1) == "INT") sig = SIGINT;
    text.erase(colon);
  }
  long wanted = 1;
  const std::size_t hash = text.find('#');
  if (hash != std::string::npos) {
    wanted = std::strtol(text.c_str() + hash + 1, nullptr, 10);
    text.erase(hash);
  }
  if (text != moment) return;
  static long passed = 0;  // one moment per process: the variable names one
  if (++passed == wanted) std::raise(sig);
}

}  // namespace rockfdem::workflows
