// Scene defaults are written once, in the schema: a scene that leaves a
// key out holds the schema's default for it, and a key whose default is
// another key's value ("engine.steps", the rock's friction angle) holds that
// value. Every key with a default is checked here, so a key added with a
// default but filled from anywhere else fails this test.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"

using namespace rockfdem;
using namespace rockfdem::workflows;

namespace {

// A circular tunnel with a ring, bolts and instruments; every key with a
// default left out. The rock gives its strengths (no defaults) so that the
// core, which inherits them, holds something to compare.
const std::string kTunnel = R"(
[tunnel]
shape = "circular"
radius = 3.0
lining_thickness = 0.3
[materials.rock]
young = 5.0e9
poisson = 0.25
tensile_strength = 1e6
cohesion = 2e6
fracture_energy_I = 10
fracture_energy_II = 50
[materials.lining]
young = 20e9
poisson = 0.2
[insitu]
sigma_h = 18.2e6
sigma_v = 11.4e6
[[bolt]]
start = [2.1213203, 2.1213203]
end = [4.2426407, 4.2426407]
[[bolt_fan]]
radius = 3.0
count = 3
length = 2.0
[[monitor]]
name = "m"
x = 0.0
y = 10.0
[[extensometer]]
name = "e"
from = "vault"
length = 5.0
[[joint_set]]
dip = 30.0
spacing = 2.0
)";

// The same stages given explicitly, each with its keys left out.
const std::string kStages = R"(
[[stages]]
kind = "lining"
[[stages]]
kind = "bolts"
[[stages]]
kind = "remove_core"
[[stages]]
kind = "equilibrium"
)";

using Number = std::function<double(const Scene&)>;
using Text = std::function<std::string(const Scene&)>;

const MaterialSpec& mat(const Scene& s, mesh::Zone z) { return s.materials.at(z); }

void add_material(std::map<std::string, Number>& f, mesh::Zone name) {
  const std::string p = "materials." + mesh::zone_name(name) + ".";
  f[p + "density"] = [=](const Scene& s) { return mat(s, name).density; };
  f[p + "young"] = [=](const Scene& s) { return mat(s, name).young; };
  f[p + "poisson"] = [=](const Scene& s) { return mat(s, name).poisson; };
  f[p + "tensile_strength"] = [=](const Scene& s) { return mat(s, name).tensile_strength; };
  f[p + "friction_angle"] = [=](const Scene& s) { return mat(s, name).friction_angle; };
  f[p + "residual_friction_angle"] = [=](const Scene& s) {
    return mat(s, name).residual_friction_angle;
  };
  if (name == mesh::kLining) {  // an elastic liner: no crack keys, its section's
    f[p + "steel_young"] = [=](const Scene& s) { return mat(s, name).section.steel_young; };
    return;
  }
  f[p + "cohesion"] = [=](const Scene& s) { return mat(s, name).cohesion; };
  f[p + "fracture_energy_I"] = [=](const Scene& s) { return mat(s, name).fracture_energy_I; };
  f[p + "fracture_energy_II"] = [=](const Scene& s) { return mat(s, name).fracture_energy_II; };
  f[p + "penalty_factor"] = [=](const Scene& s) { return mat(s, name).penalty_factor; };
  f[p + "heterogeneity"] = [=](const Scene& s) { return mat(s, name).heterogeneity; };
  f[p + "heterogeneity_seed"] = [=](const Scene& s) {
    return double(mat(s, name).heterogeneity_seed);
  };
}

// The members of a struct `of` a scene holds, under `section`.
template <class S, class Of>
void add_members(std::map<std::string, Number>& f, const std::string& section, Of of,
                 std::initializer_list<std::pair<const char*, double S::*>> members) {
  for (auto [key, m] : members)
    f[section + "." + key] = [of, m = m](const Scene& s) { return of(s).*m; };
}

void add_steel(std::map<std::string, Number>& f, const char* section,
               const SteelSettings BoltSettings::*kind) {
  using T = SteelSettings;
  add_members<T>(f, section, [kind](const Scene& s) -> const T& { return s.bolts.*kind; },
                 {{"diameter", &T::diameter},
                  {"row_spacing", &T::row_spacing},
                  {"young", &T::young},
                  {"yield_strength", &T::yield_strength},
                  {"ultimate_strength", &T::ultimate_strength},
                  {"tangent_modulus", &T::tangent_modulus},
                  {"shear_yield_strength", &T::shear_yield_strength},
                  {"shear_fracture_energy", &T::shear_fracture_energy}});
}

