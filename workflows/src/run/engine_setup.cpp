#include "run/engine_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/coupling/joint_cracks.hpp"
#include "rockfdem/error.hpp"
#include "scene/lining_parts.hpp"

namespace rockfdem::workflows {
namespace {

// The in-situ stress tensor, tension positive: -sH along `angle`, -sV across.
std::array<double, 3> insitu_tensor(const InsituSettings& s) {
  const double a = s.angle_deg * M_PI / 180, c = std::cos(a), n = std::sin(a);
  return {-(s.sigma_h * c * c + s.sigma_v * n * n), -(s.sigma_h * n * n + s.sigma_v * c * c),
          -(s.sigma_h - s.sigma_v) * n * c};
}

// Outer boundary: the in-situ traction sigma0 . n on all four sides, as in
// the implicit stage, so the box is in equilibrium with the initial stress
// at step 0. With insitu.rollers (the default) each side is also a roller:
// its normal displacement stays at the hand-off's, so the traction there
// becomes the roller's reaction (the same at step 0) and the model has no
// rigid-body mode left. Tractions alone leave three: the loads are
// self-equilibrated, but once a ring around the opening is broken the outer
// block can turn on it (outer_boundary.hpp guards against it). Reported
// displacements have the mean translation of the outer boundary removed, as
// the implicit stage removes its rigid motion.
//
// Traction sigma0 . n on each side of the box (outward normals); with
// rollers, the normal velocity held at zero too.
std::vector<fdem::BoundaryCondition> box_conditions(const InsituSettings& s) {
  const auto sig = insitu_tensor(s);
  const std::pair<int, std::array<double, 2>> sides[] = {{mesh::kLeft, {-1, 0}},
                                                         {mesh::kRight, {1, 0}},
                                                         {mesh::kBottom, {0, -1}},
                                                         {mesh::kTop, {0, 1}}};
  std::vector<fdem::BoundaryCondition> bcs;
  for (const auto& [tag, n] : sides) {
    fdem::BoundaryCondition bc;
    bc.tag = tag;
    bc.tx = sig[0] * n[0] + sig[2] * n[1];
    bc.ty = sig[2] * n[0] + sig[1] * n[1];
    if (s.rollers) (n[0] != 0 ? bc.x : bc.y) = fdem::Constraint::kFixed;
    bcs.push_back(bc);
  }
  return bcs;
}

insitu::ElasticMaterial elastic(const MaterialSpec& m) { return {m.young, m.poisson}; }

fdem::Material engine_material(const MaterialSpec& m, const EngineSettings& e) {
  fdem::Material f;
  f.density = m.density;
  f.young = m.young;
  f.poisson = m.poisson;
  f.tensile_strength = m.tensile_strength;
  f.cohesion = m.cohesion;
  f.friction_deg = m.friction_angle;
  f.residual_friction_deg = m.residual_friction_angle;
  f.gf_I = m.fracture_energy_I;
  f.gf_II = m.fracture_energy_II;
  // A zone given no strength is elastic: the crack elements that may touch
  // it (next to a fracture zone) get a strength no stress reaches.
  if (f.tensile_strength <= 0) f.tensile_strength = 10 * m.young;
  if (f.cohesion <= 0) f.cohesion = 10 * m.young;
  if (f.gf_I <= 0) f.gf_I = 1e9;
  if (f.gf_II <= 0) f.gf_II = 1e9;
  f.normal_penalty = m.penalty_factor * m.young;
  f.weibull_modulus = m.heterogeneity;
  f.heterogeneity_seed = m.heterogeneity_seed;
  f.damping_ratio = e.damping_ratio;
  return f;
}

fdem::Material bond_material(const BondSettings& g, double density, const Scene& s) {
  fdem::Material m;
  m.density = density;
  m.young = g.young;
  m.poisson = 0.25;
  m.tensile_strength = g.tensile_strength;
  m.cohesion = g.cohesion;
  m.friction_deg = m.residual_friction_deg = g.friction_angle;
  m.gf_I = g.fracture_energy_I;
  m.gf_II = g.fracture_energy_II;
  m.damping_ratio = s.engine.damping_ratio;
  return m;
}

fdem::BoltSteel steel_of(const SteelSettings& b) {
  fdem::BoltSteel steel;
  steel.young = b.young;
  steel.yield_strength = b.yield_strength;
  steel.ultimate_strength = b.ultimate_strength;
  steel.tangent_modulus = b.tangent_modulus;
  steel.shear_yield_strength = b.shear_yield_strength;
  steel.gf_II = b.shear_fracture_energy;
  return steel;
}

// The lining has no crack elements of its own, and its tensile strength is
// the capacity check's: a crack element between it and the rock (the bond,
// before the lining stage gives it [lining_interface]) is the rock's.
void as_liner(fdem::Material& m) { m.tensile_strength = m.cohesion = 10 * m.young; }

// The ring's floor part takes [materials.invert]: one more material.
void add_invert_material(const Scene& s, const mesh::Mesh& m, fdem::ModelInput& in) {
  if (!s.invert) return;
  fdem::Material invert = engine_material(*s.invert, s.engine);
  as_liner(invert);
  const int index = int(in.materials.size());
  in.materials.push_back(invert);
  const std::vector<char> part = invert_triangles(s, m);
  for (std::size_t t = 0; t < part.size(); ++t)
    if (part[t]) in.material[t] = index;
}

}  // namespace

std::map<mesh::Zone, fdem::Material> engine_materials(const Scene& s) {
  std::map<mesh::Zone, fdem::Material> out;
  for (const auto& [zone, m] : s.materials) out[zone] = engine_material(m, s.engine);
  // The lining has no crack elements of its own, and its tensile strength is
  // the capacity check's: a crack element between it and the rock (the
  // bond, before the lining stage gives it [lining_interface]) is the rock's.
  if (out.count(mesh::kLining)) as_liner(out[mesh::kLining]);
  return out;
}

fdem::Material grout_material(const Scene& s) {
  return bond_material(s.grout, s.materials.at(mesh::kRock).density, s);
}

fdem::Material lining_interface_material(const Scene& s) {
  return bond_material(s.lining_interface, s.materials.at(mesh::kRock).density, s);
}

std::vector<fdem::BoltSpec> bolt_specs(const Scene& s) {
  std::vector<fdem::BoltSpec> specs;
  for (std::size_t i = 0; i < s.bolts.segments.size(); ++i) {
    const auto& seg = s.bolts.segments[i];
    const SteelSettings& kind = s.bolts.is_cable[i] ? s.bolts.cable : s.bolts.bolt;
    fdem::BoltSpec spec;
    spec.bolt = {{seg[0], seg[1]}, {seg[2], seg[3]}, kind.diameter};
    spec.row_spacing = kind.row_spacing;
    spec.steel = steel_of(kind);
    spec.grout = grout_material(s);
    specs.push_back(spec);
  }
  return specs;
}

fdem::ContactSettings contact_settings(const Scene& s) {
  fdem::ContactSettings c;
  c.enabled = s.engine.contact;
  c.penalty = s.engine.contact_penalty_factor * s.materials.at(mesh::kRock).young;
  c.damping_ratio = s.engine.contact_damping;
  c.friction = s.engine.contact_friction;
  return c;
}

insitu::InsituSpec insitu_spec(const Scene& s) {
  insitu::InsituSpec spec;
  spec.far_field.sH = s.insitu.sigma_h;
  spec.far_field.sV = s.insitu.sigma_v;
  spec.far_field.angle_deg = s.insitu.angle_deg;
  spec.gravity.unit_weight = s.insitu.unit_weight;
  spec.gravity.reference_y = 0;  // the stresses hold at the opening's centre
  if (s.insitu.kirsch_boundary) {
    spec.loading = insitu::BoundaryLoading::kKirschExact;
    spec.kirsch_radius = s.mesh.tunnel.radius;
  }
  spec.materials.rock = elastic(s.materials.at(mesh::kRock));
  if (s.materials.count(mesh::kCore)) spec.materials.core = elastic(s.materials.at(mesh::kCore));
  if (s.materials.count(mesh::kLining))
    spec.materials.lining = elastic(s.materials.at(mesh::kLining));
  spec.lining.active = s.insitu.lining_active;
  spec.alphas = s.insitu.alpha;
  spec.solver.tolerance = s.insitu.tolerance;
  if (s.insitu.solver == "amg") spec.solver.kind = insitu::LinearSolver::kAmgCg;
  if (s.insitu.solver == "direct") spec.solver.kind = insitu::LinearSolver::kDirect;
  return spec;
}

void refuse_dt_above(const Scene& scene, double dt, double limit, const char* model) {
  if (!(dt > limit)) return;
  char msg[500];
  std::snprintf(msg, sizeof msg,
                "%s: key 'engine.dt' = %g s: above the stability limit %.6g s of %s; allowed "
                "0 < dt <= %.6g s (engine.dt = 0 takes engine.dt_safety = %g of it), or pass "
                "--force-dt to run with it anyway",
                scene.source.c_str(), dt, limit, model, limit, scene.engine.dt_safety);
  throw InputError(msg);
}

fdem::Engine make_engine(fdem::ModelInput in, const Scene& scene, bool force_dt) {
  const double dt = in.dt;
  in.dt = 0;  // built with the automatic step, then given the scene's
  fdem::Engine engine(in);
  if (dt <= 0) return engine;
  if (!force_dt) refuse_dt_above(scene, dt, engine.critical_dt(), "this mesh and its penalties");
  engine.set_dt(dt, force_dt ? fdem::DtCheck::kForce : fdem::DtCheck::kRefuseAboveLimit);
  return engine;
}

fdem::ModelInput engine_input(const Scene& scene, const mesh::Mesh& m,
                              const insitu::InsituField& handoff, int threads) {
  std::map<mesh::Zone, fdem::Material> materials = engine_materials(scene);
  // The implicit stage left the core at alpha_h E; the engine continues from there.
  if (materials.count(mesh::kCore) && handoff.alpha > 0)
    materials[mesh::kCore].young *= handoff.alpha;
  fdem::ModelInput in = coupling::model_input(
      m, materials, scene.plane_stress ? fdem::Plane::kStress : fdem::Plane::kStrain);
  add_invert_material(scene, m, in);
  coupling::apply_insitu(handoff, in);
  in.boundary_conditions = box_conditions(scene.insitu);
  // The weight the in-situ gradient holds (scene_build.cpp, relate_gravity).
  in.gravity_y = -scene.engine.gravity;
  in.dt = scene.engine.dt;  // checked by make_engine
  in.dt_safety = scene.engine.dt_safety;
  in.threads = threads;
  in.mass_scaling = {scene.engine.mass_scaling, scene.engine.mass_scaling_dt};
  in.contact = contact_settings(scene);
  return in;
}

namespace {

/// The bolts marked on the mesh and their steel models. The engine's
/// refusals (a strip too stiff or too soft for the rock around it, a bolt
/// crossing no triangle edge) arise from the design and the mesh together;
/// they get the scene and its keys here, before anything is written.
fdem::BoltPlan planned_bolts(const Scene& scene, fdem::ModelInput& in) {
  try {
    return fdem::plan_bolts(in, bolt_specs(scene));
  } catch (const InputError& e) {
    throw InputError(scene.source + ": the bolt design cannot be modelled on this mesh (" +
                     e.what() +
                     "); adjust [bolts] / [cables] (young, diameter, row_spacing, "
                     "strengths), materials.rock.young or mesh.size_near");
  }
}

// The grout and the lining-rock bond: engine materials the support stages
// give crack elements.
SupportMaterials add_support_materials(const Scene& scene, fdem::ModelInput& in) {
  SupportMaterials support;
  support.grout = int(in.materials.size());
  in.materials.push_back(grout_material(scene));
  if (scene.materials.count(mesh::kLining)) {
    support.lining_interface = int(in.materials.size());
    in.materials.push_back(lining_interface_material(scene));
  }
  return support;
}

// The joint material: the rock's elastic constants (its triangles are the
// rock's), the joint law with the [joints] strengths and penalties.
fdem::Material joint_material(const Scene& scene) {
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  const JointSettings& j = scene.joints;
  fdem::Material m = engine_material(rock, scene.engine);
  m.crack_law = fdem::CrackLaw::kJoint;
  m.tensile_strength = j.tensile_strength;
  m.cohesion = j.cohesion;
  m.friction_deg = j.friction_angle;
  m.residual_friction_deg = j.residual_friction_angle;
  m.gf_I = j.fracture_energy_I;
  m.gf_II = j.fracture_energy_II;
  m.normal_penalty = j.penalty_factor * rock.young;
  m.tangential_penalty = 0;  // the normal one
  m.weibull_modulus = 0;
  m.jrc = j.jrc;  // both 0 with Mohr-Coulomb
  m.jcs = j.jcs;
  return m;
}

// The joint material's index in `in` (added only where the mesh has joints,
// so a model without them is the same as before); -1 without joints.
int add_joint_material(const Scene& scene, const mesh::Mesh& m, fdem::ModelInput& in) {
  if (m.joint_edges.empty()) return -1;
  in.materials.push_back(joint_material(scene));
  return int(in.materials.size()) - 1;
}

// Crack elements on joint traces take the joint material, before the first
// step (the crack pre-stress is set then, with their law).
void assign_joints(const mesh::Mesh& m, int material, fdem::Engine& engine) {
  if (material < 0) return;
  const std::vector<std::int32_t> traces = coupling::joint_crack_traces(engine, m);
  for (std::size_t c = 0; c < traces.size(); ++c)
    if (traces[c]) engine.set_crack_material(c, material);
}

// The stages' local damping lowers the limit by sqrt(1 + alpha): an
// explicit dt must hold then too, and is refused before anything is written.
void refuse_dt_with_stage_damping(const Scene& scene, fdem::Engine& engine,
                                  const fdem::DampingSettings& handoff_damping,
                                  const fdem::DampingSettings& stages, bool force_dt) {
  if (scene.engine.dt <= 0 || force_dt) return;
  engine.set_damping(stages);
  refuse_dt_above(scene, scene.engine.dt, engine.critical_dt(),
                  "this mesh and its penalties with the stages' damping");
  engine.set_damping(handoff_damping);
}

}  // namespace

EngineSetup setup_engine(const Scene& scene, const mesh::Mesh& m,
                         const insitu::InsituField& handoff, int threads, bool force_dt) {
  fdem::ModelInput in = engine_input(scene, m, handoff, threads);
  const SupportMaterials support = add_support_materials(scene, in);
  const int joint = add_joint_material(scene, m, in);
  fdem::BoltPlan bolts;
  if (!scene.bolts.segments.empty()) bolts = planned_bolts(scene, in);
  EngineSetup setup{support, std::move(bolts), make_engine(in, scene, force_dt),
                    stage_damping(scene)};
  assign_joints(m, joint, setup.engine);
  refuse_dt_with_stage_damping(scene, setup.engine, in.damping, setup.stage_damping, force_dt);
  return setup;
}

std::vector<fdem::BoundaryCondition> specimen_platens(const Scene& s) {
  const bool disc = s.mesh.kind == mesh::ModelKind::kBrazilian;
  const double v = s.engine.platen_velocity;
  fdem::BoundaryCondition lower, upper;
  lower.tag = disc ? mesh::kLoadBottom : mesh::kBottom;
  upper.tag = disc ? mesh::kLoadTop : mesh::kTop;
  if (s.engine.rough_platens) lower.x = upper.x = fdem::Constraint::kFixed;
  lower.y = upper.y = fdem::Constraint::kVelocity;
  lower.vy = v;
  upper.vy = -v;
  return {lower, upper};
}

fdem::ModelInput specimen_model_input(const Scene& scene, const mesh::Mesh& m, int threads) {
  fdem::ModelInput in = coupling::model_input(
      m, engine_materials(scene), scene.plane_stress ? fdem::Plane::kStress : fdem::Plane::kStrain);
  in.boundary_conditions = specimen_platens(scene);
  in.dt = scene.engine.dt;  // checked by make_engine
  in.dt_safety = scene.engine.dt_safety;
  in.damping.local = std::max(scene.engine.local_damping, 0.0);  // -1: not given, none
  in.damping.mass_proportional = scene.engine.mass_damping;
  in.gravity_y = -scene.engine.gravity;
  in.threads = threads;
  in.mass_scaling = {scene.engine.mass_scaling, scene.engine.mass_scaling_dt};
  in.contact = contact_settings(scene);
  return in;
}

}  // namespace rockfdem::workflows
