#include "commands/mesh_preview.hpp"

#include <algorithm>
#include <iostream>
#include <optional>

#include "rockfdem/coupling/mesh_grid.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/mesh/opening.hpp"
#include "rockfdem/plots/plot.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "run/output_dir.hpp"

namespace rockfdem::workflows {
namespace {

constexpr int kFractureZone = 4;  // the region code of rock with crack elements

// Per triangle: its zone, with the rock that may crack told apart.
std::vector<double> regions(const mesh::Mesh& m, std::vector<std::pair<int, std::string>>& used) {
  const std::pair<int, std::string> names[] = {{mesh::kRock, mesh::zone_name(mesh::kRock)},
                                               {kFractureZone, "fracture zone"},
                                               {mesh::kCore, mesh::zone_name(mesh::kCore)},
                                               {mesh::kLining, mesh::zone_name(mesh::kLining)}};
  std::vector<double> out(m.n_triangles());
  std::vector<bool> present(kFractureZone + 1, false);
  for (std::size_t t = 0; t < out.size(); ++t) {
    const int code = m.zone[t] == mesh::kRock && m.fracture[t] ? kFractureZone : m.zone[t];
    out[t] = code;
    if (code >= 0 && code <= kFractureZone) present[code] = true;
  }
  for (const auto& n : names)
    if (present[n.first]) used.push_back(n);
  return out;
}

// One span beyond the opening on each side, widened to hold every bolt.
plots::MeshView window(const mesh::OpeningBoundary& b, const Scene& scene) {
  const double span = std::max(b.xmax - b.xmin, b.ymax - b.ymin);
  plots::MeshView v{b.xmin - span, b.xmax + span, b.ymin - span, b.ymax + span};
  for (const auto& s : scene.bolts.segments)
    for (int k = 0; k < 4; k += 2) {
      v.x0 = std::min(v.x0, s[k] - 1.0), v.x1 = std::max(v.x1, s[k] + 1.0);
      v.y0 = std::min(v.y0, s[k + 1] - 1.0), v.y1 = std::max(v.y1, s[k + 1] + 1.0);
    }
  return v;
}

}  // namespace

void write_mesh_preview(const Scene& scene, const mesh::Mesh& m, const std::string& dir,
                        RunRecord& summary, bool quiet) {
  coupling::VtkGrid grid = coupling::mesh_grid(m);
  plots::MeshOverlay overlay;
  grid.cell_arrays.push_back(coupling::triangle_cell_array(
      grid, coupling::scalar_array("region", regions(m, overlay.categories))));
  for (const auto& s : scene.bolts.segments) overlay.segments.push_back({s[0], s[1], s[2], s[3]});
  std::optional<plots::MeshView> view;
  if (const auto opening = mesh::find_opening(m)) {
    const bool shaped = scene.mesh.kind == mesh::ModelKind::kTunnel;
    for (const mesh::KeyPoint& p :
         mesh::opening_key_points(m, *opening, shaped ? &scene.mesh.tunnel : nullptr))
      overlay.markers.push_back({p.x, p.y, p.name});
    view = window(*opening, scene);
  }
  std::string why;
  const bool drawn =
      plots::render_mesh_png(grid, "region", 0, output_path(dir, "preview.png"),
                             "Preview: regions, bolts and cables (dark red), key points (blue)",
                             1000, 800, &why, view ? &*view : nullptr, &overlay);
  if (drawn) return;
  summary.skipped.push_back("plot preview.png: " + why);
  if (!quiet) std::cerr << "rockfdem: preview.png skipped: " << why << '\n';
}

}  // namespace rockfdem::workflows
