// The pictures of a tunnel's final state an engineer reads: zoomed on the
// opening, in mm and MPa, compression positive, with the broken cracks by
// mode, the lining and the bolts drawn (docs/workflow.md, "Pictures").
#pragma once

#include <optional>

#include "outputs/material_point.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/plots/plot.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows {

/// The engine's nodes and triangles, as the pictures draw them (current positions).
coupling::VtkGrid picture_grid(const fdem::Engine& e);

/// The opening (mesh::find_opening) and one span of rock on each side:
/// about the zone the support and the broken rock occupy. Nothing for a
/// model without an opening.
std::optional<plots::MeshView> opening_window(const mesh::Mesh& m);

/// What the pictures draw over the contours.
struct PictureContext {
  const fdem::Engine& e;
  const mesh::Mesh& m;
  const Scene& scene;
  const fdem::BoltPlan* bolts;  ///< installed bolts are drawn; may be null
  /// Displacement from the in-situ state (the key points'); empty: the
  /// opening's deformed outline is not drawn.
  NodeDisplacement u;
};

/// |u| [mm] per node, from the in-situ state (c.u), with the broken rock
/// cracks by mode, the lining, the bolts, the fracture zone's edge and the
/// opening's magnified deformed outline.
plots::MeshPicture displacement_picture(const PictureContext& c);

/// The most (or least) compressive in-plane principal stress [MPa],
/// compression positive, with the broken rock cracks, the lining, the
/// bolts, the fracture zone's edge and the opening's deformed outline.
plots::MeshPicture principal_picture(const PictureContext& c, bool most_compressive);

/// final_mesh.png of a tunnel: the mesh around the opening (as the field
/// pictures frame it), its triangles' edges, coloured by what they are
/// (rock that can crack, rock that cannot, lining, bolt steel and grout),
/// the excavated ones left out, every broken crack in red and the fracture
/// zone's edge.
plots::MeshPicture mesh_picture(const PictureContext& c);

/// final_mesh.png of a specimen: the whole model as deformed, its
/// triangles' edges, every broken crack in red (as a tunnel's), the
/// triangles no longer active left out.
plots::MeshPicture specimen_mesh_picture(const fdem::Engine& e);

/// A specimen's whole model coloured by the most compressive
/// in-plane principal stress [MPa], compression positive, or with
/// `most_tensile` (a Brazilian disc) the most tensile, tension positive;
/// every broken crack in black, excavated triangles grey.
plots::MeshPicture whole_model_picture(const fdem::Engine& e, bool most_tensile);

/// Triangle t's in-plane principal stresses [MPa], compression positive:
/// {most compressive, least compressive}.
std::array<double, 2> compressive_principal_mpa(const fdem::Engine& e, std::size_t t);

}  // namespace rockfdem::workflows
