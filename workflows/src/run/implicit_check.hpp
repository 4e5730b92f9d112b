// The implicit in-situ field is linear elasticity on the undeformed mesh:
// it stays meaningful only while its displacements are small against the
// elements. A stress far above the rock's stiffness (sigma 1e10 Pa on
// E 3e9 Pa: 18.2 MPa typed as 18.2e9, or E in MPa) inverts triangles; the
// explicit stage then fails within steps with advice about dt. The field
// is checked here, before anything is written, and refused naming the
// stress-to-modulus ratio.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

struct Scene;

/// The active triangles a field inverts (or flattens): J = det(F) <= 0
/// with x = X + u; none for a field without its arrays.
struct Inversion {
  long count = 0;
  std::size_t first = 0;  ///< the first such triangle
};
Inversion inverted_triangles(const mesh::Mesh& m, const insitu::InsituField& f);

/// Throws rockfdem::InputError when the field of `alpha` inverted triangles.
void check_implicit_field(const Scene& scene, const mesh::Mesh& m, double alpha,
                          const Inversion& inv);

/// In-situ stress over the rock's Young's modulus above which an explicit
/// stage's failure is put down to the stress rather than the time step:
/// the seed's tunnel runs at 0.006, and the linear in-situ field's strains
/// (about this ratio) stop being small well before they invert triangles.
inline constexpr double kStressRatioLimit = 0.01;

/// The explicit stage's failure message `what`, followed, when the scene's
/// in-situ stress exceeds kStressRatioLimit of the rock's modulus, by that
/// likely cause with the ratio and the keys to check.
std::string with_likely_cause(const Scene& scene, const std::string& what);

}  // namespace rockfdem::workflows
