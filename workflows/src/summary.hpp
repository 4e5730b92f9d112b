// summary.json: the fixed keys (docs/output-formats.md), filled as a run
// goes and written atomically at the end, and where a run stops early (a
// failure or a signal), so every run leaves a valid record.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "phase_timer.hpp"

namespace rockfdem::mesh {
struct Mesh;
struct MeshReport;
}  // namespace rockfdem::mesh
namespace rockfdem::insitu {
struct InsituField;
}

namespace rockfdem::workflows {

struct Scene;
struct OutputSettings;

/// summary.json's "format_version": raised whenever a key is renamed,
/// removed or changes meaning (docs/output-formats.md lists the changes).
constexpr int kSummaryFormatVersion = 2;

class RunSummary {
 public:
  /// The fixed keys, with counts.bolts the scene's bolts and cables.
  RunSummary(const Scene& scene, int threads);
  nlohmann::json& json() { return root_; }
  void skipped(const std::string& what_and_why);
  /// Notes in `skipped` the outputs the scene turned off: `paraview_files`
  /// (what output.vtk = false leaves out) and, where the command renders
  /// any, the plots.
  void note_turned_off(const OutputSettings& output, const std::string& paraview_files,
                       bool renders_plots);
  /// counts (triangles; the mesh's vertices as nodes), "mesh" (sizes and
  /// quality) and the state hash of the mesh: its vertex coordinates' bits.
  /// A later stage's figures replace counts and hash.
  void record_mesh(const mesh::Mesh& m, const mesh::MeshReport& report);
  /// The state hash of an implicit result: the bits of its displacement
  /// field (ux, uy per vertex), which the coordinates' bits would blur.
  void record_insitu_state(const insitu::InsituField& field);
  void set_timings(const PhaseTimer& timer);
  void write(const std::string& path) const;

 private:
  nlohmann::json root_;
};

}  // namespace rockfdem::workflows
