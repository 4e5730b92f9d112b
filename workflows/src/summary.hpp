// summary.json: the fixed keys of product.md, filled as a run goes and
// written atomically at the end (and after each stage, so an interrupted
// run still leaves a valid record).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "phase_timer.hpp"

namespace rockfdem::workflows {

struct Scene;

class RunSummary {
 public:
  RunSummary(const Scene& scene, int threads);
  nlohmann::json& json() { return root_; }
  void skipped(const std::string& what_and_why);
  void set_timings(const PhaseTimer& timer);
  void write(const std::string& path) const;

 private:
  nlohmann::json root_;
};

}  // namespace rockfdem::workflows