void add_bond(std::map<std::string, Number>& f, const char* section, BondSettings Scene::*bond) {
  using T = BondSettings;
  add_members<T>(f, section, [bond](const Scene& s) -> const T& { return s.*bond; },
                 {{"young", &T::young},
                  {"tensile_strength", &T::tensile_strength},
                  {"cohesion", &T::cohesion},
                  {"friction_angle", &T::friction_angle},
                  {"fracture_energy_I", &T::fracture_energy_I},
                  {"fracture_energy_II", &T::fracture_energy_II}});
}

// The last stage is the equilibrium stage, default or given.
const StageSpec& last(const Scene& s) { return s.stages.back(); }

// The angle [deg] of bolt k of the fan (bolts after the one [[bolt]]).
double fan_deg(const Scene& s, std::size_t k) {
  const auto& g = s.bolts.segments.at(1 + k);
  return std::atan2(g[1], g[0]) * 180 / M_PI;
}

// Where each numeric key lands in the Scene.
void add_joints(std::map<std::string, Number>& f) {
  using J = JointSettings;
  add_members<J>(f, "joints", [](const Scene& s) -> const J& { return s.joints; },
                 {{"tensile_strength", &J::tensile_strength},
                  {"cohesion", &J::cohesion},
                  {"friction_angle", &J::friction_angle},
                  {"residual_friction_angle", &J::residual_friction_angle},
                  {"fracture_energy_I", &J::fracture_energy_I},
                  {"fracture_energy_II", &J::fracture_energy_II},
                  {"penalty_factor", &J::penalty_factor},
                  {"margin", &J::margin}});
  f["joints.seed"] = [](const Scene& s) { return double(s.joints.seed); };
  using S = mesh::JointSetSpec;
  add_members<S>(f, "joint_set[0]", [](const Scene& s) -> const S& { return s.joints.sets[0]; },
                 {{"trace_length", &S::trace_length},
                  {"persistence", &S::persistence},
                  {"dip_scatter", &S::dip_scatter_deg},
                  {"spacing_scatter", &S::spacing_scatter},
                  {"length_scatter", &S::length_scatter}});
}

