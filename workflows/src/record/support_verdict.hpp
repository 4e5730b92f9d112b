// Whether the support holds: the lining's capacity check, the bolts' and
// cables' steel and the lining-rock bond, read from the run's figures and
// said in one line beside the equilibrium status (summary.json "support",
// report.md, the console). A run can reach equilibrium on a support that
// would not carry what the model makes it carry; the status must say so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "record/support_figures.hpp"

namespace rockfdem::workflows {

struct SupportVerdict {
  /// "holds", "overstressed", or "not checked" (no support, or no capacity
  /// to check the lining against and no bolt broken).
  std::string verdict;
  /// Each overstressed part, named with its figure and where.
  std::vector<std::string> findings;
  /// What was not checked, and what gave way without being a design
  /// failure (a debonded lining).
  std::vector<std::string> notes;
  /// ": a; b" (the findings), or empty.
  std::string findings_text() const;
  /// "support overstressed: a; b", "support holds", "support not checked".
  std::string line() const;
};

/// The verdict of the lining's and bolts' end-of-run figures; none where
/// the run has neither.
std::optional<SupportVerdict> support_verdict(const LiningRecord& lining,
                                              const std::optional<BoltRecord>& bolts);

}  // namespace rockfdem::workflows
