// The scene file's keys. To add a key: add one line here (or, for a key
// only a stage reads, in its stage's keys()), read it in scene_build.cpp, and regenerate
// docs/scene-reference.md
// (`rockfdem --scene-reference > docs/scene-reference.md`; a test checks it).
#include "rockfdem/workflows/scene_schema.hpp"

#include <algorithm>
#include <array>
#include <sstream>

#include "rockfdem/mesh/msh_io.hpp"
#include "scene/schema_keys.hpp"
#include "scene/stage_kind.hpp"

namespace rockfdem::workflows {
namespace {
constexpr double kInf = 1e300;
constexpr double kMostDensity = 1e5;  // kg/m^3
}  // namespace

namespace schema {

KeySpec number(std::string path, std::string unit, std::string def, double min, bool min_open,
               double max, bool max_open, std::string what) {
  KeySpec k;
  k.path = std::move(path);
  k.type = KeyType::kNumber;
  k.unit = std::move(unit);
  k.default_text = std::move(def);
  k.min = min;
  k.min_open = min_open;
  k.max = max;
  k.max_open = max_open;
  k.description = std::move(what);
  return k;
}

KeySpec positive(std::string path, std::string unit, std::string def, std::string what) {
  return number(std::move(path), std::move(unit), std::move(def), 0, true, kInf, false,
                std::move(what));
}

KeySpec non_negative(std::string path, std::string unit, std::string def, std::string what) {
  return number(std::move(path), std::move(unit), std::move(def), 0, false, kInf, false,
                std::move(what));
}

KeySpec integer(std::string path, std::string def, double min, double max, std::string what) {
  KeySpec k = number(std::move(path), "-", std::move(def), min, false, max, false, std::move(what));
  k.type = KeyType::kInteger;
  return k;
}

KeySpec choice(std::string path, std::string def, std::vector<std::string> choices,
               std::string what) {
  KeySpec k;
  k.path = std::move(path);
  k.type = KeyType::kChoice;
  k.unit = "-";
  k.default_text = std::move(def);
  k.choices = std::move(choices);
  k.description = std::move(what);
  return k;
}

KeySpec text(std::string path, std::string def, std::string what) {
  KeySpec k;
  k.path = std::move(path);
  k.type = KeyType::kString;
  k.unit = "-";
  k.default_text = std::move(def);
  k.description = std::move(what);
  return k;
}

KeySpec boolean(std::string path, std::string def, std::string what) {
  KeySpec k;
  k.path = std::move(path);
  k.type = KeyType::kBool;
  k.unit = "-";
  k.default_text = std::move(def);
  k.description = std::move(what);
  return k;
}

}  // namespace schema

namespace {

using namespace schema;

// A material's keys. `inherit` ("materials.rock.") makes each default the
// value of that material's key (the core takes the rock's); empty: the
// listed values. The lining is an elastic liner: its triangles share nodes,
// so it has no crack keys, only the friction of its contacts.
void add_material(std::vector<KeySpec>& s, const std::string& name, const std::string& role,
                  const std::string& inherit = "") {
  const std::string p = "materials." + name + ".";
  const bool cracks = name != "lining" && name != "invert";
  const auto def = [&](const char* key, const char* value) {
    return inherit.empty() ? std::string(value) : inherit + key;
  };
  s.push_back(number(p + "density", "kg/m^3", def("density", "2700"), 0, true, kMostDensity, false,
                     "Density of the " + role +
                         ". At most 1e5 kg/m^3, above any material (osmium, the densest "
                         "element, has 22,590): a larger value is a unit slip. Mass scaling "
                         "(engine.mass_scaling) is the engine's, not the density's."));
  s.push_back(
      positive(p + "young", "Pa", def("young", ""), "Young's modulus of the " + role + "."));
  s.push_back(number(p + "poisson", "-", def("poisson", ""), 0, true, 0.45, false,
                     "Poisson's ratio of the " + role +
                         ". At most 0.45: the linear "
                         "(constant-strain) triangles of both stages lock as it nears 0.5 (the "
                         "Kirsch case's stress error: 0.85% at 0.25, 3.8% at 0.45, 16% at 0.49, "
                         "366% at 0.4999)."));
  if (cracks) {
    s.push_back(positive(p + "tensile_strength", "Pa", def("tensile_strength", ""),
                         "Tensile strength ft of the " + role + "'s crack elements."));
    s.push_back(positive(p + "cohesion", "Pa", def("cohesion", ""),
                         "Cohesion c of the " + role + "'s crack elements (Mohr-Coulomb)."));
  }
  s.push_back(number(p + "friction_angle", "deg", def("friction_angle", "30"), 0, false, 90, true,
                     cracks ? "Internal friction angle of the " + role + "'s crack elements."
                            : std::string("Friction angle of the lining's contacts with the "
                                          "rock once their bond ([lining_interface]) has "
                                          "broken (the lining has no crack elements).")));
  // The residual angle follows the material's own friction angle.
  s.push_back(number(p + "residual_friction_angle", "deg", "friction_angle", 0, false, 90, true,
                     "Friction angle of broken cracks and contacts in the " + role + "."));
  if (!cracks) return;
  s.push_back(positive(p + "fracture_energy_I", "J/m^2", def("fracture_energy_I", ""),
                       "Mode I fracture energy GfI of the " + role + "."));
  s.push_back(positive(p + "fracture_energy_II", "J/m^2", def("fracture_energy_II", ""),
                       "Mode II fracture energy GfII of the " + role + "."));
  s.push_back(number(p + "penalty_factor", "-", def("penalty_factor", "10"), 1, false, 1000, false,
                     "Crack and contact penalty as a multiple of the Young's modulus."));
  s.push_back(number(p + "heterogeneity", "-", def("heterogeneity", "0"), 0, false, 100, false,
                     "Weibull modulus m of the " + role +
                         "'s crack strengths: each crack "
                         "element's tensile strength and cohesion are scaled by one factor drawn "
                         "from a Weibull distribution of mean 1 (coefficient of variation 0.36 "
                         "at m = 3, 0.12 at m = 10; clamped to [0.05, 5]); 0: homogeneous. The "
                         "draw depends only on the seed and the element's two mesh vertices, so "
                         "the pattern is the same for any thread count."));
  s.push_back(integer(p + "heterogeneity_seed", def("heterogeneity_seed", "1"), 0, 1e15,
                      "Seed of the " + role + "'s strength heterogeneity."));
}

// A ring part's section for its capacity check (docs/support.md, "Section
// types"): plain, reinforced (two symmetric layers of bars) or steel sets
// in the shotcrete. `inherit` ("materials.lining."): each key defaults to
// that part's (the invert's to the lining's).
void add_section(std::vector<KeySpec>& s, const std::string& name, const std::string& inherit) {
  const std::string p = "materials." + name + ".";
  const auto def = [&](const char* key, const char* value) {
    return inherit.empty() ? std::string(value) : inherit + key;
  };
  const auto required = [&](KeySpec k, const char* where) {
    if (inherit.empty()) k.default_doc = std::string("required with section = ") + where;
    return k;
  };
  s.push_back(choice(p + "section", def("section", "plain"), {"plain", "reinforced", "steel_sets"},
                     "Section of the capacity check: \"plain\" shotcrete (the elastic limit of "
                     "the fibre stresses), \"reinforced\" shotcrete or concrete (two symmetric "
                     "layers of bars: the M-N interaction diagram of EN 1992-1-1's rectangular "
                     "stress block) or \"steel_sets\" embedded in the shotcrete (a composite "
                     "section: thrust and moment shared by stiffness, each part within its "
                     "elastic limit, Carranza-Torres and Diederichs 2009). The model's ring is "
                     "elastic with `young` whatever the section; the section decides only the "
                     "capacity and safety factors (docs/support.md)."));
  s.push_back(positive(p + "steel_young", "Pa", def("steel_young", "200e9"),
                       "Young's modulus of the bars (reinforced) or the steel sets (steel_sets)."));
  s.push_back(required(positive(p + "steel_yield_strength", "Pa", def("steel_yield_strength", ""),
                                "Yield strength fy of the bars or the steel sets (elastic-"
                                "perfectly plastic; e.g. 500e6 for B500 bars, 235e6 to "
                                "355e6 for sets); no partial factor."),
                       "reinforced or steel_sets"));
  s.push_back(required(number(p + "bar_area", "m^2", def("bar_area", ""), 0, true, 0.1, false,
                              "Reinforced: area of the bars per metre of tunnel in EACH of the "
                              "two layers (one near each face), e.g. 1.131e-3 for 12 mm bars "
                              "at 100 mm. At most 0.1 m^2/m (a larger value is a unit slip)."),
                       "reinforced"));
  s.push_back(required(positive(p + "bar_cover", "m", def("bar_cover", ""),
                                "Reinforced: distance from each face to its layer's bar "
                                "centroid; below half the part's thickness."),
                       "reinforced"));
  s.push_back(required(positive(p + "set_area", "m^2", def("set_area", ""),
                                "Steel sets: cross-section area of one set (e.g. 5.43e-3 for "
                                "an HEB 160)."),
                       "steel_sets"));
  s.push_back(required(positive(p + "set_inertia", "m^4", def("set_inertia", ""),
                                "Steel sets: second moment of area of one set about its axis "
                                "of bending in the ring (e.g. 2.492e-5 for an HEB 160 about its "
                                "strong axis)."),
                       "steel_sets"));
  s.push_back(required(positive(p + "set_depth", "m", def("set_depth", ""),
                                "Steel sets: depth of one set through the ring's thickness "
                                "(its extreme fibres at +-depth/2 from the mid-line; at most the "
                                "part's thickness)."),
                       "steel_sets"));
  s.push_back(required(positive(p + "set_spacing", "m", def("set_spacing", ""),
                                "Steel sets: spacing of the sets along the tunnel."),
                       "steel_sets"));
}

// [[monitor]] and [[extensometer]]: history points followed as material
// points of the rock (docs/workflow.md, "Monitors and results").
void add_instruments(std::vector<KeySpec>& s) {
  const std::string naming =
      ": a letter, then letters, digits or '_', at most 40 characters (history.csv's column "
      "names start with it), unique among monitors and extensometers and none of the key "
      "points' names.";
  s.push_back(text("monitor[].name", "", "Name of the monitor" + naming));
  s.push_back(number("monitor[].x", "m", "", -kInf, false, kInf, false,
                     "x of the material point followed (in the rock or the lining, not in the "
                     "excavated core)."));
  s.push_back(number("monitor[].y", "m", "", -kInf, false, kInf, false,
                     "y of the material point followed."));
  s.push_back(boolean("monitor[].relative_to_support", "false",
                      "Read the displacement from the state at the first `lining` or `bolts` "
                      "stage (what a point installed with the support reads; 0 before); "
                      "false: from the in-situ state."));
  s.push_back(text("extensometer[].name", "", "Name of the extensometer" + naming));
  const std::string either = "`from`, or `head` and `direction`";
  KeySpec from = choice(
      "extensometer[].from", "",
      {"vault", "crown", "left_shoulder", "right_shoulder", "left_wall", "right_wall", "invert"},
      "Key point of the opening the head sits at; the extensometer runs along its outward "
      "normal into the rock (`crown` is the vault). Or give `head` and `direction` instead.");
  from.default_doc = either + " required";
  s.push_back(from);
  for (const auto& [key, unit, what] :
       {std::array<std::string, 3>{"head", "m",
                                   "Head (collar) of the extensometer, [x, y], when `from` is "
                                   "not given."},
        {"direction", "-",
         "Direction from the head into the rock, [dx, dy] (any length but 0)."}}) {
    KeySpec k = number("extensometer[]." + key, unit, "", -kInf, false, kInf, false, what);
    k.type = KeyType::kNumberArray;
    k.default_doc = either + " required";
    s.push_back(k);
  }
  s.push_back(
      positive("extensometer[].length", "m", "", "Distance from the head to the deepest anchor."));
  s.push_back(boolean("extensometer[].relative_to_support", "false",
                      "Read the displacements from the state at the first `lining` or `bolts` "
                      "stage (what an extensometer installed with the support reads; 0 "
                      "before); false: from the in-situ state."));
  s.push_back(integer("extensometer[].anchors", "3", 1, 50,
                      "Anchors at equal spacing from the head: anchor k at k length / anchors; "
                      "the deepest is the fixed reference of the readings."));
}

// [joints] and [[joint_set]]: discontinuities the mesh honours and whose
// crack elements take the joint material (docs/meshing.md, "Joints").
void add_joints(std::vector<KeySpec>& s) {
  s.push_back(non_negative("joints.tensile_strength", "Pa", "0",
                           "Tensile strength of the joints' crack elements; 0: a joint opens "
                           "freely and carries no tension."));
  s.push_back(non_negative("joints.cohesion", "Pa", "0",
                           "Cohesion of the joints (Mohr-Coulomb peak: c + sigma tan(phi))."));
  s.push_back(number("joints.friction_angle", "deg", "30", 0, false, 90, true,
                     "Peak friction angle phi of the joints."));
  s.push_back(number("joints.residual_friction_angle", "deg", "friction_angle", 0, false, 90, true,
                     "Residual friction angle phi_r (at most phi): once the slip has taken a "
                     "joint element past its softening range it slides at sigma tan(phi_r), "
                     "and goes on doing so (a joint element never breaks)."));
  s.push_back(positive("joints.fracture_energy_I", "J/m^2", "10",
                       "Mode I fracture energy of the joints (used with a tensile strength)."));
  s.push_back(positive("joints.fracture_energy_II", "J/m^2", "50",
                       "Mode II energy: sets the slip past the peak over which the shear "
                       "strength softens from the peak fp to the residual sigma_n "
                       "tan(residual_friction_angle), fracture_energy_II / (0.386 fp) (0.386: "
                       "the softening curve's integral). fp is the peak at the element's normal "
                       "stress sigma_n, as joints.shear_strength gives it: c + sigma_n "
                       "tan(friction_angle), or with barton_bandis c + sigma_n tan(phi_r + JRC "
                       "log10(JCS / sigma_n)), so there a rougher joint or a lower sigma_n "
                       "softens over a shorter slip. Either way the softening dissipates "
                       "fracture_energy_II per unit area (energy.fracture); the residual "
                       "friction gained meanwhile does work booked as energy.joint_friction."));
  s.push_back(number("joints.penalty_factor", "-", "materials.rock.penalty_factor", 1, false, 1000,
                     false,
                     "Normal and shear penalty (stiffness) of the joints as a multiple of the "
                     "rock's Young's modulus."));
  s.push_back(
      choice("joints.shear_strength", "mohr_coulomb", {"mohr_coulomb", "barton_bandis"},
             "Peak shear strength of the joints: `mohr_coulomb`, c + sigma_n tan(friction_angle); "
             "`barton_bandis`, c + sigma_n tan(phi_r + JRC log10(JCS / sigma_n)) with phi_r the "
             "residual_friction_angle (the basic friction of the walls) and joints.jrc, joints.jcs "
             "(both required), the total angle at most 70 deg (as sigma_n -> 0) and at least phi_r "
             "(sigma_n above JCS), no tension; friction_angle is then unused. Past the peak both "
             "soften to the residual sigma_n tan(phi_r)."));
  KeySpec jrc = number("joints.jrc", "-", "", 0, false, 20, false,
                       "Joint roughness coefficient JRC of Barton and Choubey's profiles "
                       "(shear_strength = \"barton_bandis\"): 0 smooth and planar, 20 very "
                       "rough.");
  jrc.default_doc = "none: required with barton_bandis";
  s.push_back(jrc);
  KeySpec jcs = positive("joints.jcs", "Pa", "",
                         "Joint wall compressive strength JCS (shear_strength = "
                         "\"barton_bandis\"): the intact rock's uniaxial compressive strength "
                         "for fresh walls, less for weathered ones.");
  jcs.default_doc = "none: required with barton_bandis";
  s.push_back(jcs);
  s.push_back(integer("joints.seed", "1", 0, 2147483647,
                      "Seed of the joint sets' random offsets and scatter: the same seed gives "
                      "the same joints, bit for bit."));
  s.push_back(non_negative(
      "joints.margin", "m", "tunnel.fracture_zone",
      "The joint sets fill the opening's bounding box grown by this margin (joints act where "
      "there are crack elements: within tunnel.fracture_zone of the opening)."));
  s.push_back(
      text("joints.dfn_file", "\"\"",
           "Joint traces from a file (a discrete fracture network mapped or generated elsewhere), "
           "relative to the scene file: CSV, one trace per line `x0,y0,x1,y1` in m in the model's "
           "frame (the opening's bounding box centred on the origin); lines starting with `#` and "
           "a header line of names are skipped. Empty: none."));
  s.push_back(number("joint_set[].dip", "deg", "", 0, false, 180, true,
                     "Dip of the set's traces in the section plane, below the horizontal, "
                     "dipping towards +x (90: vertical; above 90: dipping towards -x)."));
  s.push_back(positive("joint_set[].spacing", "m", "",
                       "Spacing of the set's parallel lines, measured across them (at least "
                       "mesh.size_near)."));
  s.push_back(non_negative("joint_set[].trace_length", "m", "0",
                           "Length of each trace; 0: continuous (persistent) joints."));
  s.push_back(number("joint_set[].persistence", "-", "1", 0, true, 1, false,
                     "Fraction of each line the traces cover (the rest is rock bridges); with "
                     "trace_length only."));
  s.push_back(number("joint_set[].dip_scatter", "deg", "0", 0, false, 45, false,
                     "Each line's dip is uniform within +- this of the set's dip."));
  s.push_back(number("joint_set[].spacing_scatter", "-", "0", 0, false, 0.9, false,
                     "Each spacing is uniform within +- this fraction of the set's."));
  s.push_back(number("joint_set[].length_scatter", "-", "0", 0, false, 0.9, false,
                     "Each trace length is uniform within +- this fraction of the set's."));
}

// [references]: figures to compare the run with in report.md (measured
// convergences, another code's answer).
void add_references(std::vector<KeySpec>& s) {
  // No default: a figure not given is not compared.
  const auto figure = [&](const std::string& key, const std::string& what) {
    KeySpec k = number("references." + key, "mm", "", -kInf, false, kInf, false, what);
    k.default_doc = "none";
    s.push_back(k);
  };
  for (const char* point :
       {"vault", "left_shoulder", "right_shoulder", "left_wall", "right_wall", "invert"})
    figure(point, std::string("Reference displacement of the key point ") + point +
                      " (towards the opening positive; read as references.reading says), "
                      "compared with the run's figure in report.md.");
  figure("wall_chord", "Reference closure of the chord between the walls.");
  figure("shoulder_chord", "Reference closure of the chord between the shoulders.");
  s.push_back(choice("references.from", "start", {"start", "support"},
                     "What the references are measured from: the in-situ state (`start`), or "
                     "the first `lining` or `bolts` stage (`support`, as points installed "
                     "with the support read)."));
  s.push_back(choice(
      "references.reading", "radial", {"radial", "survey"},
      "How the key-point references read each point: `radial`, along its ray towards the "
      "opening; `survey`, as convergence monitoring reads it: the vault's settlement and the "
      "invert's heave (vertical), the shoulders' and walls' horizontal convergence (each "
      "point's own, half a symmetric chord's closure). Chords are closures either way."));
  s.push_back(
      text("references.source", "\"\"", "Where the references come from (shown in report.md)."));
}

// The model, its domain and geometry.
void add_model(std::vector<KeySpec>& s) {
  // [model]
  s.push_back(choice("model.kind", "tunnel", {"tunnel", "ucs", "brazilian", "msh"},
                     "What the scene models: a tunnel in a rock domain, a lab specimen, or a "
                     "user's own .msh file."));
  s.push_back(text("model.title", "\"\"", "Free text shown in outputs."));
  s.push_back(choice("model.analysis", "plane_strain", {"plane_strain", "plane_stress"},
                     "Two-dimensional idealisation (unit thickness)."));
  // [domain]
  s.push_back(positive("domain.width", "m", "100", "Width of the rectangular rock domain."));
  s.push_back(positive("domain.height", "m", "100", "Height of the rectangular rock domain."));
  s.push_back(number("domain.center_x", "m", "0", -kInf, false, kInf, false,
                     "Domain centre relative to the opening's centre (x)."));
  s.push_back(number("domain.center_y", "m", "0", -kInf, false, kInf, false,
                     "Domain centre relative to the opening's centre (y)."));
  // [tunnel]
  s.push_back(choice("tunnel.shape", "horseshoe",
                     {"circular", "horseshoe", "arched", "d-shaped", "rectangular"},
                     "Shape of the opening; the opening's bounding box is centred at the origin. "
                     "`d-shaped` is a synonym of `arched`."));
  s.push_back(positive("tunnel.radius", "m", "", "Radius (circular only; required there)."));
  s.push_back(positive("tunnel.span", "m", "11.3", "Width of the opening (not circular)."));
  s.push_back(positive("tunnel.height", "m", "8.8",
                       "Floor-to-crown height of the opening (not circular). Horseshoe: at least "
                       "span/2."));
  s.push_back(positive("tunnel.rise", "m", "",
                       "Arched only (required there): rise of the arch above the walls, at most "
                       "span/2 and below the height."));
  s.push_back(non_negative("tunnel.invert_rise", "m", "0",
                           "Horseshoe and arched only: depth of a curved invert (a circular arc "
                           "through the walls' feet) below them; 0: flat floor. The height is "
                           "then crown to the invert's lowest point."));
  s.push_back(non_negative("tunnel.lining_thickness", "m", "0",
                           "Thickness of the lining ring inside the tunnel boundary; 0: none."));
  s.push_back(non_negative("tunnel.invert_thickness", "m", "tunnel.lining_thickness",
                           "Horseshoe and arched only: thickness of the lining ring's floor part "
                           "(the flat floor or the curved invert, below the walls' feet), e.g. "
                           "a cast invert arch thicker than the shotcrete; its material is "
                           "[materials.invert]."));
  s.push_back(non_negative("tunnel.fracture_zone", "m", "0",
                           "Crack elements are allowed within this distance outside the opening; "
                           "0: elastic rock everywhere."));
  // [specimen]
  s.push_back(positive("specimen.width", "m", "0.05", "UCS specimen width."));
  s.push_back(positive("specimen.height", "m", "0.1", "UCS specimen height."));
  s.push_back(positive("specimen.diameter", "m", "0.05", "Brazilian disc diameter."));
  s.push_back(number("specimen.load_arc_deg", "deg", "10", 0, true, 90, true,
                     "Brazilian disc: angle subtended by each loading arc."));
}

// A user's .msh file, and the mesh generator's settings.
void add_mesh(std::vector<KeySpec>& s) {
  // [msh]
  s.push_back(text("msh.file", "",
                   "User's gmsh .msh file (relative to the scene file); "
                   "required when model.kind = \"msh\"."));
  KeySpec zones;
  zones.path = "msh.zones";
  zones.type = KeyType::kStringMap;
  zones.unit = "-";
  zones.default_text = "{}";
  for (mesh::Zone z : mesh::kZones) zones.choices.push_back(mesh::zone_name(z));
  zones.description = "Map from 2D physical group name to zone, e.g. { Rock = \"rock\" }.";
  s.push_back(zones);
  KeySpec edges = zones;
  edges.path = "msh.edges";
  edges.choices.clear();
  for (mesh::EdgeTag t : mesh::kEdgeTags) edges.choices.push_back(mesh::edge_tag_name(t));
  edges.description = "Map from 1D physical group name to edge tag, e.g. { Floor = \"bottom\" }.";
  s.push_back(edges);
  s.push_back(text("msh.fracture_group", "\"\"",
                   "2D physical group where crack elements are allowed; empty: all rock."));
  KeySpec joints;
  joints.path = "msh.joints";
  joints.type = KeyType::kStringArray;
  joints.unit = "-";
  joints.default_text = "[]";
  joints.description =
      "1D physical groups whose lines are joints, e.g. [\"Fault\", \"Bedding\"]: each curve of "
      "them is a joint trace, and the crack elements on its lines take the [joints] material "
      "(crack elements exist in msh.fracture_group only). Every line must be an interior edge "
      "of the triangles (the curve embedded in the surface).";
  s.push_back(joints);
  // [mesh]
  KeySpec near = positive("mesh.size_near", "m", "0.5",
                          "Element size at the tunnel boundary and in the fracture zone "
                          "(specimens: everywhere); at most half the geometry's smallest "
                          "feature: tunnels, the opening's smaller side (circular: its "
                          "diameter) and 4 x tunnel.lining_thickness; UCS, the specimen's "
                          "smaller side; Brazilian, its diameter. Unused by .msh models.");
  near.default_doc = "0.5 (tunnels); specimens: required";
  s.push_back(near);
  s.push_back(positive("mesh.size_far", "m", "5", "Element size at the outer boundary."));
  s.push_back(non_negative("mesh.grading_distance", "m", "0",
                           "Distance from the tunnel over which the size grows from near to "
                           "far; 0: half the domain's smaller side."));
  KeySpec algo = integer("mesh.algorithm", "5", 1, 9,
                         "gmsh 2D algorithm: 1 MeshAdapt, 5 Delaunay or 6 Frontal-Delaunay; "
                         "gmsh's other numbers in the range are refused (they make no "
                         "triangles fit for this engine, or none at all). 5 is isotropic and "
                         "unstructured; 6 meshes the fracture zone as a near-regular lattice "
                         "(91% of nodes of valence 6) whose lines broken cracks then follow.");
  s.push_back(algo);
}

// The in-situ stress and the implicit stage.
void add_insitu(std::vector<KeySpec>& s) {
  // [insitu]
  // The implicit stage needs compression in both directions (insitu/).
  s.push_back(positive("insitu.sigma_h", "Pa", "",
                       "Horizontal far-field principal stress at the tunnel centre "
                       "(compression positive); required for tunnels and .msh models, unused "
                       "by specimens."));
  s.push_back(positive("insitu.sigma_v", "Pa", "",
                       "Vertical far-field principal stress at the tunnel centre "
                       "(compression positive); required for tunnels and .msh models, unused "
                       "by specimens."));
  s.push_back(number("insitu.angle", "deg", "0", -90, false, 90, false,
                     "Rotation of sigma_h from the x axis, counter-clockwise."));
  s.push_back(non_negative("insitu.unit_weight", "N/m^3", "0",
                           "Stress gradient with depth: both principal stresses grow by "
                           "unit_weight (times sigma_h/sigma_v for the horizontal one) per metre "
                           "below the centre; 0: uniform. With engine.gravity > 0 it is the "
                           "rock's density x gravity (left out: taken as that; given: must be "
                           "that), so the in-situ field holds the weight; `run` refuses a "
                           "gradient without gravity."));
  s.push_back(choice("insitu.boundary", "far_field", {"far_field", "kirsch"},
                     "Loading on the box: the far-field tractions, or exact Kirsch tractions "
                     "(circular tunnel only, for verification)."));
  s.push_back(boolean("insitu.rollers", "true",
                      "Explicit stages: each side of the box is a roller, its normal "
                      "displacement held at the implicit hand-off's (where the box stood in "
                      "equilibrium with the in-situ stress), so the model has no rigid-body "
                      "mode; false: the in-situ tractions alone load the box, as in the "
                      "implicit stage, and the run stops if the outer boundary turns by more "
                      "than 0.01 deg as a rigid body."));
  KeySpec alpha =
      number("insitu.alpha", "-", "[1.0]", 0, false, 1, false,
             "Core softening factors solved implicitly, strictly decreasing in "
             "[0, 1]; 0 removes the core. At most " +
                 std::to_string(kMaxAlphas) + " values: each is a full implicit solve and output.");
  alpha.type = KeyType::kNumberArray;
  s.push_back(alpha);
  s.push_back(choice(
      "insitu.handoff", "last", {"last", "first_crack"},
      "Where the implicit stage hands the core over to the explicit stages. last: at the last "
      "alpha of insitu.alpha. first_crack: walking the list down, at the last alpha before the "
      "first one that loads a crack element beyond its strength (its face's traction from the "
      "implicit stresses against ft and c - sigma_n tan phi), so that no over-stress arrives in "
      "one step; the explicit soften stages continue from there (those at or above it are "
      "skipped). Needs crack elements (tunnel.fracture_zone > 0). summary.json "
      "fdem.handoff gives the strength ratio of every alpha."));
  s.push_back(boolean("insitu.lining_active", "false",
                      "Whether the lining ring carries load during the implicit stage."));
  s.push_back(choice("insitu.solver", "auto", {"auto", "amg", "direct"},
                     "auto: direct for small systems, else AMG-preconditioned CG."));
  s.push_back(number("insitu.tolerance", "-", "1e-8", 0, true, 1e-3, false,
                     "Relative residual of the iterative solver (AMG-CG only: the residual "
                     "over the in-situ nodal forces). The default leaves the fields within "
                     "4e-7 of a converged solve at 420k triangles, far below the mesh's own "
                     "error; each decade smaller costs a few more CG iterations per alpha."));
  s.push_back(choice("insitu.continuum", "elastic", {"elastic", "mohr_coulomb"},
                     "The continuum counterpart a tunnel run is compared with once the core is "
                     "removed (summary continuum_comparison): the elastic stage's sequence, or "
                     "the Mohr-Coulomb elasto-plastic rock (materials.rock cohesion and "
                     "friction_angle) with the in-situ wall traction released in steps."));
  s.push_back(boolean(
      "insitu.continuum_post_peak", "false",
      "Also solve the Mohr-Coulomb continuum with the FDEM's post-peak strength once the core "
      "is removed: the rock's c and phi until it yields, then c = 0 and phi = "
      "residual_friction_angle (elastic-brittle-plastic, as a broken crack element keeps "
      "friction only). Its verdict, summary.json continuum_post_peak (equilibrium or not, and "
      "why), judges whether the ground itself can stand on the run's support. Costly where it "
      "cannot: failing Newton steps (about 40 s on a 3 m tunnel at h = 0.3 m)."));
  s.push_back(number("insitu.dilation_angle", "deg", "0", 0, false, 90, true,
                     "Mohr-Coulomb continuum: the rock's dilation angle psi (0: no volume "
                     "change in plastic flow; at most materials.rock.friction_angle)."));
  s.push_back(number(
      "insitu.install_at_face_distance", "m", "", 0, false, 1000, false,
      "Convergence-confinement: the support goes in this far behind the face. The "
      "longitudinal displacement profile (Vlachopoulos and Diederichs 2009, with Salencon's "
      "plastic radius of the equivalent circular opening) turns it into the fraction u* of the "
      "final wall displacement, and the implicit stage's ground reaction curve into the core's "
      "alpha at which the wall has moved that much; the implicit stage then hands over at that "
      "alpha, where the support stages install (summary.json "
      "convergence_confinement.installation). Needs a lining or bolts stage with no soften "
      "stage before it, insitu.handoff = \"last\" and insitu.lining_active = false. Left "
      "out: the support goes in at the last alpha of insitu.alpha."));
}

// The explicit engine, and the platens of specimen tests.
void add_engine(std::vector<KeySpec>& s) {
  // [engine]
  s.push_back(integer("engine.steps", "10000", 1, 1e12,
                      "Explicit steps of a specimen run (tunnels: the cap of each stage)."));
  s.push_back(non_negative("engine.dt", "s", "0",
                           "Time step; 0: dt_safety times the computed stability limit. A value "
                           "above the limit is refused."));
  s.push_back(number("engine.dt_safety", "-", "0.8", 0, true, 1, false,
                     "Fraction of the computed critical time step used when engine.dt = 0."));
  s.push_back(number("engine.damping_ratio", "-", "0.1", 0, false, 2, false,
                     "Viscous damping of the triangles, a multiple of Munjiza's element "
                     "viscosity eta = 2 h sqrt(E rho) (h: smallest altitude); the stiffest "
                     "element mode then has 1.7-1.8 times this ratio of critical damping."));
  std::ostringstream tunnel_local;  // one value for tunnels, none for specimens: no one default
  tunnel_local << kTunnelLocalDamping;
  KeySpec local = number("engine.local_damping", "-", "", 0, false, 1, true,
                         "Cundall local damping coefficient: f -= alpha |f| sign(v) per node "
                         "component. Tunnel stages are quasi-static and take " +
                             tunnel_local.str() +
                             " unless given (0 runs them undamped but for the triangles' "
                             "viscosity); specimen runs take 0. The summary's `damping` entry "
                             "shows the value used.");
  local.default_doc = tunnel_local.str() + " (tunnel stages), 0 (specimens)";
  s.push_back(local);
  s.push_back(boolean("engine.kinetic_damping", "false",
                      "Cundall's kinetic damping in tunnel stages: every node's velocity is "
                      "set to zero (at the step's midpoint) whenever the total kinetic energy "
                      "passes a peak; combined with engine.local_damping (then best about "
                      "0.3) it reaches equilibrium in fewer steps. The statics do not change."));
  s.push_back(non_negative("engine.mass_damping", "1/s", "0",
                           "Mass-proportional damping coefficient c (force -c m v)."));
  s.push_back(
      choice("engine.mass_scaling", "auto", {"auto", "on", "off"},
             "Quasi-static mass scaling: densities raised until every node is stable "
             "at the least constrained node's step (statics unchanged, dynamics and "
             "simulated time not physical). auto: on for tunnels (and .msh models), off for "
             "UCS and Brazilian specimens."));
  s.push_back(non_negative("engine.mass_scaling_dt", "s", "0",
                           "Target step of the mass scaling before local damping (which divides "
                           "it by sqrt(1 + local_damping)) and dt_safety; 0: the least "
                           "constrained node's stability limit."));
  s.push_back(non_negative("engine.gravity", "m/s^2", "0",
                           "Gravitational acceleration acting in -y; 0: none. In a tunnel or "
                           ".msh model the explicit stages apply the weight rho g (a softened "
                           "core alpha of it) and the in-situ field grows with depth by the "
                           "rock's rho g below the centre, where sigma_h and sigma_v hold; it "
                           "needs insitu.rollers and angle 0."));
  // The stages' own keys ([loading]: stage_load_platens.cpp).
  for (const std::string& kind : stage_kinds())
    for (KeySpec& k : stage_kind(kind).keys()) s.push_back(std::move(k));
}

// The steel of bolts and cables; the grout and lining-rock bonds.
void add_support(std::vector<KeySpec>& s) {
  // [bolts] and [cables]: the steel each kind of bolt shares. Cables are
  // long bolts of strand (the seed's simplification), here 15.2 mm 7-wire
  // strand Y1860S7 (EN 10138-3): 0.1% proof 1600 MPa, 1860 MPa at 3.5%.
  struct SteelDefaults {
    const char *section, *what, *diameter, *young, *yield, *ultimate, *tangent, *shear;
  };
  for (const SteelDefaults& k :
       {SteelDefaults{"bolts", "Bolt", "0.025", "200e9", "400e6", "500e6", "2e9", "240e6"},
        SteelDefaults{"cables", "Cable", "0.0152", "195e9", "1600e6", "1860e6", "9.7e9",
                      "960e6"}}) {
    const std::string p = std::string(k.section) + ".";
    s.push_back(positive(p + "diameter", "m", k.diameter, std::string(k.what) + " diameter."));
    s.push_back(positive(p + "row_spacing", "m", "1",
                         "Out-of-plane spacing of rows s_b (stiffness and strength scale by "
                         "1/s_b)."));
    s.push_back(positive(p + "young", "Pa", k.young, "Steel Young's modulus Eb."));
    s.push_back(positive(p + "yield_strength", "Pa", k.yield, "Steel yield strength."));
    s.push_back(positive(p + "ultimate_strength", "Pa", k.ultimate,
                         "Steel ultimate strength (above the yield strength)."));
    s.push_back(positive(p + "tangent_modulus", "Pa", k.tangent,
                         "Hardening modulus ET (below the steel's Young's modulus)."));
    s.push_back(positive(p + "shear_yield_strength", "Pa", k.shear,
                         "Steel shear strength (brittle in shear)."));
    s.push_back(
        positive(p + "shear_fracture_energy", "J/m^2", "1e4", "Steel shear fracture energy GfII."));
    if (p == "bolts.")
      s.push_back(choice(
          "bolts.install_stress", "free", {"free", "current"},
          "Stress of the bolt and cable strips when the `bolts` stage installs them: `free`, "
          "stress-free in their installed shape (the rock they replace unloads into its "
          "surroundings); `current`, the stress the rock there carries (strain counted from "
          "the installed shape), their steel and grout crack elements carrying the tractions "
          "its cracks carried: the installation changes no stress and no force. Bolt "
          "outputs count from the installation either way."));
  }
  // [grout] (the bolt-rock bond and what re-joins broken cracks) and
  // [lining_interface] (the shotcrete-rock bond: adhesion 0.1-1.3 MPa measured
  // in situ, Malmgren, Nordlund and Rolund 2005, TUST 20:33-48).
  struct BondDefaults {
    const char *section, *what, *young, *ft, *c, *phi, *gf1, *gf2;
  };
  for (const BondDefaults& k :
       {BondDefaults{"grout", "Grout", "10e9", "1e6", "2e6", "30", "20", "100"},
        BondDefaults{"lining_interface", "Shotcrete-rock bond", "5e8", "0.5e6", "1e6", "35", "10",
                     "50"}}) {
    const std::string p = std::string(k.section) + ".", what = k.what;
    s.push_back(positive(p + "young", "Pa", k.young,
                         what + ": modulus setting its crack penalty (penalty_factor x young)."));
    s.push_back(positive(p + "tensile_strength", "Pa", k.ft, what + ": tensile strength."));
    s.push_back(positive(p + "cohesion", "Pa", k.c, what + ": cohesion."));
    s.push_back(
        number(p + "friction_angle", "deg", k.phi, 0, false, 90, true, what + ": friction angle."));
    s.push_back(
        positive(p + "fracture_energy_I", "J/m^2", k.gf1, what + ": mode I fracture energy."));
    s.push_back(
        positive(p + "fracture_energy_II", "J/m^2", k.gf2, what + ": mode II fracture energy."));
  }
}

// Where the bolts are: one by one, or as fans.
void add_bolts(std::vector<KeySpec>& s) {
  // [[bolt]] and [[bolt_fan]]
  KeySpec point = number("bolt[].start", "m", "", -kInf, false, kInf, false,
                         "Head (collar) of the bolt, [x, y]: on the excavation boundary or in "
                         "the lining, within max(mesh.size_near / 2, 5 cm); a bolt running "
                         "through the opening or out of the domain is refused.");
  point.type = KeyType::kNumberArray;
  s.push_back(point);
  point.path = "bolt[].end";
  point.description = "End of the bolt in the rock, [x, y].";
  s.push_back(point);
  const KeySpec kind = choice("bolt[].kind", "bolt", {"bolt", "cable"},
                              "`bolt` takes the steel of [bolts], `cable` that of [cables].");
  s.push_back(kind);
  point.path = "bolt_fan[].centre";
  point.default_text = "[0.0, 0.0]";
  point.description = "Centre of the circle the bolt heads lie on, [x, y].";
  s.push_back(point);
  s.push_back(positive("bolt_fan[].radius", "m", "",
                       "Radius of the heads' circle; each head is checked as bolt[].start."));
  s.push_back(number("bolt_fan[].first_deg", "deg", "0", -360, false, 360, false,
                     "Angle of the first bolt, counter-clockwise from +x."));
  s.push_back(number("bolt_fan[].last_deg", "deg", "180", -360, false, 360, false,
                     "Angle of the last bolt."));
  s.push_back(integer("bolt_fan[].count", "", 1, 1000, "Number of bolts in the fan."));
  s.push_back(positive("bolt_fan[].length", "m", "", "Bolt length."));
  KeySpec fan_kind = kind;
  fan_kind.path = "bolt_fan[].kind";
  s.push_back(fan_kind);
}

void add_contact(std::vector<KeySpec>& s) {
  // [contact]
  s.push_back(boolean("contact.enabled", "true",
                      "Penalty contact with friction between triangles on free surfaces and "
                      "next to broken cracks; costs nothing while nothing can touch."));
  s.push_back(number("contact.penalty_factor", "-", "1", 0.1, false, 10, false,
                     "Contact penalty as a multiple of the rock's Young's modulus. At most "
                     "10: where contact takes over a compressed broken crack its overlap "
                     "energy is booked against fracture, and a penalty far stiffer than "
                     "the crack's creates energy there (factor 100: 12 MJ/m in the default "
                     "tunnel; 1000: the run blew up)."));
  s.push_back(number("contact.damping_ratio", "-", "0", 0, false, 1, false,
                     "Normal contact damping as a fraction of critical."));
  s.push_back(boolean("contact.friction", "true",
                      "Coulomb friction with mu = tan(residual_friction_angle)."));
}

void add_stages(std::vector<KeySpec>& s) {
  // [[stages]]
  std::vector<std::string> kinds = stage_kinds();  // the registered stages (stages/)
  kinds.insert(kinds.begin(), "insitu");
  s.push_back(choice("stages[].kind", "", kinds,
                     "Construction stage: `insitu` (the implicit stage, first if given), " +
                         stage_kind_descriptions() +
                         ". Without [[stages]]: insitu, "
                         "lining (if the model has a ring not already active in the implicit "
                         "stage), bolts (if the scene has any), remove_core, equilibrium; UCS and "
                         "Brazilian specimens (which take no [[stages]]): load_platens. At "
                         "most " +
                         std::to_string(kMaxStages) + " entries."));
  s.push_back(integer("stages[].max_steps", "engine.steps", 0, 1e12,
                      "Explicit steps at most in this stage."));
  s.push_back(number("stages[].ratio", "-", "1e-3", 0, true, 1, false,
                     "Equilibrium: stop when the unbalanced-force ratio falls below this (and "
                     "the monitors have settled, see settle)."));
  s.push_back(number("stages[].settle", "-", "1e-3", 0, false, 1, false,
                     "Equilibrium also needs the monitors settled: the largest monitor "
                     "displacement change over the last output interval, per 1000 steps, at "
                     "most this fraction of the largest monitor displacement; 0: the ratio "
                     "alone."));
  s.push_back(number("stages[].broken_settle", "-", "0", 0, false, 1, false,
                     "Equilibrium also needs the broken count settled: its growth over the "
                     "last output interval, per 1000 steps, at most this fraction of the "
                     "broken crack elements (all kinds); 0: not checked. Key points can "
                     "settle while cracks still break away from them."));
  s.push_back(integer("stages[].hold", "2", 1, 1000,
                      "Equilibrium: ratio and settle must both hold at this many consecutive "
                      "outputs (a ratio met once on the way to a collapse is no equilibrium)."));
  s.push_back(number("stages[].unstable_fraction", "-", "0.05", 0, true, 1, false,
                     "A monitor displaced by more than this fraction of the opening's span "
                     "stops the run as `unstable`: 0.05 of the span is a radial strain of "
                     "10% on a round opening, the threshold of extreme squeezing (Hoek and "
                     "Marinos 2000)."));
  s.push_back(boolean("stages[].stop_when_unstable", "true",
                      "Whether the run stops where the opening is found unstable; false runs "
                      "on to the stage's cap (to watch the collapse), the status staying "
                      "`unstable` with the first finding."));
  s.push_back(non_negative("stages[].time", "s", "0",
                           "Stop after this much simulated time in the stage (pseudo-time when "
                           "engine.mass_scaling is on, as it is for tunnels by default: prefer "
                           "max_steps then); 0: no limit."));
  s.push_back(integer("stages[].every_steps", "output.every_steps", 1, 1e9,
                      "Steps between outputs in this stage."));
  // The keys one kind alone reads (stage_soften.cpp, stage_grout.cpp, ...).
  for (const std::string& kind : stage_kinds())
    for (KeySpec& k : stage_kind(kind).entry_keys()) s.push_back(std::move(k));
}

void add_output(std::vector<KeySpec>& s) {
  // [output]
  s.push_back(integer("output.every_steps", "1000", 1, 1e9,
                      "Explicit steps between outputs (VTK frames, history rows)."));
  s.push_back(boolean("output.vtk", "true", "Write ParaView files."));
  s.push_back(boolean("output.plots", "true", "Render PNG plots (needs a display or Xvfb)."));
  s.push_back(integer("output.checkpoint_every", "0", 0, 1e12,
                      "Steps between checkpoints (written at the next output step); 0: none. "
                      "`--checkpoint-every` overrides it."));
  s.push_back(choice("output.convergence_from", "support", {"support", "start"},
                     "Origin of convergence.png and chord_convergence.png: `support`, the "
                     "state at the first `lining` or `bolts` stage (what points installed "
                     "with the support measure; the in-situ state where the scene installs "
                     "none); `start`, the in-situ state (the implicit deconfinement "
                     "included). The axis label names it."));
}

// [materials.rock] gsi, disturbance, hoek_brown_mi: from lab to rock mass.
void add_rock_mass(std::vector<KeySpec>& s) {
  KeySpec gsi =
      number("materials.rock.gsi", "-", "", 10, false, 100, false,
             "Geological Strength Index of the rock mass (tunnels). Given, the section's young, "
             "cohesion, friction_angle and tensile_strength are the intact rock's laboratory "
             "figures, and the model's rock (and the core, for each key it does not give) is the "
             "rock mass derived from them (docs/workflow.md, \"From the laboratory to the rock "
             "mass\"): E by Hoek and Diederichs (2006); c, phi by the generalised Hoek-Brown "
             "criterion's Mohr-Coulomb fit for tunnels (Hoek, Carranza-Torres and Corkum 2002), "
             "with sigma_ci the lab set's Mohr-Coulomb UCS and insitu.sigma_v as the overburden "
             "stress; ft = s sigma_ci / mb; the residual friction angle at most the mass's phi; "
             "the fracture energies as given. 100: intact rock.");
  gsi.default_doc = "none: the section is the model's rock";
  s.push_back(gsi);
  s.push_back(number("materials.rock.disturbance", "-", "0", 0, false, 1, false,
                     "Disturbance factor D of the rock mass (with gsi): 0 for careful "
                     "excavation (a TBM, smooth blasting), up to 1 for heavy blast damage "
                     "(Hoek, Carranza-Torres and Corkum 2002)."));
  s.push_back(number("materials.rock.hoek_brown_mi", "-", "", 1, false, 50, false,
                     "Hoek-Brown constant mi of the intact rock (with gsi, required): about 4 "
                     "for claystone, 7 for shale, 10 for marl and siltstone, 17 for sandstone, "
                     "32 for granite (Hoek's table)."));
  KeySpec ratio =
      number("materials.rock.mass_ft_over_ucs", "-", "", 0, true, 0.5, false,
             "The rock mass's tensile strength as a fraction of its Mohr-Coulomb UCS (with gsi), "
             "instead of Hoek-Brown's s sigma_ci / mb, which falls below any intact rock's ratio "
             "as GSI falls (at GSI 45: UCS / 24 for mi 4, UCS / 94 for mi 10): e.g. the lab's "
             "measured ft / UCS, so that the mass keeps the intact rock's ratio while both "
             "strengths fall with GSI.");
  ratio.default_doc = "none: ft = s sigma_ci / mb";
  s.push_back(ratio);
}

std::vector<KeySpec> build_schema() {
  std::vector<KeySpec> s;
  add_model(s);
  add_mesh(s);
  // [materials.*]
  add_material(s, "rock", "host rock (or the specimen)");
  add_rock_mass(s);
  add_material(s, "core", "excavation core (defaults to the rock's values)", "materials.rock.");
  add_material(s, "lining", "shotcrete lining");
  s.push_back(positive("materials.lining.tensile_strength", "Pa", "",
                       "Tensile strength of the shotcrete for the lining's capacity check "
                       "(the lining is an elastic liner: its triangles share nodes, it has no "
                       "crack elements; what breaks is the lining-rock bond, "
                       "[lining_interface])."));
  KeySpec fc = positive("materials.lining.compressive_strength", "Pa", "",
                        "Uniaxial compressive strength of the shotcrete for the lining's "
                        "capacity check (docs/support.md): each segment's thrust and moment "
                        "against the plain section's elastic limit, with tensile_strength as "
                        "the tensile limit (0 when not given: no tension); not given: no check.");
  fc.default_doc = "none: no capacity check";
  s.push_back(fc);
  add_section(s, "lining", "");
  add_material(s, "invert",
               "lining ring's floor part (an invert arch, e.g. cast concrete under a shotcrete "
               "arch; horseshoe and arched openings; the whole section defaults to "
               "[materials.lining])",
               "materials.lining.");
  s.push_back(positive("materials.invert.tensile_strength", "Pa",
                       "materials.lining.tensile_strength",
                       "Tensile strength of the invert's section for the ring's capacity check."));
  KeySpec fci = positive("materials.invert.compressive_strength", "Pa",
                         "materials.lining.compressive_strength",
                         "Uniaxial compressive strength of the invert's section for the ring's "
                         "capacity check (segments of the floor part; needs "
                         "materials.lining.compressive_strength).");
  s.push_back(fci);
  add_section(s, "invert", "materials.lining.");
  add_insitu(s);
  add_engine(s);
  add_support(s);
  add_bolts(s);
  add_instruments(s);
  add_contact(s);
  add_joints(s);
  add_stages(s);
  add_output(s);
  add_references(s);
  return s;
}

std::string section_of(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

}  // namespace

const std::vector<KeySpec>& scene_schema() {
  static const std::vector<KeySpec> schema = build_schema();
  return schema;
}

const KeySpec* find_key(const std::string& path) {
  for (const KeySpec& k : scene_schema())
    if (k.path == path) return &k;
  return nullptr;
}

std::string default_key(const KeySpec& k, const std::string& path) {
  if (k.default_text.empty()) return "";
  if (find_key(k.default_text)) return k.default_text;
  if (find_key(section_of(k.path) + "." + k.default_text))
    return section_of(path) + "." + k.default_text;
  return "";
}

bool is_known_section(const std::string& section) {
  for (const KeySpec& k : scene_schema()) {
    const std::string s = section_of(k.path);
    if (s == section || s.rfind(section + ".", 0) == 0) return true;
  }
  return false;
}

std::vector<std::string> keys_in_section(const std::string& section) {
  std::vector<std::string> keys;
  for (const KeySpec& k : scene_schema())
    if (section_of(k.path) == section) keys.push_back(k.path.substr(section.size() + 1));
  return keys;
}

std::string describe_allowed(const KeySpec& k) {
  std::ostringstream out;
  out.precision(12);
  switch (k.type) {
    case KeyType::kBool:
      return "true or false";
    case KeyType::kString:
      return "a string";
    case KeyType::kStringArray:
      return "an array of strings";
    case KeyType::kChoice:
    case KeyType::kStringMap: {
      out << (k.type == KeyType::kStringMap ? "a table of strings, each one of " : "one of ");
      for (std::size_t i = 0; i < k.choices.size(); ++i)
        out << (i ? ", " : "") << '"' << k.choices[i] << '"';
      return out.str();
    }
    default:
      break;
  }
  if (k.type == KeyType::kInteger) out << "an integer ";
  if (k.type == KeyType::kNumberArray) out << "an array of numbers each ";
  const bool lo = k.min > -kInf, hi = k.max < kInf;
  if (lo && hi) {
    out << "in " << (k.min_open ? "(" : "[") << k.min << ", " << k.max << (k.max_open ? ")" : "]");
  } else if (lo) {
    out << (k.min_open ? "> " : ">= ") << k.min;
  } else if (hi) {
    out << (k.max_open ? "< " : "<= ") << k.max;
  } else {
    out << "any finite number";
  }
  if (!k.unit.empty() && k.unit != "-") out << " (" << k.unit << ")";
  return out.str();
}

std::string scene_reference_markdown() {
  std::ostringstream md;
  md << "# Scene file reference\n\n"
        "Generated by `rockfdem --scene-reference` from the schema in "
        "`workflows/src/scene/scene_schema.cpp`; a test keeps this page equal to it.\n\n"
        "A scene is one TOML file. Units are SI (m, Pa, kg, s, J); angles in degrees; "
        "stresses compression positive in `[insitu]`. Unknown keys, wrong types and values "
        "out of range are errors (exit code 2) naming the file, the key, the value and what "
        "is allowed. Any key can be overridden on the command line with "
        "`--set section.key=value`.\n";
  std::string current;
  for (const KeySpec& k : scene_schema()) {
    const std::string section = section_of(k.path);
    if (section != current) {
      current = section;
      md << "\n## [" << section
         << "]\n\n| key | unit | default | allowed | meaning |\n"
            "|---|---|---|---|---|\n";
    }
    const std::string def = !k.default_doc.empty()   ? k.default_doc
                            : k.default_text.empty() ? "required where used"
                                                     : k.default_text;
    md << "| `" << k.path.substr(section.size() + 1) << "` | " << k.unit << " | " << def << " | "
       << describe_allowed(k) << " | " << k.description << " |\n";
  }
  return md.str();
}

}  // namespace rockfdem::workflows