std::map<std::string, Number> number_fields() {
  std::map<std::string, Number> f;
  f["domain.width"] = [](const Scene& s) { return s.mesh.domain.width; };
  f["domain.height"] = [](const Scene& s) { return s.mesh.domain.height; };
  f["domain.center_x"] = [](const Scene& s) { return s.mesh.domain.center_x; };
  f["domain.center_y"] = [](const Scene& s) { return s.mesh.domain.center_y; };
  f["tunnel.fracture_zone"] = [](const Scene& s) { return s.mesh.tunnel.fracture_zone; };
  f["specimen.width"] = [](const Scene& s) { return s.mesh.specimen.width; };
  f["specimen.height"] = [](const Scene& s) { return s.mesh.specimen.height; };
  f["specimen.diameter"] = [](const Scene& s) { return s.mesh.specimen.diameter; };
  f["specimen.load_arc_deg"] = [](const Scene& s) { return s.mesh.specimen.load_arc_deg; };
  f["mesh.size_near"] = [](const Scene& s) { return s.mesh.size.size_near; };
  f["mesh.size_far"] = [](const Scene& s) { return s.mesh.size.size_far; };
  f["mesh.grading_distance"] = [](const Scene& s) { return s.mesh.size.grading_distance; };
  f["mesh.algorithm"] = [](const Scene& s) { return double(s.mesh.size.algorithm); };
  for (mesh::Zone z : mesh::kZones) add_material(f, z);
  f["insitu.angle"] = [](const Scene& s) { return s.insitu.angle_deg; };
  f["insitu.unit_weight"] = [](const Scene& s) { return s.insitu.unit_weight; };
  f["insitu.tolerance"] = [](const Scene& s) { return s.insitu.tolerance; };
  f["insitu.dilation_angle"] = [](const Scene& s) { return s.insitu.dilation_angle; };
  f["engine.steps"] = [](const Scene& s) { return double(s.engine.steps); };
  f["engine.dt"] = [](const Scene& s) { return s.engine.dt; };
  f["engine.dt_safety"] = [](const Scene& s) { return s.engine.dt_safety; };
  f["engine.damping_ratio"] = [](const Scene& s) { return s.engine.damping_ratio; };
  f["engine.mass_damping"] = [](const Scene& s) { return s.engine.mass_damping; };
  f["engine.mass_scaling_dt"] = [](const Scene& s) { return s.engine.mass_scaling_dt; };
  f["engine.gravity"] = [](const Scene& s) { return s.engine.gravity; };
  f["loading.platen_velocity"] = [](const Scene& s) { return s.engine.platen_velocity; };
  f["loading.stop_after_peak"] = [](const Scene& s) { return s.engine.stop_after_peak; };
  add_steel(f, "bolts", &BoltSettings::bolt);
  add_steel(f, "cables", &BoltSettings::cable);
  add_bond(f, "grout", &Scene::grout);
  add_bond(f, "lining_interface", &Scene::lining_interface);
  f["bolt_fan[0].first_deg"] = [](const Scene& s) { return fan_deg(s, 0); };
  f["bolt_fan[0].last_deg"] = [](const Scene& s) { return fan_deg(s, 2); };
  f["extensometer[0].anchors"] = [](const Scene& s) { return double(s.extensometers[0].anchors); };
  f["contact.penalty_factor"] = [](const Scene& s) { return s.engine.contact_penalty_factor; };
  f["contact.damping_ratio"] = [](const Scene& s) { return s.engine.contact_damping; };
  f["stages[0].max_steps"] = [](const Scene& s) { return double(last(s).max_steps); };
  f["stages[0].ratio"] = [](const Scene& s) { return last(s).ratio; };
  f["stages[0].settle"] = [](const Scene& s) { return last(s).settle; };
  f["stages[0].broken_settle"] = [](const Scene& s) { return last(s).broken_settle; };
  f["stages[0].hold"] = [](const Scene& s) { return double(last(s).hold); };
  f["stages[0].unstable_fraction"] = [](const Scene& s) { return last(s).unstable_fraction; };
  f["stages[0].time"] = [](const Scene& s) { return last(s).time; };
  f["stages[0].every_steps"] = [](const Scene& s) { return double(last(s).every_steps); };
  f["output.every_steps"] = [](const Scene& s) { return double(s.output.every_steps); };
  f["output.checkpoint_every"] = [](const Scene& s) { return double(s.output.checkpoint_every); };
  add_joints(f);
  return f;
}

std::string yes(bool b) { return b ? "true" : "false"; }

