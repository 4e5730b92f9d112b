// support_forces.png: the support's forces drawn on the geometry, as an
// engineer draws them on a cross-section (docs/workflow.md, "Pictures"):
//
//            rock                        bolt (axis a, normal b = a turned
//     ~~~~~~~~~~~~~~~~~~ lining            +90 deg): tension drawn to the b
//      |  |  |  |  |  |  ring              side in red, compression to the
//      +--+--+--+--+--+  thrust N,         other side in blue
//         opening        drawn inward
//
// Each diagram is an ordinate per point of the member (a ring segment's
// mid-line point, a bolt's station), offset from the member along its
// normal by value / scale, closed by hatching from the member to the
// ordinate; the scale (a round value per metre drawn) is stated in the
// picture's notes box. The lining's thrust N (compression positive) and moment M are
// drawn on the opening's side for N > 0 and M > 0 (the opening's face in
// tension: the moment on its tension side), else on the rock's.
#pragma once

#include <string>
#include <vector>

#include "outputs/lining_forces.hpp"
#include "outputs/run_pictures.hpp"
#include "outputs/run_plots.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

/// One ordinate of a force diagram.
struct DiagramPoint {
  double x = 0, y = 0;    ///< the member's point [m]
  double nx = 0, ny = 0;  ///< unit normal the ordinate is drawn along (positive values)
  double value = 0;       ///< in the diagram's unit (kN/m, kNm/m, kN per bar)
};

/// The value per metre drawn that draws `max_abs` as at most `length` [m]
/// and at least 0.4 of it: a round value (1, 2 or 5 times a power of ten);
/// 1 when there is nothing to draw.
double diagram_scale(double max_abs, double length);

/// The diagram's ordinate points (x + n value / scale) joined in order
/// (`closed`: the last back to the first, a ring) and the hatching from
/// each member point to its ordinate, into `positive` (values >= 0) and
/// `negative` by the sign of each piece (an outline piece by its two
/// ends' mean).
void diagram_lines(const std::vector<DiagramPoint>& points, double scale, bool closed,
                   plots::PictureLines& positive, plots::PictureLines& negative);

/// The ring's diagrams of N [kN/m] or (`moment`) M [kNm/m] from forces
/// `f` of `g`'s segments, both along the inward normal (N > 0:
/// compression towards the opening; M > 0: the opening's face in tension,
/// the moment on its tension side): one run of points between the ring's
/// corner segments (no beam section there, left out), a run through
/// segment 0 joined to the one before it.
std::vector<std::vector<DiagramPoint>> lining_diagram(const LiningGeometry& g,
                                                      const std::vector<SectionForces>& f,
                                                      bool moment);

/// Installed bolt b's axial force [kN per bar, tension +] at its stations,
/// placed on the bar's axis as built at their distances from the head,
/// along the bar's normal b (the axis head to end turned +90 deg).
std::vector<DiagramPoint> bolt_diagram(const PictureContext& c, std::size_t b);

/// support_forces.png: the model in light colours (rock, lining, bolts;
/// the opening white) in the opening's window, the ring's N and M diagrams
/// (`ring`, `forces`: the lining's at the end; null: no ring installed)
/// and every installed bolt's and cable's axial force diagram, each with
/// its sign in the legend, the diagrams' scales in the notes box, and the
/// extremes labelled in `labels` (which the picture points to).
plots::MeshPicture support_forces_picture(const PictureContext& c, const LiningGeometry* ring,
                                          const std::vector<SectionForces>* forces,
                                          plots::MeshOverlay& labels);

/// support_forces.png (support_forces_picture) when a ring's forces or an
/// installed bolt are there to draw.
void support_forces_plot(PlotWriter& plots, const PictureContext& c, const LiningGeometry* ring,
                         const std::vector<SectionForces>* forces);

}  // namespace rockfdem::workflows
