// The explicit engine's part of summary.json, the same for every kind of
// run: counts, steps, dt, throughput over the time loop, broken cracks by
// mode, contact counters (and what was skipped), phase times, state hash.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/phase_timer.hpp"
#include "run/summary.hpp"

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

/// Energy is not created by a sound run: a relative imbalance above this
/// (measured at most 0.2-3% on sound runs, docs/reliability.md) means the
/// integration diverged, typically with a dt forced above the limit while
/// crack elements break before any velocity can grow.
constexpr double kEnergyImbalanceLimit = 0.10;

/// Below this absolute residual [J/m] a relative imbalance says nothing:
/// when the energies moved are tiny (a platen at a lab rate, a near-zero
/// in-situ stress) the ledger's first half steps and rounding dominate
/// them. 1e-6 of the rock's elastic energy density at its tensile strength
/// (ft^2 / 2E; 1e-3 E where no ft is given) over the model's area: a
/// divergence passes it within a few steps.
double energy_floor(const Scene& scene, const mesh::Mesh& m);

/// Sound runs close their energy balance within a few tenths of a per cent
/// (at most 3% measured, docs/reliability.md); above this a run that
/// completed carries a warning.
constexpr double kEnergyWarningLimit = 0.03;

/// Adds to summary.json "warnings" (and says on stderr unless `quiet`) when
/// the run's final imbalance exceeds kEnergyWarningLimit with a residual
/// above `floor` (energy_floor).
void warn_if_unbalanced(const fdem::Engine& e, double floor, bool quiet, RunRecord& summary);

/// Throws NumericalError naming the step and the terms when the balance's
/// relative imbalance exceeds kEnergyImbalanceLimit and its residual
/// exceeds `floor` (energy_floor).
void check_energy(const fdem::EnergyBalance& b, long step, double floor);

}  // namespace rockfdem::workflows
