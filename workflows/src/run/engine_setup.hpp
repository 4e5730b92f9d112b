// Private: the run's set-up from the validated scene: the implicit stage's
// input, the engine's materials, bolts and contact, and the engine itself
// at a tunnel's hand-off or a specimen's start.
#pragma once

#include <map>

#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/fdem/model_input.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "scene/stage_damping.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {

insitu::InsituSpec insitu_spec(const Scene& scene);

/// The engine's material for each zone present in the scene (rock, core, lining).
std::map<mesh::Zone, fdem::Material> engine_materials(const Scene& scene);

/// The grout as an engine material (rock law with the grout's strengths).
fdem::Material grout_material(const Scene& scene);

/// The shotcrete-rock bond as an engine material ([lining_interface]).
fdem::Material lining_interface_material(const Scene& scene);

/// The scene's bolts as the engine's bolt records.
std::vector<fdem::BoltSpec> bolt_specs(const Scene& scene);

/// The scene's contact settings for the engine.
fdem::ContactSettings contact_settings(const Scene& scene);

/// The engine's input at a tunnel's hand-off from the implicit `handoff`
/// field: its stresses, the core at its alpha, the box's
/// in-situ tractions, the scene's dt, mass scaling and contact, on
/// `threads` OpenMP threads.
fdem::ModelInput engine_input(const Scene& scene, const mesh::Mesh& m,
                              const insitu::InsituField& handoff, int threads);

/// The engine for `in`. An in.dt above the stability limit is refused
/// (InputError naming engine.dt) unless `force_dt`: then the run keeps it
/// and stops with a diagnostic if it diverges.
fdem::Engine make_engine(fdem::ModelInput in, const Scene& scene, bool force_dt);

/// What a tunnel run's engine setup gives the run: the engine materials the
/// support stages give crack elements, the bolt plan (empty without bolts),
/// the engine (with the hand-off step's damping) and the stages' damping.
struct EngineSetup {
  SupportMaterials support;
  fdem::BoltPlan bolts;  ///< marks bolt triangles and allows fracture there
  fdem::Engine engine;
  fdem::DampingSettings stage_damping;  ///< after the hand-off step (stage_damping)
};

/// The engine of a tunnel at the hand-off (engine_input) with the support
/// materials and bolts, and engine.dt checked against the stability limit
/// with the hand-off's damping and with the stages' (InputError naming the
/// scene's keys, before anything is written; nothing when `force_dt`).
EngineSetup setup_engine(const Scene& scene, const mesh::Mesh& m,
                         const insitu::InsituField& handoff, int threads, bool force_dt);

/// The specimen's platens: the loaded edges (UCS: bottom and top; disc:
/// the loading arcs) move towards each other at loading.platen_velocity.
/// Rough platens (loading.platen_friction) also hold the ends laterally;
/// frictionless ones leave the lateral motion free (rollers).
std::vector<fdem::BoundaryCondition> specimen_platens(const Scene& scene);

/// The engine's input for a specimen: the mesh, the rock, the platens, the
/// scene's time step, damping, mass scaling and contact settings.
fdem::ModelInput specimen_model_input(const Scene& scene, const mesh::Mesh& m, int threads);

/// Throws the scene's InputError for an explicit engine.dt above `limit`
/// (the stability limit of `model`, in words); nothing when dt <= limit.
void refuse_dt_above(const Scene& scene, double dt, double limit, const char* model);

}  // namespace rockfdem::workflows
