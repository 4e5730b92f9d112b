#include "summary.hpp"

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

}  // namespace

RunSummary::RunSummary(const Scene& scene, int threads) {
  using nlohmann::json;
  root_ = {
      {"format_version", kSummaryFormatVersion},
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
      {"timings", {{"mesh", 0.0}, {"insitu", 0.0}, {"fdem", 0.0}, {"output", 0.0}, {"total", 0.0}}},
      {"throughput", {{"triangle_steps_per_second", 0.0}}},
      {"skipped", json::array()},
      {"broken", {{"mode_I", 0}, {"mode_II", 0}, {"mixed", 0}}},
      {"monitors", json::object()},
      {"insitu",
       {{"alpha", json::array()},
        {"kirsch_rel_l2", nullptr},
        {"solver_iterations", json::array()}}},
      {"state_hash", ""}};
  for (const std::string& w : scene.warnings) root_["warnings"].push_back(w);
}

void RunSummary::skipped(const std::string& what_and_why) {
  root_["skipped"].push_back(what_and_why);
}

void RunSummary::note_turned_off(const OutputSettings& output, const std::string& paraview_files,
                                 bool renders_plots) {
  if (!output.vtk) skipped("ParaView files (" + paraview_files + "): output.vtk = false");
  if (renders_plots && !output.plots) skipped("plots: output.plots = false");
}

void RunSummary::record_mesh(const mesh::Mesh& m, const mesh::MeshReport& report) {
  root_["counts"]["triangles"] = m.n_triangles();
  root_["counts"]["nodes"] = m.n_vertices();
  root_["mesh"] = {{"triangles", report.n_triangles},
                   {"vertices", report.n_vertices},
                   {"min_altitude", report.min_altitude},
                   {"min_angle_deg", report.min_angle_deg},
                   {"seconds", report.seconds}};
  root_["state_hash"] = fdem::bits_hash(interleave(m.x, m.y));
}

void RunSummary::record_insitu_state(const insitu::InsituField& field) {
  root_["state_hash"] = fdem::bits_hash(interleave(field.ux, field.uy));
}

void RunSummary::set_timings(const PhaseTimer& timer) {
  for (const std::string& phase : timer.order())
    root_["timings"][snake_case(phase)] = timer.seconds(phase);
  root_["timings"]["total"] = timer.total();
}

void RunSummary::write(const std::string& path) const {
  coupling::atomic_write_text(path, root_.dump(2) + "\n");
}

}  // namespace rockfdem::workflows