// Where each boolean, string and choice key lands, written as the schema
// writes its default.
std::map<std::string, Text> text_fields() {
  std::map<std::string, Text> f;
  f["model.kind"] = [](const Scene& s) {
    return s.mesh.kind == mesh::ModelKind::kTunnel ? "tunnel" : "other";
  };
  f["model.title"] = [](const Scene& s) { return "\"" + s.title + "\""; };
  f["model.analysis"] = [](const Scene& s) {
    return s.plane_stress ? "plane_stress" : "plane_strain";
  };
  f["insitu.boundary"] = [](const Scene& s) {
    return s.insitu.kirsch_boundary ? "kirsch" : "far_field";
  };
  f["materials.lining.section"] = [](const Scene& s) {
    return s.materials.at(mesh::kLining).section.kind;
  };
  f["insitu.rollers"] = [](const Scene& s) { return yes(s.insitu.rollers); };
  f["insitu.continuum_post_peak"] = [](const Scene& s) {
    return yes(s.insitu.continuum_post_peak);
  };
  f["insitu.handoff"] = [](const Scene& s) {
    return s.insitu.handoff_first_crack ? "first_crack" : "last";
  };
  f["insitu.lining_active"] = [](const Scene& s) { return yes(s.insitu.lining_active); };
  f["insitu.solver"] = [](const Scene& s) { return s.insitu.solver; };
  f["insitu.continuum"] = [](const Scene& s) { return s.insitu.continuum; };
  f["engine.kinetic_damping"] = [](const Scene& s) { return yes(s.engine.kinetic_damping); };
  // auto: on for tunnels.
  f["engine.mass_scaling"] = [](const Scene& s) { return s.engine.mass_scaling ? "auto" : "off"; };
  f["loading.platen_friction"] = [](const Scene& s) {
    return s.engine.rough_platens ? "rough" : "frictionless";
  };
  f["bolts.install_stress"] = [](const Scene& s) {
    return s.bolts.keep_current_stress ? "current" : "free";
  };
  f["bolt[0].kind"] = [](const Scene& s) { return s.bolts.is_cable[0] ? "cable" : "bolt"; };
  f["bolt_fan[0].kind"] = [](const Scene& s) { return s.bolts.is_cable[1] ? "cable" : "bolt"; };
  f["monitor[0].relative_to_support"] = [](const Scene& s) {
    return yes(s.monitors[0].relative_to_support);
  };
  f["extensometer[0].relative_to_support"] = [](const Scene& s) {
    return yes(s.extensometers[0].relative_to_support);
  };
  f["contact.enabled"] = [](const Scene& s) { return yes(s.engine.contact); };
  f["contact.friction"] = [](const Scene& s) { return yes(s.engine.contact_friction); };
  f["stages[0].stop_when_unstable"] = [](const Scene& s) {
    return yes(last(s).stop_when_unstable);
  };
  f["output.vtk"] = [](const Scene& s) { return yes(s.output.vtk); };
  f["output.plots"] = [](const Scene& s) { return yes(s.output.plots); };
  f["output.convergence_from"] = [](const Scene& s) {
    return s.output.convergence_from_support ? "support" : "start";
  };
  f["references.from"] = [](const Scene& s) {
    return s.references.from_support ? "support" : "start";
  };
  f["references.reading"] = [](const Scene& s) {
    return s.references.survey ? "survey" : "radial";
  };
  f["references.source"] = [](const Scene& s) { return "\"" + s.references.source + "\""; };
  f["joints.dfn_file"] = [](const Scene& s) { return "\"" + s.joints.dfn_file + "\""; };
  f["joints.shear_strength"] = [](const Scene& s) {
    return s.joints.barton_bandis ? "barton_bandis" : "mohr_coulomb";
  };
  f["insitu.alpha"] = [](const Scene& s) {
    return s.insitu.alpha == std::vector<double>{1.0} ? "[1.0]" : "other";
  };
  f["bolt_fan[0].centre"] = [](const Scene& s) {  // the middle bolt's head at (0, radius)
    const auto& g = s.bolts.segments.at(2);
    return std::abs(g[0]) < 1e-12 && std::abs(g[1] - 3.0) < 1e-12 ? "[0.0, 0.0]" : "other";
  };
  return f;
}

// Keys whose default another scene shows (a horseshoe tunnel, a .msh model).
const std::set<std::string> kElsewhere = {
    "tunnel.shape", "tunnel.span", "tunnel.height", "tunnel.lining_thickness", "tunnel.invert_rise",
    "msh.zones", "msh.edges", "msh.fracture_group", "msh.joints",
    // A ring's floor part of its own: a_floor_part_takes_the_rings_values.
    "tunnel.invert_thickness", "materials.invert.density", "materials.invert.young",
    "materials.invert.poisson", "materials.invert.friction_angle",
    "materials.invert.residual_friction_angle", "materials.invert.tensile_strength",
    "materials.invert.compressive_strength", "materials.invert.section",
    "materials.invert.steel_young", "materials.invert.steel_yield_strength",
    "materials.invert.bar_area", "materials.invert.bar_cover", "materials.invert.set_area",
    "materials.invert.set_inertia", "materials.invert.set_depth", "materials.invert.set_spacing",
    // With gsi alone: RockMass.a_scene_with_gsi_runs_on_the_rock_mass.
    "materials.rock.disturbance",
    // A grout stage's own, held in its stage file:
    // GroutTrigger.no_trigger_key_grouts_at_once_on_the_default.
    "stages[].trigger_broken"};

std::string normalised(const std::string& path) {
  return std::regex_replace(path, std::regex(R"(\[[0-9]+\])"), "[]");
}

const KeySpec& spec_of(const std::string& path) {
  const KeySpec* k = find_key(normalised(path));
  if (!k) throw std::logic_error("not in the schema: " + path);
  return *k;
}

}  // namespace

