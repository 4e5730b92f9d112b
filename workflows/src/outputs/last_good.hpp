// The state a failed run reports. A NumericalError leaves the engine
// diverged (an inverted triangle, a broken energy balance); the outputs
// keep the last state that passed its checks, the one the last frame
// shows, and summary.json describes that one, not the wreck.
#pragma once

#include <optional>
#include <string>

#include "record/phase_timer.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::workflows {

class LastGoodState {
 public:
  /// Notes the engine's state once it passed the energy check (`energy`,
  /// its balance) and was written; `monitors`: the record's monitor
  /// figures for it (none for specimens).
  void take(const fdem::Engine& e, const fdem::EnergyBalance& energy, MonitorRecord monitors = {});
  /// summary.json of a run a NumericalError stopped: the model's counts
  /// and the timings so far, this state's steps, dt, time, broken counts,
  /// energy, monitors and hash, status "failed" and the diagnostic.
  void report_failure(const fdem::Engine& e, const PhaseTimer& timer, const std::string& why,
                      RunRecord& summary) const;

 private:
  std::optional<EngineState> state_;  ///< the last good state; none before the first
  MonitorRecord monitors_;
};

}  // namespace rockfdem::workflows
