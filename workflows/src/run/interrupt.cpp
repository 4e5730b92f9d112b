#include "run/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>

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

}  // namespace

void install_early_handlers() {
  struct sigaction action {};
  action.sa_handler = on_early_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void install_interrupt_handlers() {
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_requested() { return g_signal.load(std::memory_order_relaxed); }

}  // namespace rockfdem::workflows