// Every key with a default is one of the fields checked below (or in the
// tests after it): a new key with a default needs its line here.
TEST(SceneDefaults, every_default_is_checked) {
  const auto numbers = number_fields();
  const auto texts = text_fields();
  std::set<std::string> checked(kElsewhere);
  for (const auto& [key, get] : numbers) checked.insert(normalised(key));
  for (const auto& [key, get] : texts) checked.insert(normalised(key));
  for (const KeySpec& k : scene_schema()) {
    if (k.default_text.empty()) continue;
    EXPECT_TRUE(checked.count(k.path)) << k.path << " has a default no test checks";
  }
}

// A scene that leaves every defaulted key out holds each schema default,
// with the default stage list and with the stages given.
TEST(SceneDefaults, a_scene_without_the_keys_holds_the_schema_defaults) {
  for (const std::string& text : {kTunnel, kTunnel + kStages}) {
    const Scene s = parse_scene(text, "defaults.toml", ".");
    ASSERT_EQ(s.stages.back().kind, "equilibrium");
    for (const auto& [key, get] : number_fields()) {
      const KeySpec& k = spec_of(key);
      const std::string from = default_key(k, key);
      if (k.default_text.empty() || !from.empty()) continue;
      EXPECT_DOUBLE_EQ(get(s), std::stod(k.default_text)) << key << " = " << k.default_text;
    }
    for (const auto& [key, get] : text_fields())
      EXPECT_EQ(get(s), spec_of(key).default_text) << key;
  }
}

// A key whose default is another key's value follows that key: set each
// such key away from its own default, and the key that defaults to it
// follows (the core takes the rock's values, a stage the engine's cap and
// output interval, a residual friction angle the friction angle).
TEST(SceneDefaults, a_default_that_names_a_key_takes_its_value) {
  const std::vector<std::string> sets = {"engine.steps=1234",
                                         "output.every_steps=77",
                                         "materials.rock.density=2500",
                                         "materials.rock.friction_angle=35",
                                         "materials.rock.penalty_factor=20",
                                         "materials.rock.heterogeneity=5",
                                         "materials.rock.heterogeneity_seed=9",
                                         "materials.lining.friction_angle=40",
                                         "tunnel.fracture_zone=1.5",
                                         "joints.friction_angle=40"};
  const auto fields = number_fields();
  int linked = 0;
  for (const std::string& text : {kTunnel, kTunnel + kStages}) {
    const Scene s = parse_scene(text, "linked.toml", ".", sets);
    for (const auto& [key, get] : fields) {
      const std::string from = default_key(spec_of(key), key);
      if (from.empty()) continue;
      ASSERT_TRUE(fields.count(from)) << key << " defaults to " << from;
      const Number& source = fields.at(from);
      EXPECT_EQ(get(s), source(s)) << key << " defaults to " << from;
      // The comparison means something only if the source left its own default.
      const KeySpec& f = spec_of(from);
      if (!f.default_text.empty() && default_key(f, from).empty())
        EXPECT_NE(source(s), std::stod(f.default_text)) << from << " still at its default";
      else
        EXPECT_NE(source(s), 0.0) << from;
      ++linked;
    }
  }
  // the core's 11 keys, 3 residual angles, 2 stage keys, the joints' margin,
  // penalty and residual angle
  EXPECT_EQ(linked, 2 * (11 + 3 + 2 + 3));
}

// The defaults the tunnel above cannot show: a horseshoe opening's size and
// ring, and
// a .msh model's edge groups and fracture group (msh.zones has to be given).
TEST(SceneDefaults, a_horseshoe_and_a_msh_model_hold_their_defaults) {
  const Scene h = parse_scene(
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n",
      "horseshoe.toml", ".");
  EXPECT_EQ(h.mesh.tunnel.shape, mesh::TunnelShape::kHorseshoe);
  EXPECT_EQ(spec_of("tunnel.shape").default_text, "horseshoe");
  EXPECT_EQ(h.mesh.tunnel.span, std::stod(spec_of("tunnel.span").default_text));
  EXPECT_EQ(h.mesh.tunnel.height, std::stod(spec_of("tunnel.height").default_text));
  EXPECT_EQ(h.mesh.tunnel.lining_thickness,
            std::stod(spec_of("tunnel.lining_thickness").default_text));
  EXPECT_EQ(h.mesh.tunnel.invert_rise, std::stod(spec_of("tunnel.invert_rise").default_text));
  // The reader only needs msh.file to be a readable file here.
  const Scene m = parse_scene(
      "[model]\nkind = \"msh\"\n[msh]\nfile = \"scene_defaults_test.cpp\"\n"
      "zones = { Rock = \"rock\" }\n"
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n",
      "msh.toml", ROCKFDEM_TEST_DIR);
  EXPECT_TRUE(m.mesh.msh.edge_groups.empty());
  EXPECT_EQ(spec_of("msh.edges").default_text, "{}");
  EXPECT_EQ("\"" + m.mesh.msh.fracture_group + "\"", spec_of("msh.fracture_group").default_text);
  EXPECT_TRUE(m.mesh.msh.joint_groups.empty());
  EXPECT_EQ(spec_of("msh.joints").default_text, "[]");
}

