#include "interrupt.hpp"

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

}  // namespace

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
