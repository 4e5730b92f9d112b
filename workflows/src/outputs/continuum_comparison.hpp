// FDEM stress after relaxation against continuum FEM: the engine's final
// triangle stresses beside the implicit deal.II field of the open
// excavation (alpha = 0) and, for a circular opening, Kirsch. Written as a
// per-triangle CSV and relative L2 errors (summary.json's "comparison").
#pragma once

#include <array>
#include <cmath>
#include <string>

#include "record/continuum_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Relative L2 of stresses (sxx, syy, sxy) over an area:
/// sqrt(sum A |s - ref|^2 / sum A |ref|^2), |s|^2 = sxx^2 + syy^2 + 2 sxy^2.
struct StressL2 {
  double num = 0, den = 0;
  void add(double area, const std::array<double, 3>& s, const std::array<double, 3>& ref) {
    const double dxx = s[0] - ref[0], dyy = s[1] - ref[1], dxy = s[2] - ref[2];
    num += area * (dxx * dxx + dyy * dyy + 2 * dxy * dxy);
    den += area * (ref[0] * ref[0] + ref[1] * ref[1] + 2 * ref[2] * ref[2]);
  }
  double value() const { return den > 0 ? std::sqrt(num / den) : 0.0; }
};

/// Whether the scene's geometry has the Kirsch closed form (circular opening,
/// uniform stress, no lining) and its parameters.
bool kirsch_case(const Scene& scene, insitu::KirschCase* k);

/// Compares over the rock triangles whose centroid lies within 5 half-spans
/// of the opening's centre (the annulus a <= r <= 5a for a circle); writes
/// `csv_path` and returns the figures.
ContinuumComparison compare_with_continuum(const Scene& scene, const mesh::Mesh& m,
                                           const fdem::Engine& e,
                                           const insitu::InsituField& open_hole,
                                           const std::string& csv_path);

}  // namespace rockfdem::workflows
