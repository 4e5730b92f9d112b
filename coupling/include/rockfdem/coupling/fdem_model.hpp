// Mesh (and implicit field) to the explicit engine's input, and the engine's
// state back to a ParaView grid. The mesh's triangles are the engine's
// triangles one to one, so the implicit stress hands over element by
// element with no interpolation.
#pragma once

#include <map>

#include "rockfdem/coupling/vtk_grid.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/model_input.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::coupling {

/// Vertices, triangles, zones (as material indices), fracture flags and
/// tagged edges of `m`; `by_zone` gives each zone present its material.
/// Throws rockfdem::InputError naming a zone without a material.
fdem::ModelInput model_input(const mesh::Mesh& m,
                             const std::map<mesh::Zone, fdem::Material>& by_zone,
                             fdem::Plane plane);

/// The implicit field as the engine's initial state: its per-triangle
/// stress. The engine starts on the undeformed mesh (the linear implicit
/// solution is in equilibrium there); the implicit displacement is added
/// back at output (fdem_grid's `implicit`, the key points).
void apply_insitu(const insitu::InsituField& field, fdem::ModelInput& in);

/// The engine's state: its own nodes (duplicated where cracks may open) with
/// displacement and velocity; triangles with stress (xx, yy, zz, xy; zz from
/// the implicit field's szz and the engine's plane strain), principal stresses,
/// zone, activity; crack elements as line cells with damage, state and mode.
/// With `implicit`, displacements include the implicit stage's part.
VtkGrid fdem_grid(const fdem::Engine& engine, const mesh::Mesh& m,
                  const insitu::InsituField* implicit = nullptr);

/// Names the frame in its field data: the construction stage it ends, the
/// engine step and the simulated time [s].
void add_frame_info(VtkFieldData& f, const std::string& stage, long step, double time);

}  // namespace rockfdem::coupling
