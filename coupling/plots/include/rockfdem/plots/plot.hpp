// PNG pictures rendered by VTK: line plots (convergence, broken cracks, the
// ground reaction curve) and the mesh coloured by a cell field with cracks
// drawn on top.
//
// VTK renders through an X display (GLX); with none, VTK's offscreen path
// aborts the process. So every function first calls rendering_available()
// and returns false with the reason instead of rendering. Run under
// `xvfb-run -a` on machines without a display.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "rockfdem/coupling/vtk_grid.hpp"

namespace rockfdem::plots {

// The plots draw the hand-off's grids.
using coupling::VtkArray;
using coupling::VtkGrid;
using coupling::VtkKind;

/// True when an X display can be opened and offers GLX, i.e. VTK can render.
/// Checked without VTK (which would abort): DISPLAY must be set, libX11 and
/// libGL are opened with dlopen, XOpenDisplay must succeed and
/// glXQueryExtension must answer yes. Costs one X connection (milliseconds);
/// a failed connection is retried for up to half a second (Xvfb resets after
/// its last client leaves, and refuses connections meanwhile).
/// @param why  if not null, receives the reason when the answer is false.
bool rendering_available(std::string* why = nullptr);

/// One curve of a line plot.
struct PlotSeries {
  std::string name;       ///< legend entry
  std::vector<double> x;  ///< abscissae
  std::vector<double> y;  ///< ordinates, as many as x
  bool points = false;    ///< drawn as marks, not joined (a single state)
};

/// A vertical line across a line plot at abscissa `x`, dashed, with its
/// label written along it at the top (a construction stage, an event).
struct PlotMarker {
  double x = 0;
  std::string label;
};

/// A shaded band across a line plot from x0 to x1 (a construction stage),
/// its label written at its top left; bands next to each other alternate
/// two light shades.
struct PlotBand {
  double x0 = 0, x1 = 0;
  std::string label;
};

/// Line plot with title, axis labels, a legend, `markers` and `bands`
/// (behind the curves), written atomically as PNG of width x height
/// pixels. The x axis spans the series exactly; a marker outside it is not
/// drawn, a band is clipped to it. Labels that would overlap the one
/// before move down a row.
/// @return false (reason in *why) when rendering is not available; nothing written.
/// @throws std::invalid_argument for no series, x/y size mismatch (names the
///         series) or a size below 16 pixels; std::runtime_error naming `path`
///         when it cannot be written.
bool plot_xy_png(const std::string& title, const std::string& x_label, const std::string& y_label,
                 const std::vector<PlotSeries>& series, const std::string& path, int width = 900,
                 int height = 600, std::string* why = nullptr,
                 const std::vector<PlotMarker>& markers = {},
                 const std::vector<PlotBand>& bands = {});

/// One chart of a stacked figure: its y axis label, curves drawn as lines
/// and series drawn as unjoined circles (either list may be empty, not both).
struct PlotPanel {
  std::string y_label;
  std::vector<PlotSeries> lines;
  std::vector<PlotSeries> markers;
};

/// Charts stacked top to bottom in one PNG, each with its own y axis, the
/// shared x axis label under the last, `title` over the first, `bands`
/// shaded behind every chart (labelled on the first); written atomically.
/// @return false (reason in *why) when rendering is not available; nothing written.
/// @throws as plot_xy_png, and std::invalid_argument for no panels.
bool plot_panels_png(const std::string& title, const std::string& x_label,
                     const std::vector<PlotPanel>& panels, const std::string& path, int width = 900,
                     int height = 900, std::string* why = nullptr,
                     const std::vector<PlotBand>& bands = {});

/// A window of the model to draw [m]: x0 < x1, y0 < y1.
struct MeshView {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

struct MeshOverlay;

/// Lines drawn over a mesh picture in one colour (cracks of one mode, the
/// lining's faces, bolts), with an entry in the picture's legend.
struct PictureLines {
  std::string label;                            ///< legend entry; empty: none
  std::array<double, 3> rgb{0, 0, 0};           ///< colour, components in [0, 1]
  double width = 2;                             ///< [pixels]
  std::vector<std::array<double, 4>> segments;  ///< (x0, y0, x1, y1) [m]
};

/// What a mesh picture shows: the grid's triangles (only its points and
/// triangles are used) coloured by `values`, NaN grey, hidden triangles
/// left out (white); `lines` on top in order; a colour bar titled
/// `bar_title` (the quantity and its unit) with round tick values; a legend
/// of the labelled lines. Every mesh picture has axes in metres left of and
/// under the mesh and a scale bar at its lower right.
struct MeshPicture {
  std::string title;
  std::string bar_title;
  std::vector<double> values;  ///< one per triangle, or per point with `per_point`
  bool per_point = false;      ///< values per point, interpolated over each triangle
  bool magnitude = false;      ///< a light-to-dark map from yellow to red (else blue to red)
  bool edges = false;          ///< the triangles' edges drawn (the mesh itself)
  /// Names for the codes in `values` (each code its own colour, named
  /// beside the bar); empty: a colour scale (or the overlay's categories).
  std::vector<std::pair<int, std::string>> categories;
  std::vector<std::uint8_t> hidden;  ///< per triangle, 1: not drawn; empty: all drawn
  std::vector<PictureLines> lines;
  /// The window drawn; the colour scale then spans the drawn triangles
  /// whose centroid lies in it. Without: the whole grid.
  std::optional<MeshView> view;
  /// Bolts and labelled key points drawn on top, and the names of a coded
  /// field's values (each its own colour); null: none.
  const MeshOverlay* overlay = nullptr;
};

/// `picture` of `grid`, written atomically as PNG of width x height pixels.
/// @return false (reason in *why) when rendering is not available; nothing written.
/// @throws std::invalid_argument when `values` or `hidden` do not match the
///         grid; std::runtime_error naming `path`.
bool render_picture_png(const VtkGrid& grid, const MeshPicture& picture, const std::string& path,
                        int width = 1000, int height = 800, std::string* why = nullptr);

/// What a mesh picture draws besides the field: segments (bolts) as thick
/// dark lines, labelled markers (key points), and names for the codes of an
/// integer field (each code its own colour, named in the legend).
struct MeshOverlay {
  struct Segment {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< [m]
  };
  struct Marker {
    double x = 0, y = 0;  ///< [m]
    std::string label;
  };
  std::vector<Segment> segments;  ///< bolts and cables (dark red)
  std::vector<Marker> markers;    ///< key points (blue)
  /// Instruments (green): extensometer lines and labelled monitor points.
  std::vector<Segment> instrument_segments;
  std::vector<Marker> instrument_markers;
  /// Lines of text in a box at the picture's lower left (what the picture
  /// cannot show as geometry: loads, boundary conditions, stages).
  std::vector<std::string> notes;
  std::vector<std::pair<int, std::string>> categories;  ///< code, name; empty: a colour scale
};

/// The grid's triangles coloured by one component of a cell array (with a
/// colour bar titled by the field), its line cells (cracks) drawn in black
/// on top, and a title; written atomically as PNG. `component` indexes the
/// record's tuple (for a stress (xx, yy, xy): 0, 1 or 2); NaN cells are grey.
/// With a `view`, the picture shows that window and the colour scale spans
/// the triangles whose centroid lies in it; without, the whole grid. An
/// `overlay` adds its segments and markers on top.
/// @return false (reason in *why) when rendering is not available; nothing written.
/// @throws std::invalid_argument naming the field when it is missing or the
///         component is out of range; std::runtime_error naming `path`.
bool render_mesh_png(const VtkGrid& grid, const std::string& cell_field, int component,
                     const std::string& path, const std::string& title, int width = 1000,
                     int height = 800, std::string* why = nullptr, const MeshView* view = nullptr,
                     const MeshOverlay* overlay = nullptr);

/// A PNG's pixels as read back (the tests' pixel checks): rgb of column i,
/// row j (from the bottom, as VTK stores them) at 3 (j width + i).
struct PngPixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  /// How many pixels have `colour`, within `tolerance` per channel.
  int count(std::array<int, 3> colour, int tolerance = 3) const;
};

/// Reads the PNG at `path` (needs no display).
/// @throws std::runtime_error naming `path` when it is no readable PNG.
PngPixels read_png_pixels(const std::string& path);

}  // namespace rockfdem::plots
