// Outlines drawn over the pictures of a tunnel: the fracture zone's outer
// edge (damage cannot reach past it, so a capped broken zone shows as
// cracks running along it) and the opening's outline deformed by the
// displacement from the in-situ state, magnified by a stated round factor.
#pragma once

#include <optional>

#include "outputs/material_point.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

/// The fracture zone's outer edge, dashed (dashes of `dash` [m]); no
/// segments where the whole rock can crack.
plots::PictureLines fracture_zone_lines(const mesh::Mesh& m, double dash);

/// The magnification that draws the largest displacement `u_max` as about
/// a tenth of `span`: a round factor (1, 2 or 5 times a power of ten), at
/// least 1.
double outline_magnification(double u_max, double span);

/// The opening's boundary at x + k u (k: outline_magnification of its
/// largest |u| against the opening's width), the factor in the legend;
/// nothing without an opening or where no point moved.
std::optional<plots::PictureLines> deformed_opening(const fdem::Engine& e, const mesh::Mesh& m,
                                                    const NodeDisplacement& u);

/// `segments` cut into dashes of `dash` [m] with gaps as long, the phase
/// running on from one segment to the next.
std::vector<std::array<double, 4>> dashed(const std::vector<std::array<double, 4>>& segments,
                                          double dash);

}  // namespace rockfdem::workflows
