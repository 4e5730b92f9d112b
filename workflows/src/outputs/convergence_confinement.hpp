// The run on the axes of convergence-confinement (docs/support.md,
// "Convergence-confinement"): the support characteristic lines of the
// scene's support on its equivalent circle, where they start (the first
// support stage) and the run's end point (summary "convergence_confinement").
#pragma once

#include <optional>

#include "record/run_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// Where the support went in and where the run ended, read by the caller.
struct ConvergenceConfinementState {
  double install_radial_mm = 0;  ///< the key points' mean, at the first support stage
  double install_alpha = 0;      ///< the core's alpha then
  double end_radial_mm = 0;      ///< the key points' mean at the end
  bool lining_installed = false;
};

/// The lines (support_lines.hpp), the installation and the end point: the
/// lining's pressure is its mean thrust over the ring's segments divided by
/// the equivalent radius (a thick ring under external pressure p at radius
/// R carries N = p R); the bolts' share is not in it.
ConvergenceConfinementFigures convergence_confinement(const Scene& scene, const mesh::Mesh& m,
                                                      const fdem::Engine& e,
                                                      const ConvergenceConfinementState& s);

}  // namespace rockfdem::workflows
