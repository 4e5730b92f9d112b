// SIGINT and SIGTERM during a run: the first signal asks the run to stop
// after the current step (it then writes its outputs and a checkpoint and
// exits with 128 + signal: 130 or 143); a second one exits at once. Every
// output is written atomically, so exiting at once leaves each file either
// in its previous complete version or its new one.
#pragma once

#include <stdexcept>
#include <string>

namespace rockfdem::workflows {

/// From the start of main() until a run installs its own: SIGINT or
/// SIGTERM prints one line naming the signal and exits 128 + signal (the
/// default action ended the process without a word during start-up, about
/// 0.9 s of MPI initialisation and scene reading, and during commands that
/// install no handlers of their own).
void install_early_handlers();
/// Installs the handlers (idempotent) and clears any earlier request.
void install_interrupt_handlers();
/// The signal that asked the run to stop, or 0.
int interrupt_requested();

/// Thrown once an interrupted run has written its outputs; main() maps it
/// to the exit code 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

}  // namespace rockfdem::workflows
