// Wall time by named phase, printed as a table in the spirit of deal.II's
// TimerOutput and stored in summary.json's "timings"; with each phase the
// process's peak resident memory so far ("peak_memory_mib"), so a run at
// scale shows which phase set the peak.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace rockfdem::workflows {

class PhaseTimer {
 public:
  PhaseTimer();
  /// Adds the time since the last stamp (or construction) to `phase`.
  void stamp(const std::string& phase);
  double seconds(const std::string& phase) const;
  /// The process's peak resident set [MiB] at the phase's last stamp: the
  /// peak of everything up to its end (0 where the phase never ran).
  double peak_mib(const std::string& phase) const;
  double total() const;
  const std::vector<std::string>& order() const { return order_; }
  std::string table() const;

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_, last_;
  std::map<std::string, double> seconds_;
  std::map<std::string, double> peak_mib_;
  std::vector<std::string> order_;
};

}  // namespace rockfdem::workflows
