#include "run/last_good.hpp"

#include "outputs/engine_report.hpp"

namespace rockfdem::workflows {

void LastGoodState::take(const fdem::Engine& e, const fdem::EnergyBalance& energy,
                         nlohmann::json monitors) {
  figures_ = state_figures(e, energy);
  figures_["monitors"] = std::move(monitors);
}

void LastGoodState::report_failure(const fdem::Engine& e, const PhaseTimer& timer,
                                   const std::string& why, RunRecord& summary) const {
  report_engine(e, timer, summary);  // counts, timings, skipped; figures of the wreck ...
  auto& j = summary.figures();
  if (!figures_.is_null()) j.update(figures_);  // ... replaced by the last good ones
  j["dt_min"] = j["dt_max"] = j["dt"];
  summary.status = "failed";
  summary.failure = why;
  summary.set_timings(timer);
}

}  // namespace rockfdem::workflows
