#include "outputs/last_good.hpp"

#include "outputs/engine_report.hpp"

namespace rockfdem::workflows {

void LastGoodState::take(const fdem::Engine& e, const fdem::EnergyBalance& energy,
                         MonitorRecord monitors) {
  state_ = engine_state(e, energy);
  monitors_ = std::move(monitors);
}

void LastGoodState::report_failure(const fdem::Engine& e, const PhaseTimer& timer,
                                   const std::string& why, RunRecord& summary) const {
  report_engine(e, timer, summary);  // counts, timings, skipped; figures of the wreck ...
  if (state_) {                      // ... replaced by the last good ones
    summary.state = *state_;
    summary.monitors = monitors_;
  }
  summary.dt_range = std::make_pair(summary.state.dt, summary.state.dt);
  summary.status = "failed";
  summary.failure = why;
  summary.set_timings(timer);
}

}  // namespace rockfdem::workflows
