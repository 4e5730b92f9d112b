#include "record/phase_timer.hpp"

#include <sys/resource.h>

#include <cstdio>

namespace rockfdem::workflows {

namespace {

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

}  // namespace

PhaseTimer::PhaseTimer() : start_(Clock::now()), last_(start_) {}

void PhaseTimer::stamp(const std::string& phase) {
  const Clock::time_point now = Clock::now();
  if (!seconds_.count(phase)) order_.push_back(phase);
  seconds_[phase] += std::chrono::duration<double>(now - last_).count();
  peak_mib_[phase] = peak_rss_mib();
  last_ = now;
}

double PhaseTimer::peak_mib(const std::string& phase) const {
  const auto it = peak_mib_.find(phase);
  return it == peak_mib_.end() ? 0.0 : it->second;
}

double PhaseTimer::seconds(const std::string& phase) const {
  const auto it = seconds_.find(phase);
  return it == seconds_.end() ? 0.0 : it->second;
}

double PhaseTimer::total() const { return std::chrono::duration<double>(last_ - start_).count(); }

std::string PhaseTimer::table() const {
  const char* rule = "+----------------------+------------+------------+\n";
  std::string out = rule;
  char line[128];
  std::snprintf(line, sizeof line, "| %-20s | %9.3fs | %10s |\n", "Total wall time", total(), "");
  out += line;
  out += rule;
  std::snprintf(line, sizeof line, "| %-20s | %10s | %10s |\n", "Phase", "wall time", "% of total");
  out += line;
  out += rule;
  for (const std::string& p : order_) {
    const double s = seconds(p);
    std::snprintf(line, sizeof line, "| %-20s | %9.3fs | %9.1f%% |\n", p.c_str(), s,
                  total() > 0 ? 100.0 * s / total() : 0.0);
    out += line;
  }
  out += rule;
  return out;
}

}  // namespace rockfdem::workflows
