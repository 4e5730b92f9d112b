// continuum_yield.png: where the Mohr-Coulomb counterpart of a tunnel run
// flowed plastically, framed as the run's pictures (around the opening,
// axes in metres), with the fracture zone's edge: the FDEM model can crack
// only inside it, so a yielded zone reaching past it is a zone too small.
#pragma once

#include <cstdint>
#include <vector>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/plots/plot.hpp"

namespace rockfdem::workflows {

/// The picture of `yielded` (per triangle, 1: flowed) on mesh `m`'s rock,
/// the triangles not `active` at the end (excavated) left out.
plots::MeshPicture yield_picture(const mesh::Mesh& m, const std::vector<std::uint8_t>& yielded,
                                 const std::vector<std::uint8_t>& active);

}  // namespace rockfdem::workflows
