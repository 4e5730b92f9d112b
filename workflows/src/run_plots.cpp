#include "run_plots.hpp"

#include <cmath>
#include <iostream>

#include "output_dir.hpp"
#include "rockfdem/coupling/fdem_model.hpp"

namespace rockfdem::workflows {
namespace {

// The picture of the final state shows broken cracks only: intact crack
// elements lie on every edge of the fracture zone and would hide the mesh.
coupling::VtkGrid broken_crack_grid(const fdem::Engine& e, const mesh::Mesh& m,
                                    const insitu::InsituField* implicit) {
  coupling::VtkGrid g = coupling::fdem_grid(e, m, implicit);
  std::vector<std::array<int, 2>> lines;
  for (std::size_t c = 0; c < e.n_cracks(); ++c)
    if (e.crack_state(c) == fdem::CrackState::kBroken) lines.push_back(g.lines[c]);
  const std::size_t n_tri = g.n_triangles();
  g.lines = lines;
  for (coupling::VtkArray& a : g.cell_arrays) {
    if (a.is_int()) {
      auto& v = std::get<std::vector<std::int32_t>>(a.values);
      v.resize(n_tri * a.n_components);
    } else {
      auto& v = std::get<std::vector<double>>(a.values);
      v.resize(n_tri * a.n_components);
    }
    a = coupling::triangle_cell_array(g, std::move(a));
  }
  // Excavated triangles are drawn grey (NaN), not as stress-free rock.
  for (coupling::VtkArray& a : g.cell_arrays) {
    if (a.is_int()) continue;
    auto& v = std::get<std::vector<double>>(a.values);
    for (std::size_t t = 0; t < n_tri; ++t)
      if (!e.active(t))
        for (int k = 0; k < a.n_components; ++k) v[t * a.n_components + k] = std::nan("");
  }
  return g;
}

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

}  // namespace

PlotWriter::PlotWriter(std::string dir, RunSummary& summary, bool quiet)
    : dir_(std::move(dir)), summary_(summary) {
  std::string why;  // ends with the advice to run under xvfb-run
  available_ = coupling::rendering_available(&why);
  if (available_) return;
  summary_.skipped("plots: " + why);
  if (!quiet) std::cerr << "rockfdem: plots skipped: " << why << '\n';
}

void PlotWriter::note(bool rendered, const std::string& file, const std::string& why) {
  if (!rendered) summary_.skipped("plot " + file + ": " + why);
}

void PlotWriter::xy(const std::string& file, const std::string& title, const std::string& x_label,
                    const std::string& y_label, const std::vector<coupling::PlotSeries>& series) {
  std::string why;
  note(coupling::plot_xy_png(title, x_label, y_label, series, output_path(dir_, file), 900, 600,
                             &why),
       file, why);
}

void PlotWriter::panels(const std::string& file, const std::string& title,
                        const std::string& x_label, const std::vector<coupling::PlotPanel>& panels,
                        int height) {
  std::string why;
  note(
      coupling::plot_panels_png(title, x_label, panels, output_path(dir_, file), 900, height, &why),
      file, why);
}

void PlotWriter::broken_cracks(const fdem::Engine& e, const History& h) {
  const std::vector<double> t = h.column("time");
  xy("broken.png", "Broken crack elements", time_axis_label(e), "count",
     {{"mode I", t, h.column("broken_I")},
      {"mode II", t, h.column("broken_II")},
      {"mixed", t, h.column("broken_mixed")}});
}

void PlotWriter::final_mesh(const fdem::Engine& e, const mesh::Mesh& m,
                            const insitu::InsituField* implicit, int principal,
                            const std::string& title) {
  std::string why;
  note(coupling::render_mesh_png(broken_crack_grid(e, m, implicit), "principal_stress", principal,
                                 output_path(dir_, "final_mesh.png"), title, 1000, 800, &why),
       "final_mesh.png", why);
}

void PlotWriter::broken_zone(const fdem::Engine& e, const mesh::Mesh& m,
                             const insitu::InsituField* implicit, const coupling::MeshView& view) {
  std::string why;
  note(coupling::render_mesh_png(broken_crack_grid(e, m, implicit), "principal_stress", 1,
                                 output_path(dir_, "broken_zone.png"),
                                 "Around the opening: most compressive principal stress [Pa], "
                                 "broken cracks in black",
                                 1000, 800, &why, &view),
       "broken_zone.png", why);
}

std::string time_axis_label(const fdem::Engine& e) {
  // Scaled masses make the simulated time a pseudo-time: say so on the axis.
  return e.mass_scaling_report().enabled ? "pseudo-time [s] (mass-scaled)" : "time [s]";
}

void specimen_plots(const fdem::Engine& e, const mesh::Mesh& m, const History& h, bool disc,
                    const std::string& dir, RunSummary& summary, bool quiet) {
  PlotWriter plots(dir, summary, quiet);
  if (!plots.available()) return;
  const char* stress = disc ? "tensile_stress" : "axial_stress";
  plots.xy("stress_strain.png", disc ? "Brazilian test: tensile stress 2P/(pi D)" : "UCS test",
           "nominal axial strain (platen closure / length)",
           disc ? "tensile stress [MPa]" : "axial stress [MPa]",
           {{disc ? "tensile stress" : "axial stress", h.column("axial_strain"),
             scaled(h.column(stress), 1e-6)}});
  plots.broken_cracks(e, h);
  // A disc splits in tension (the major principal stress), a UCS specimen
  // is crushed (the minor).
  plots.final_mesh(e, m, nullptr, disc ? 0 : 1,
                   disc ? "Major principal stress [Pa], broken cracks in black"
                        : "Minor principal stress [Pa], broken cracks in black");
}

}  // namespace rockfdem::workflows
