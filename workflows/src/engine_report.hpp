// The explicit engine's part of summary.json, the same for every kind of
// run: counts, steps, dt, throughput over the time loop, broken cracks by
// mode, contact counters (and what was skipped), phase times, state hash.
#pragma once

#include "phase_timer.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "summary.hpp"

namespace rockfdem::workflows {

void report_engine(const fdem::Engine& e, const PhaseTimer& timer, RunSummary& summary);

}  // namespace rockfdem::workflows
