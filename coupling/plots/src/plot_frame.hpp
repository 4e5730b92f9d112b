// The frame of a mesh picture: axes in metres left of and under the mesh,
// with round ticks, and a scale bar on the mesh (docs/workflow.md,
// "Pictures"). The mesh's camera is parallel and looks straight down z, so
// where a coordinate falls in the window is known without asking VTK.
#pragma once

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <string>

#include "rockfdem/plots/plot.hpp"

namespace rockfdem::plots {

/// Where the mesh's viewport lies in the window (normalised, [0, 1]) and the
/// window of the model it shows [m].
struct Frame {
  double left = 0, bottom = 0, right = 1, top = 1;
  MeshView shown;
  int width = 0, height = 0;  ///< the window [px]
};

/// The model window a parallel camera of half-height `parallel_scale`
/// centred on (cx, cy) shows in the frame's viewport.
MeshView shown_window(const Frame& f, double cx, double cy, double parallel_scale);

/// Renderers for the strips left of the mesh and across the window's foot:
/// ticks (one round step on both axes), tick values and the axis titles
/// "x [m]", "y [m]".
void add_axes(vtkRenderWindow* window, const Frame& f);

/// A box around the mesh's viewport and a scale bar (a round length about
/// a fifth of the width shown) at its lower right, on white.
void add_scale_bar(vtkRenderer* mesh, const Frame& f);

/// A 2D line from (x0, y0) to (x1, y1) in the renderer's normalised
/// viewport coordinates.
void add_line_2d(vtkRenderer* r, double x0, double y0, double x1, double y1, const double* rgb,
                 double width);

}  // namespace rockfdem::plots
