// Progress on stderr for long work: stage, step, simulated time, steps per
// second and the time left; silent with -q. At most one line a second.
#pragma once

#include <chrono>
#include <string>

namespace rockfdem::workflows {

class Progress {
 public:
  Progress(std::string stage, long total_steps, bool quiet);
  void update(long step, double simulated_time);
  void finish(long step, double simulated_time);

 private:
  void print(long step, double simulated_time);
  using Clock = std::chrono::steady_clock;
  std::string stage_;
  long total_;
  bool quiet_;
  Clock::time_point start_, last_;
};

}  // namespace rockfdem::workflows
