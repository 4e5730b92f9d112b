// The ground reaction curve in pressure (convergence-confinement, Carranza-
// Torres and Fairhurst 2000): at each implicit solve, the pressure the
// softened core exerts on the opening at a key point against the key
// point's radial displacement. The core's factor alpha scales its whole
// stress, so alpha is not p/p0; the pressure is read from the core's
// stress itself: p = -n.sigma.n over the core triangles at the point
// (sigma tension positive, n the unit normal), compression positive.
#pragma once

#include <optional>
#include <vector>

#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The mean of -n.sigma.n [Pa, compression positive] over the active core
/// triangles of `f` that have `vertex` as a corner, those of a lining ring
/// not yet installed included (softened with the core); none when no such
/// triangle has it (the core removed: no pressure).
std::optional<double> core_pressure(const mesh::Mesh& m, const insitu::InsituField& f, int vertex,
                                    double nx, double ny);

/// The in-situ normal stress [Pa, compression positive] on a plane of unit
/// normal (nx, ny): sigma_h along its angle, sigma_v across it (no gravity).
double insitu_normal_stress(const InsituSettings& s, double nx, double ny);

}  // namespace rockfdem::workflows
