// What the stage loop (StageRunner) tells a run's outputs: per output
// step a row, then (after the energy check) a frame; and the support's
// installation. A tunnel's outputs (RunOutputs) and a specimen's
// (SpecimenOutputs) both observe the loop through this one interface.
#pragma once

#include <string>
#include <vector>

#include "outputs/monitors.hpp"
#include "record/phase_timer.hpp"
#include "record/run_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

/// The stage an output step belongs to: its kind ("handoff" for the
/// hand-off step) and its number, the same in history.csv, summary.json and
/// report.md: 0 the implicit stage (whose hand-off step it is), then the
/// explicit stages in order, as [[stages]] lists them after `insitu`.
struct StageTag {
  std::string kind;
  int number = 0;
};

class StepOutputs {
 public:
  virtual ~StepOutputs() = default;
  /// An output step's history row of `stage`, before the run's checks of
  /// the step (so that a failing step has its row); `support_ratio`: the
  /// core's stiffness factor then (0 once removed).
  virtual void record_rows(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                           double support_ratio, const fdem::EnergyBalance& energy) = 0;
  /// The output step once the run's checks passed: the ParaView frame (if
  /// enabled) and the last good state.
  virtual void record_frame(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                            const fdem::EnergyBalance& energy, PhaseTimer& timer) = 0;
  /// The outer boundary's rigid rotation now [rad] (its least-squares fit,
  /// outputs/outer_boundary.hpp), for the stage loop's guard; 0 where the
  /// model has no outer box (specimens).
  virtual double outer_rotation(const fdem::Engine&) { return 0; }
  /// Whether the lining ring is installed as lining (tunnels).
  virtual void set_lining_installed(bool) {}
  /// Stage `stage` ended, having done `done` (its record's changes, which
  /// the outputs complete with the files they wrote from it), leaving the
  /// model as `e` holds it.
  virtual void stage_done(const fdem::Engine&, const mesh::Mesh&, const StageTag&, StageChanges&) {}
  /// A `lining` or `bolts` stage installed its support (tunnels).
  virtual void support_installed(const fdem::Engine&) {}
};

}  // namespace rockfdem::workflows
