#include "run/progress.hpp"

#include <cstdio>

namespace rockfdem::workflows {

Progress::Progress(std::string stage, long total_steps, bool quiet, std::FILE* out)
    : stage_(std::move(stage)),
      total_(total_steps),
      quiet_(quiet),
      out_(out),
      start_(Clock::now()),
      last_(start_) {}

void Progress::update(long step, double simulated_time) {
  if (quiet_) return;
  const Clock::time_point now = Clock::now();
  if (std::chrono::duration<double>(now - last_).count() < 1.0) return;
  last_ = now;
  print(step, simulated_time);
}

void Progress::finish(long step, double simulated_time) {
  if (!quiet_ && step != printed_step_) print(step, simulated_time);
}

void Progress::print(long step, double simulated_time) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  const double rate = elapsed > 0 ? step / elapsed : 0;
  const double eta = rate > 0 ? (total_ - step) / rate : 0;
  printed_step_ = step;
  std::fprintf(out_, "[%s] step %ld/%ld  t = %.4g s  %.0f steps/s  ETA %.0f s\n", stage_.c_str(),
               step, total_, simulated_time, rate, eta);
}

}  // namespace rockfdem::workflows
