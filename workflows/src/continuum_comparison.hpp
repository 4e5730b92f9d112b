// FDEM stress after relaxation against continuum FEM: the engine's final
// triangle stresses beside the implicit deal.II field of the open
// excavation (alpha = 0) and, for a circular opening, Kirsch. Written as a
// per-triangle CSV and relative L2 errors in summary.json ("comparison").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Compares over the rock triangles whose centroid lies within 5 half-spans
/// of the opening's centre (the annulus a <= r <= 5a for a circle); writes
/// `csv_path` and returns the summary entry.
nlohmann::json compare_with_continuum(const Scene& scene, const mesh::Mesh& m,
                                      const fdem::Engine& e, const insitu::InsituField& open_hole,
                                      const std::string& csv_path);

}  // namespace rockfdem::workflows
