// report.md: a tunnel run's answers in one page an engineer reads, made
// from the run's in-memory record (the summary) at the end of the run,
// also when it ends unstable, not at equilibrium, failed or interrupted.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "record/summary.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// What the report needs besides the scene and the run's record.
struct ReportExtras {
  /// Key points (radial) and chords ("wall_chord", "shoulder_chord") [mm]
  /// measured from the support's installation; empty when the run has none.
  std::map<std::string, double> since_support_mm;
  std::vector<std::string> pictures;  ///< PNG files rendered, linked in order
};

/// The report's Markdown text: inputs, stage table, status and equilibrium
/// figures, key points and chords against the scene's [references], bolt
/// and lining maxima, the broken zone, the pictures.
std::string report_markdown(const Scene& scene, const RunRecord& record,
                            const ReportExtras& extras);

/// Writes report.md into `dir` atomically.
void write_report(const std::string& dir, const Scene& scene, const RunRecord& record,
                  const ReportExtras& extras);

}  // namespace rockfdem::workflows
