#include "commands/mesh_preview.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "record/output_dir.hpp"
#include "rockfdem/coupling/mesh_grid.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/mesh/opening.hpp"
#include "rockfdem/plots/plot.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "scene/stage_kind.hpp"

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

// %g of a value in a unit (MPa from Pa: factor 1e-6).
std::string num(double v, double factor = 1) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v * factor);
  return text;
}

// The scene's monitors (labelled points) and extensometers (head to the
// deepest anchor, from a key point along its outward normal or as given).
void add_instruments(const Scene& scene, const std::vector<mesh::KeyPoint>& key_points,
                     plots::MeshOverlay& overlay) {
  for (const MonitorSpec& m : scene.monitors)
    overlay.instrument_markers.push_back({m.x, m.y, m.name});
  for (const ExtensometerSpec& x : scene.extensometers) {
    double hx = x.head_x, hy = x.head_y, dx = x.dir_x, dy = x.dir_y;
    if (!x.from.empty()) {
      const std::string from = x.from == "crown" ? "vault" : x.from;
      const auto k = std::find_if(key_points.begin(), key_points.end(),
                                  [&](const mesh::KeyPoint& p) { return p.name == from; });
      if (k == key_points.end()) continue;
      hx = k->x, hy = k->y, dx = -k->inward_x, dy = -k->inward_y;
    }
    overlay.instrument_segments.push_back({hx, hy, hx + x.length * dx, hy + x.length * dy});
    overlay.instrument_markers.push_back({hx + x.length * dx, hy + x.length * dy, x.name});
  }
}

// A stage as the notes list it: its number, kind and what bounds it.
std::string stage_note(int number, const StageSpec& st) {
  std::string t = std::to_string(number) + " " + st.kind;
  const std::string own = stage_kind(st.kind).note(st);
  if (!own.empty()) t += " " + own;
  if (st.max_steps > 0) t += " (at most " + std::to_string(st.max_steps) + " steps)";
  return t;
}

// What the picture cannot draw: the box's loads and supports, the in-situ
// stress and the stages, numbered as the run's outputs number them.
std::vector<std::string> tunnel_notes(const Scene& scene) {
  const InsituSettings& in = scene.insitu;
  std::vector<std::string> notes;
  notes.push_back((scene.mesh.kind == mesh::ModelKind::kTunnel
                       ? "Box " + num(scene.mesh.domain.width) + " x " +
                             num(scene.mesh.domain.height) + " m (beyond the picture): "
                       : std::string("Outer boundary: ")) +
                  "in-situ tractions in the implicit stage,");
  notes.push_back(std::string("  ") +
                  (in.rollers ? "rollers at the hand-off's normal displacement"
                              : "the in-situ tractions alone") +
                  " in the explicit stages");
  std::string stress = "In-situ stress (compression): sigma_H " + num(in.sigma_h, 1e-6) +
                       " MPa, sigma_v " + num(in.sigma_v, 1e-6) + " MPa";
  if (in.angle_deg != 0) stress += ", sigma_H at " + num(in.angle_deg) + " deg from x";
  if (in.unit_weight > 0) stress += ", unit weight " + num(in.unit_weight, 1e-3) + " kN/m^3";
  if (scene.engine.gravity > 0) stress += "; gravity " + num(scene.engine.gravity) + " m/s^2";
  notes.push_back(stress);
  std::string alphas;
  for (double a : in.alpha) alphas += (alphas.empty() ? "" : ", ") + num(a);
  std::string line = "Stages: 0 insitu (alpha " + alphas + ")";
  constexpr std::size_t kListed = 12;  // a long list is summarised
  for (std::size_t i = 0; i < scene.stages.size() && i < kListed; ++i) {
    const std::string next = stage_note(int(i) + 1, scene.stages[i]);
    if (line.size() + next.size() > 90)
      notes.push_back(line + ","), line = "  ";
    else
      line += ", ";
    line += next;
  }
  if (scene.stages.size() > kListed)
    line += " and " + std::to_string(scene.stages.size() - kListed) + " more";
  notes.push_back(line);
  return notes;
}

}  // namespace

void write_mesh_preview(const Scene& scene, const mesh::Mesh& m, const std::string& dir,
                        RunRecord& summary, bool quiet) {
  const coupling::VtkGrid grid = coupling::mesh_grid(m);
  plots::MeshOverlay overlay;
  plots::MeshPicture p;
  p.values = regions(m, overlay.categories);
  p.bar_title = "region";
  p.overlay = &overlay;
  for (const auto& s : scene.bolts.segments) overlay.segments.push_back({s[0], s[1], s[2], s[3]});
  if (const auto opening = mesh::find_opening(m)) {
    const bool shaped = scene.mesh.kind == mesh::ModelKind::kTunnel;
    const std::vector<mesh::KeyPoint> key_points =
        mesh::opening_key_points(m, *opening, shaped ? &scene.mesh.tunnel : nullptr);
    for (const mesh::KeyPoint& k : key_points) overlay.markers.push_back({k.x, k.y, k.name});
    add_instruments(scene, key_points, overlay);
    overlay.notes = tunnel_notes(scene);
    p.view = window(*opening, scene);
  }
  // The tagged edges in black; the joint traces as meshed, in the purple
  // the run's pictures draw joints in (their state there).
  plots::PictureLines tagged{"", {0, 0, 0}, 2, {}};
  for (const auto& l : grid.lines)
    tagged.segments.push_back({grid.x[l[0]], grid.y[l[0]], grid.x[l[1]], grid.y[l[1]]});
  p.lines.push_back(std::move(tagged));
  if (!m.joint_edges.empty()) {
    plots::PictureLines joints{"joint traces", {0.45, 0.0, 0.7}, 2, {}};
    for (const mesh::JointEdge& j : m.joint_edges)
      joints.segments.push_back({m.x[j.a], m.y[j.a], m.x[j.b], m.y[j.b]});
    p.lines.push_back(std::move(joints));
  }
  p.title = std::string("Preview: regions, bolts and cables (dark red), key points (blue), ") +
            (m.joint_edges.empty() ? "instruments (green)" : "instruments (green), joints");
  std::string why;
  const bool drawn =
      plots::render_picture_png(grid, p, output_path(dir, "preview.png"), 1000, 800, &why);
  if (drawn) return;
  summary.skipped.push_back("plot preview.png: " + why);
  if (!quiet) std::cerr << "rockfdem: preview.png skipped: " << why << '\n';
}

}  // namespace rockfdem::workflows
