// A tunnel run's construction stages on its time axis, read from the
// summary's stage report: the markers of the plots against (pseudo-)time,
// and the origin of convergence measured from the support's installation.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "record/run_figures.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

/// When one explicit stage began and ended on the run's time axis [s]
/// and in steps.
struct StageSpan {
  std::string kind;
  double start = 0, end = 0;
  double first_step = 0, last_step = 0;  ///< equal for a stage of no steps
  const StageRecord* report = nullptr;   ///< its entry of the record's stages
};

/// The stages of `stages` (the record's stage reports: kind, simulated_time
/// and steps per stage, in order) laid end to end from `t_handoff` and
/// `step_handoff`, the time and step at the end of the hand-off step
/// (history.csv's first row). The spans point into `stages`, which must
/// outlive them.
std::vector<StageSpan> stage_spans(const std::vector<StageRecord>& stages, double t_handoff,
                                   double step_handoff = 0);

/// The plots' stage bands on the step axis: one per stage that took steps,
/// labelled with its number and kind; the stages of no steps before it are
/// named at the head of its label ("2 lining, 3 bolts, then 5 grout"), and
/// a grout stage that grouted says how many cracks it re-joined.
std::vector<plots::PlotBand> stage_bands(const std::vector<StageSpan>& spans);

/// One marker per stage start, stages starting together sharing one
/// ("lining, bolts, remove_core"); a grout stage that grouted adds one at
/// its end, where the broken count drops ("grouting: N cracks re-joined").
std::vector<plots::PlotMarker> stage_markers(const std::vector<StageSpan>& spans);

/// The first `lining` or `bolts` stage, or null where the run installed no support.
const StageSpan* support_stage(const std::vector<StageSpan>& spans);

/// The index of the last of `times` (ascending) at or before `t` (within a
/// relative 1e-9 of the time axis' length, for sums of stage times); 0 when
/// none is.
std::size_t row_at(const std::vector<double>& times, double t);

/// `values` from row `from` on, less their value there.
std::vector<double> since_row(const std::vector<double>& values, std::size_t from);

}  // namespace rockfdem::workflows
