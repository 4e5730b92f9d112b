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
/// Installs the handlers (idempotent). A request that came before stays:
/// a study installs them once at its start and each variant's run again,
/// and a signal between two variants must still stop the study.
void install_interrupt_handlers();
/// The signal that asked the run to stop, or 0.
int interrupt_requested();
/// Once a command has returned: a signal from now on prints one line
/// saying the outputs are whole and exits 128 + signal at once, so that
/// one arriving while the process closes (MPI's finalisation) is not lost.
/// main() then checks for a signal that came before (throw_if_interrupted).
void install_closing_handlers();

/// Test hook: raises SIGTERM (or the signal named) the n-th time the
/// program passes `moment`, when the environment variable
/// ROCKFDEM_TEST_SIGNAL_AT is `MOMENT[#N][:INT|:TERM]` (N is 1 when left
/// out). Lets a test deliver a signal at a chosen moment instead of after a
/// guessed delay; without the variable it does nothing.
void signal_point(const char* moment);

/// Thrown once an interrupted run has written its outputs; main() maps it
/// to the exit code 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

/// "signal 15 (SIGTERM)", "signal 2 (SIGINT)": how messages name a signal.
std::string signal_text(int sig);

/// Throws Interrupted when a signal asked to stop: "stopped by signal 15
/// (SIGTERM) " + `state` (what is written, how to resume).
void throw_if_interrupted(const std::string& state);

}  // namespace rockfdem::workflows
