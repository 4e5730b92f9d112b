// PNG plots of a run, tunnel or specimen, from its history and final state
// (docs/output-formats.md, "PNG plots"). Without a display nothing is
// rendered and `skipped` says why, once; a picture that fails later (the
// display went away) is named there too.
#pragma once

#include <string>
#include <vector>

#include "history.hpp"
#include "rockfdem/coupling/plot.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "summary.hpp"

namespace rockfdem::workflows {

class PlotWriter {
 public:
  /// Asks for a display; without one, notes why in `skipped` (and on
  /// stderr unless `quiet`) and available() is false.
  PlotWriter(std::string dir, RunSummary& summary, bool quiet);
  bool available() const { return available_; }
  /// DIR/`file`: a line plot of `series`.
  void xy(const std::string& file, const std::string& title, const std::string& x_label,
          const std::string& y_label, const std::vector<coupling::PlotSeries>& series);
  /// DIR/`file`: charts stacked top to bottom (coupling::plot_panels_png).
  void panels(const std::string& file, const std::string& title, const std::string& x_label,
              const std::vector<coupling::PlotPanel>& panels, int height);
  /// broken.png: broken crack elements by mode against (pseudo-)time.
  void broken_cracks(const fdem::Engine& e, const History& h);
  /// final_mesh.png: the triangles coloured by principal stress `principal`
  /// (0: major, the most tensile; 1: minor), broken cracks in black,
  /// excavated triangles grey. `implicit`: the implicit displacement to add.
  void final_mesh(const fdem::Engine& e, const mesh::Mesh& m, const insitu::InsituField* implicit,
                  int principal, const std::string& title);
  /// broken_zone.png: the same picture in the window `view` (around the
  /// opening and its fracture zone), where the crack pattern can be seen.
  void broken_zone(const fdem::Engine& e, const mesh::Mesh& m, const insitu::InsituField* implicit,
                   const coupling::MeshView& view);

 private:
  void note(bool rendered, const std::string& file, const std::string& why);
  std::string dir_;
  RunSummary& summary_;
  bool available_ = false;
};

/// The time axis' label: pseudo-time when the masses are scaled.
std::string time_axis_label(const fdem::Engine& e);

/// A specimen's pictures: stress_strain.png (axial stress of a UCS test,
/// or the Brazilian tensile stress 2P / (pi D) of a disc, against the
/// platens' nominal strain), broken.png and final_mesh.png.
void specimen_plots(const fdem::Engine& e, const mesh::Mesh& m, const History& h, bool disc,
                    const std::string& dir, RunSummary& summary, bool quiet);

}  // namespace rockfdem::workflows
