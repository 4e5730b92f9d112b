// The energy balance as the time loop's check: a sound run creates no
// energy. The stage loop (StageRunner) owns one check and runs it at every
// output step (a broken balance stops the run before its frame is
// written); at the end, a balance that closes only loosely is a warning.
#pragma once

#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Energy is not created by a sound run: a relative imbalance above this
/// (measured at most 0.2-3% on sound runs, docs/reliability.md) means the
/// integration diverged, typically with a dt forced above the limit while
/// crack elements break before any velocity can grow.
constexpr double kEnergyImbalanceLimit = 0.10;

/// Sound runs close their energy balance within a few tenths of a per cent
/// (at most 3% measured, docs/reliability.md); above this a run that
/// completed carries a warning.
constexpr double kEnergyWarningLimit = 0.03;

class EnergyCheck {
 public:
  /// The floor (floor()) from the scene's rock and the model's area.
  EnergyCheck(const Scene& scene, const mesh::Mesh& m);
  /// Below this absolute residual [J/m] a relative imbalance says nothing:
  /// when the energies moved are tiny (a platen at a lab rate, a near-zero
  /// in-situ stress) the ledger's first half steps and rounding dominate
  /// them. 1e-6 of the rock's elastic energy density at its tensile
  /// strength (ft^2 / 2E; 1e-3 E where no ft is given) over the model's
  /// area: a divergence passes it within a few steps.
  double floor() const { return floor_; }
  /// Throws NumericalError naming the step and the terms when the
  /// balance's relative imbalance exceeds kEnergyImbalanceLimit and its
  /// residual exceeds the floor (or the imbalance is not finite).
  void at_output_step(const fdem::EnergyBalance& b, long step) const;
  /// Adds to summary.json "warnings" (and says on stderr unless `quiet`)
  /// when the run's final imbalance exceeds kEnergyWarningLimit with a
  /// residual above the floor.
  void warn_if_unbalanced(const fdem::Engine& e, bool quiet, RunRecord& summary) const;

 private:
  double floor_ = 0;
};

}  // namespace rockfdem::workflows
