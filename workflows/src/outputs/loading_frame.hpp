// Key points read as a model loaded from zero stress reads them. rockfdem
// starts from the in-situ state: its displacements are what the excavation
// adds. Many FDEM tunnel models instead start from the unloaded mesh, load
// the outer boundary with the in-situ stresses on a fixed base and report
// displacement from the unloaded mesh; their figures carry the box's own
// compression under the in-situ stress, which moves the crown down and the
// floor up less. To compare with such figures like for like, this adds that
// compression to a displacement of ours: the uniform elastic strain of the
// intact box under (sigma_h, sigma_v), its base held vertically and its
// vertical centre line horizontally.
#pragma once

#include <array>
#include <optional>

#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The intact box's strain under the in-situ stress, compression positive.
struct LoadingStrain {
  double xx = 0, yy = 0;
  double base_y = 0, centre_x = 0;  ///< the held base and centre line [m]
};

/// From the rock's E and nu (plane strain unless the scene is plane
/// stress) and insitu.sigma_h, sigma_v. None where the loading is not a
/// uniform stress on a box: no in-situ stress, a rotated one, a unit
/// weight or gravity.
std::optional<LoadingStrain> loading_strain(const Scene& s);

/// The box's displacement at (x, y) [m] under the loading (base and
/// centre line held): (-xx (x - centre_x), -yy (y - base_y)).
std::array<double, 2> loading_displacement(const LoadingStrain& e, double x, double y);

}  // namespace rockfdem::workflows
