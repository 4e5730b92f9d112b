// Progress on stderr for long work: stage, step, simulated time, steps per
// second and the time left; silent with -q. At most one line a second.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace rockfdem::workflows {

class Progress {
 public:
  /// Lines go to `out` (stderr unless a test captures them).
  Progress(std::string stage, long total_steps, bool quiet, std::FILE* out = stderr);
  void update(long step, double simulated_time);
  /// The stage's last line, unless update() has just printed that step.
  void finish(long step, double simulated_time);

 private:
  void print(long step, double simulated_time);
  using Clock = std::chrono::steady_clock;
  std::string stage_;
  long total_;
  bool quiet_;
  std::FILE* out_;
  long printed_step_ = -1;
  Clock::time_point start_, last_;
};

}  // namespace rockfdem::workflows
