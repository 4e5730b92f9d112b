// Private to the plot sources: what a mesh picture draws over its field
// (bolts, labelled key points) and the colours of a coded field.
#pragma once

#include <vtkActor.h>
#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "rockfdem/plots/plot.hpp"

namespace rockfdem::plots {

/// One colour per code, named in the colour bar (an indexed lookup table).
vtkSmartPointer<vtkLookupTable> category_colours(
    const std::vector<std::pair<int, std::string>>& categories);

/// Adds the overlay's segments and markers (with their labels) to
/// `renderer`, `lift` towards the camera so they are drawn on top.
void add_overlay(vtkRenderer* renderer, const MeshOverlay& overlay, double lift);

}  // namespace rockfdem::plots
