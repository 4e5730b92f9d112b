#include "run/summary.hpp"

#include <algorithm>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/version.hpp"

namespace rockfdem::workflows {
namespace {

// (a0, b0, a1, b1, ...): the engine's layout, so the hashes read alike.
std::vector<double> interleave(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(2 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[2 * i] = a[i];
    out[2 * i + 1] = b[i];
  }
  return out;
}

// "fdem setup" -> "fdem_setup": a phase's name as a JSON key.
std::string snake_case(std::string name) {
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}

// {"checkpoint" or "last": path, "step": step}.
nlohmann::json mark_json(const char* path_key, const CheckpointMark& m) {
  return {{path_key, m.path}, {"step", m.step}};
}

}  // namespace

RunRecord::RunRecord(const Scene& scene, int threads)
    : warnings(scene.warnings),
      timings_{{"mesh", 0.0}, {"insitu", 0.0}, {"fdem", 0.0}, {"output", 0.0}, {"total", 0.0}} {
  using nlohmann::json;
  figures_ = {{"format_version", kSummaryFormatVersion},
              {"rockfdem_version", version_string()},
              {"scene", scene.source},
              {"overrides", scene.overrides},
              {"title", scene.title},
              {"threads", threads},
              {"counts",
               {{"triangles", 0},
                {"nodes", 0},
                {"crack_elements", 0},
                {"bolts", scene.bolts.segments.size()}}},
              {"steps", 0},
              {"dt", 0.0},
              {"simulated_time", 0.0},
              {"throughput", {{"triangle_steps_per_second", 0.0}}},
              {"broken", {{"mode_I", 0}, {"mode_II", 0}, {"mixed", 0}}},
              {"monitors", json::object()},
              {"insitu",
               {{"alpha", json::array()},
                {"kirsch_rel_l2", nullptr},
                {"solver_iterations", json::array()}}},
              {"state_hash", ""}};
}

void RunRecord::note_turned_off(const OutputSettings& output, const std::string& paraview_files,
                                bool renders_plots) {
  if (!output.vtk) skipped.push_back("ParaView files (" + paraview_files + "): output.vtk = false");
  if (renders_plots && !output.plots) skipped.push_back("plots: output.plots = false");
}

void RunRecord::record_mesh(const mesh::Mesh& m, const mesh::MeshReport& report) {
  figures_["counts"]["triangles"] = m.n_triangles();
  figures_["counts"]["nodes"] = m.n_vertices();
  figures_["mesh"] = {{"triangles", report.n_triangles},
                      {"vertices", report.n_vertices},
                      {"min_altitude", report.min_altitude},
                      {"min_angle_deg", report.min_angle_deg},
                      {"seconds", report.seconds}};
  figures_["state_hash"] = fdem::bits_hash(interleave(m.x, m.y));
}

void RunRecord::record_insitu_state(const insitu::InsituField& field) {
  figures_["state_hash"] = fdem::bits_hash(interleave(field.ux, field.uy));
}

void RunRecord::set_timings(const PhaseTimer& timer) {
  for (const std::string& phase : timer.order()) timings_[snake_case(phase)] = timer.seconds(phase);
  timings_["total"] = timer.total();
}

nlohmann::json RunRecord::to_json() const {
  nlohmann::json j = figures_;
  if (!status.empty()) j["status"] = status;
  if (status_reason) j["status_reason"] = *status_reason;
  if (failure) j["failure"] = *failure;
  if (!warnings.empty()) j["warnings"] = warnings;
  j["skipped"] = skipped;
  if (restarted_from) j["restarted_from"] = mark_json("checkpoint", *restarted_from);
  if (checkpoint) j["checkpoint"] = mark_json("last", *checkpoint);
  j["timings"] = timings_;
  return j;
}

void RunRecord::write(const std::string& path) const {
  coupling::atomic_write_text(path, to_json().dump(2) + "\n");
}

}  // namespace rockfdem::workflows
