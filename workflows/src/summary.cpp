#include "summary.hpp"

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/version.hpp"

namespace rockfdem::workflows {

RunSummary::RunSummary(const Scene& scene, int threads) {
  using nlohmann::json;
  root_ = {{"rockfdem_version", version_string()},
           {"scene", scene.source},
           {"title", scene.title},
           {"threads", threads},
           {"counts", {{"triangles", 0}, {"nodes", 0}, {"crack_elements", 0}, {"bolts", 0}}},
           {"steps", 0},
           {"dt", 0.0},
           {"simulated_time", 0.0},
           {"timings", {{"mesh", 0.0}, {"insitu", 0.0}, {"fdem", 0.0}, {"output", 0.0},
                        {"total", 0.0}}},
           {"throughput", {{"triangle_steps_per_second", 0.0}}},
           {"skipped", json::array()},
           {"broken", {{"mode_I", 0}, {"mode_II", 0}, {"mixed", 0}}},
           {"monitors", json::object()},
           {"insitu", {{"alpha", json::array()}, {"kirsch_rel_l2", nullptr},
                       {"solver_iterations", json::array()}}},
           {"state_hash", ""}};
}

void RunSummary::skipped(const std::string& what_and_why) {
  root_["skipped"].push_back(what_and_why);
}

void RunSummary::set_timings(const PhaseTimer& timer) {
  for (const std::string& phase : timer.order()) root_["timings"][phase] = timer.seconds(phase);
  root_["timings"]["total"] = timer.total();
}

void RunSummary::write(const std::string& path) const {
  coupling::atomic_write_text(path, root_.dump(2) + "\n");
}

}  // namespace rockfdem::workflows
