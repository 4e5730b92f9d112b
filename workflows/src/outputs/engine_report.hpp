// The explicit engine's part of summary.json, the same for every kind of
// run: counts, steps, dt, throughput over the time loop, broken cracks by
// mode, contact counters (and what was skipped), phase times, state hash.
#pragma once

#include <string>
#include <vector>

#include "record/phase_timer.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"

namespace rockfdem::workflows {

void report_engine(const fdem::Engine& e, const PhaseTimer& timer, RunRecord& summary);

/// One state of the engine as the record describes it: steps, dt (the
/// last step's), simulated_time, broken, energy (`en`, the state's balance)
/// and state_hash.
EngineState engine_state(const fdem::Engine& e, const fdem::EnergyBalance& en);

/// history.csv's energy columns and one row of them (energy since the
/// first step [J/m]: external work, change of stored energy, dissipated and
/// taken out by stage controls, residual and relative imbalance).
std::vector<std::string> energy_columns();
std::vector<double> energy_row(const fdem::EnergyBalance& b);

}  // namespace rockfdem::workflows
