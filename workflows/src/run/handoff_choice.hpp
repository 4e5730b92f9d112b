// Where the implicit stage hands the core over (insitu.handoff): at the
// last alpha of the list, or at the last alpha before the first one whose
// field loads a crack element beyond its strength, so that the explicit
// stages start with every crack element intact and fracture grows as the
// core softens further (the paper's procedure) instead of arriving in one
// step.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <vector>

#include "rockfdem/fdem/model_input.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

struct HandoffChoice {
  /// Per solved alpha: the largest ratio of a crack element's face traction
  /// to its strength (normal against ft, shear against c - sigma_n tan phi)
  /// over the crack elements the engine will make (interior edges with a
  /// fracture triangle on either side, both triangles in the field), each
  /// face loaded by the mean of its two triangles' stresses, with the
  /// strengths the engine gives that pair (the weaker material's).
  /// Strength heterogeneity's scatter is not in it.
  std::vector<double> strength_ratio;
  std::size_t index = 0;  ///< the field handed over
};

/// The largest ratio of HandoffChoice::strength_ratio in one field; the
/// crack elements' faces are found at the first field and kept for the next.
class StrengthRatio {
 public:
  struct Face;  ///< a crack element's triangles, normal and tangent
  StrengthRatio(const Scene& scene, const mesh::Mesh& m);
  double operator()(const insitu::InsituField& f);

 private:
  const mesh::Mesh* mesh_;
  std::map<mesh::Zone, fdem::Material> materials_;
  std::shared_ptr<const std::vector<Face>> faces_;
};

/// The scene's rule over the solved fields' ratios (alphas decreasing):
/// "last" takes the last; "first_crack" the last of those before the first
/// with a ratio above 1 (the first field if it is itself above 1).
HandoffChoice choose_handoff(const Scene& scene, std::vector<double> strength_ratio);

}  // namespace rockfdem::workflows
