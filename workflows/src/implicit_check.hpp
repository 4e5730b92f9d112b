// The implicit in-situ field is linear elasticity on the undeformed mesh:
// it stays meaningful only while its displacements are small against the
// elements. A stress far above the rock's stiffness (sigma 1e10 Pa on
// E 3e9 Pa: 18.2 MPa typed as 18.2e9, or E in MPa) inverts triangles; the
// explicit stage then fails within steps with advice about dt. The field
// is checked here, before anything is written, and refused naming the
// stress-to-modulus ratio.
#pragma once

#include <vector>

#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

struct Scene;

/// Throws rockfdem::InputError when a field inverts (or flattens) any of
/// its active triangles: J = det(F) <= 0 with x = X + u.
void check_implicit_field(const Scene& scene, const mesh::Mesh& m,
                          const std::vector<insitu::InsituField>& fields);

}  // namespace rockfdem::workflows