// A ring's floor part given no values of its own is the ring's: its
// thickness the lining's, every key of [materials.invert] the lining's.
TEST(SceneDefaults, a_floor_part_takes_the_rings_values) {
  const Scene h = parse_scene(
      "[tunnel]\nlining_thickness = 0.3\n"
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[materials.lining]\ndensity = 2300\nyoung = 20e9\npoisson = 0.2\nfriction_angle = 38\n"
      "residual_friction_angle = 33\ntensile_strength = 2e6\ncompressive_strength = 25e6\n"
      "[materials.invert]\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n",
      "invert.toml", ".");
  EXPECT_EQ(spec_of("tunnel.invert_thickness").default_text, "tunnel.lining_thickness");
  EXPECT_EQ(h.mesh.tunnel.invert_thickness, 0.3);
  ASSERT_TRUE(h.invert);
  const MaterialSpec& l = h.materials.at(mesh::kLining);
  const MaterialSpec& i = *h.invert;
  EXPECT_EQ(i.density, 2300);
  EXPECT_EQ(i.young, l.young);
  EXPECT_EQ(i.poisson, l.poisson);
  EXPECT_EQ(i.friction_angle, 38);
  EXPECT_EQ(i.residual_friction_angle, 38);  // its own friction angle, as every material's
  EXPECT_EQ(i.tensile_strength, 2e6);
  EXPECT_EQ(i.compressive_strength, 25e6);
  for (const char* key :
       {"density", "young", "poisson", "friction_angle", "tensile_strength", "compressive_strength",
        "section", "steel_young", "steel_yield_strength", "bar_area", "bar_cover", "set_area",
        "set_inertia", "set_depth", "set_spacing"})
    EXPECT_EQ(spec_of(std::string("materials.invert.") + key).default_text,
              std::string("materials.lining.") + key);
  EXPECT_EQ(i.section.kind, "plain");
  EXPECT_EQ(i.section.steel_young, l.section.steel_young);
}

// The floor part's section follows the lining's, key by key: a reinforced
// ring's invert is reinforced with its bars unless it says otherwise.
TEST(SceneDefaults, a_floor_part_takes_the_rings_section) {
  const std::string ring =
      "[tunnel]\nlining_thickness = 0.3\n"
      "[materials.rock]\nyoung = 5e9\npoisson = 0.25\n"
      "[materials.lining]\nyoung = 20e9\npoisson = 0.2\ncompressive_strength = 25e6\n"
      "section = \"reinforced\"\nsteel_young = 195e9\nsteel_yield_strength = 500e6\n"
      "bar_area = 1.131e-3\nbar_cover = 0.05\n"
      "[insitu]\nsigma_h = 1e6\nsigma_v = 1e6\n"
      "[materials.invert]\n";
  const Scene h = parse_scene(ring, "invert.toml", ".");
  ASSERT_TRUE(h.invert);
  const LiningSectionSpec& i = h.invert->section;
  EXPECT_EQ(i.kind, "reinforced");
  EXPECT_EQ(i.steel_young, 195e9);
  EXPECT_EQ(i.steel_yield_strength, 500e6);
  EXPECT_EQ(i.bar_area, 1.131e-3);
  EXPECT_EQ(i.bar_cover, 0.05);
  const Scene p = parse_scene(ring + "section = \"plain\"\n", "plain_invert.toml", ".");
  EXPECT_EQ(p.invert->section.kind, "plain");
  EXPECT_EQ(p.materials.at(mesh::kLining).section.kind, "reinforced");
}
