#include "outputs/run_timeline.hpp"

#include <algorithm>
#include <cmath>

#include "stages/registry.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {

std::vector<StageSpan> stage_spans(const std::vector<StageRecord>& stages, double t_handoff,
                                   double step_handoff) {
  std::vector<StageSpan> spans;
  double t = t_handoff, step = step_handoff;
  for (const StageRecord& s : stages) {
    spans.push_back({s.kind, t, t + s.simulated_time, step, step + double(s.steps), &s});
    t += s.simulated_time;
    step += double(s.steps);
  }
  return spans;
}

namespace {

std::string numbered(const StageSpan& s) {
  return (s.report ? std::to_string(s.report->number) + " " : std::string()) + s.kind;
}

}  // namespace

std::vector<plots::PlotBand> stage_bands(const std::vector<StageSpan>& spans) {
  std::vector<plots::PlotBand> bands;
  std::string before;  // the stages of no steps since the last band
  for (const StageSpan& s : spans) {
    if (!(s.last_step > s.first_step)) {
      before += (before.empty() ? "" : ", ") + numbered(s);
      continue;
    }
    std::string label = before.empty() ? numbered(s) : before + ", then " + numbered(s);
    before.clear();
    const StageChanges none;
    const StageChanges& changes = s.report ? s.report->changes : none;
    if (changes.triggered.value_or(false))  // only a grout stage triggers
      label += " (" + std::to_string(changes.rejoined.value_or(0)) + " cracks re-joined)";
    bands.push_back({s.first_step, s.last_step, label});
  }
  if (!before.empty() && !bands.empty()) bands.back().label += ", then " + before;
  return bands;
}

std::vector<plots::PlotMarker> stage_markers(const std::vector<StageSpan>& spans) {
  std::vector<plots::PlotMarker> out;
  const double length = spans.empty() ? 0.0 : spans.back().end - spans.front().start;
  const auto add = [&](double x, const std::string& label) {
    // Stages of no steps start where the next one does: one marker, all names.
    if (!out.empty() && std::abs(out.back().x - x) <= 1e-9 * length)
      out.back().label += ", " + label;
    else
      out.push_back({x, label});
  };
  for (const StageSpan& s : spans) {
    add(s.start, s.kind);
    const StageChanges none;
    const StageChanges& changes = s.report ? s.report->changes : none;
    if (changes.triggered.value_or(false))  // only a grout stage triggers
      add(s.end,
          "grouting: " + std::to_string(changes.rejoined.value_or(0)) + " broken cracks re-joined");
  }
  return out;
}

const StageSpan* support_stage(const std::vector<StageSpan>& spans) {
  for (const StageSpan& s : spans)
    if (stage_of(s.kind).installs_support()) return &s;
  return nullptr;
}

std::size_t row_at(const std::vector<double>& times, double t) {
  if (times.empty()) return 0;
  const double tol = 1e-9 * std::abs(times.back() - times.front());
  std::size_t row = 0;
  for (std::size_t i = 0; i < times.size(); ++i)
    if (times[i] <= t + tol) row = i;
  return row;
}

std::vector<double> since_row(const std::vector<double>& values, std::size_t from) {
  std::vector<double> out;
  for (std::size_t i = from; i < values.size(); ++i) out.push_back(values[i] - values[from]);
  return out;
}

}  // namespace rockfdem::workflows
