// PNG plots of a run, tunnel or specimen, from its history and final state
// (docs/output-formats.md, "PNG plots"). Without a display nothing is
// rendered and `skipped` says why, once; a picture that fails later (the
// display went away) is named there too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "outputs/history.hpp"
#include "outputs/monitors.hpp"
#include "outputs/run_pictures.hpp"
#include "outputs/run_timeline.hpp"
#include "record/summary.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

class PlotWriter {
 public:
  /// Asks for a display; without one, notes why in `skipped` (and on
  /// stderr unless `quiet`) and available() is false.
  PlotWriter(std::string dir, RunRecord& summary, bool quiet);
  bool available() const { return available_; }
  /// DIR/`file`: a line plot of `series`, with vertical `markers` and
  /// shaded `bands`.
  void xy(const std::string& file, const std::string& title, const std::string& x_label,
          const std::string& y_label, const std::vector<plots::PlotSeries>& series,
          const std::vector<plots::PlotMarker>& markers = {},
          const std::vector<plots::PlotBand>& bands = {});
  /// DIR/`file`: charts stacked top to bottom (plots::plot_panels_png),
  /// with shaded `bands` behind each.
  void panels(const std::string& file, const std::string& title, const std::string& x_label,
              const std::vector<plots::PlotPanel>& panels, int height,
              const std::vector<plots::PlotBand>& bands = {});
  /// broken.png: broken crack elements by mode against history column
  /// `x` (labelled `x_label`), with the stages' `bands`.
  void broken_cracks(const History& h, const std::string& x, const std::string& x_label,
                     const std::vector<plots::PlotBand>& bands = {});
  /// A specimen's pictures of its final state: final_mesh.png (the mesh
  /// as deformed, broken cracks in red: specimen_mesh_picture) and the
  /// whole model coloured by the most compressive in-plane principal
  /// stress [MPa] (compression positive, sigma_max_compressive.png), or
  /// for a Brazilian disc (`most_tensile`) the most tensile (tension
  /// positive, sigma_max_tensile.png), broken cracks in black.
  void specimen_pictures(const fdem::Engine& e, bool most_tensile);
  /// DIR/`file`: a mesh picture of `grid`.
  void picture(const std::string& file, const coupling::VtkGrid& grid, const plots::MeshPicture& p);
  /// The files rendered so far, in order (report.md links them).
  const std::vector<std::string>& rendered() const { return rendered_; }

 private:
  void note(bool rendered, const std::string& file, const std::string& why);
  std::string dir_;
  std::vector<std::string> rendered_;
  RunRecord& summary_;
  bool available_ = false;
};

/// The time axis' label: pseudo-time when the masses are scaled.
std::string time_axis_label(const fdem::Engine& e);

/// The step axis' label of a tunnel's curves.
constexpr const char* kStepAxis = "explicit step (stages shaded)";

/// A tunnel run's curves against the explicit step, with the stages as
/// bands (`spans`): convergence.png (the key points' radial displacement),
/// chord_convergence.png (the chords' closure), from the in-situ state or,
/// given history row `from` (the support's installation), from that row
/// on less their value there; and broken.png.
void tunnel_curves(PlotWriter& plots, const History& h, const std::vector<Monitor>& monitors,
                   const std::vector<StageSpan>& spans, std::optional<std::size_t> from);

/// ground_reaction.png: the record's ground reaction curves in pressure
/// (implicit, and the Mohr-Coulomb counterpart's), the support's
/// characteristic lines and the run's end point (convergence_confinement).
void ground_reaction_plot(PlotWriter& plots, const RunRecord& r);

/// A tunnel's final state: displacement.png, sigma_max_compressive.png,
/// sigma_min_compressive.png and final_mesh.png (the mesh).
void tunnel_pictures(PlotWriter& plots, const PictureContext& c);

/// A specimen's pictures: stress_strain.png (axial stress of a UCS test,
/// or the Brazilian tensile stress 2P / (pi D) of a disc, against the
/// platens' nominal strain), broken.png, final_mesh.png and the stress
/// picture (PlotWriter::specimen_pictures).
void specimen_plots(const fdem::Engine& e, const History& h, bool disc, const std::string& dir,
                    RunRecord& summary, bool quiet);

}  // namespace rockfdem::workflows
