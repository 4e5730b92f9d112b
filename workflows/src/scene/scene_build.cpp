// From a schema-checked TOML tree to the typed Scene, with defaults and the
// checks that involve several keys (tunnel inside the domain, a material for
// every zone, decreasing alpha, ...).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

#include "rockfdem/error.hpp"
#include "rockfdem/mesh/joints.hpp"
#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/mesh/outline.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/scene_schema.hpp"
#include "scene/dfn_file.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_reader.hpp"
#include "scene/stage_kind.hpp"

namespace rockfdem::workflows {
namespace {

using detail::BoltPlacement;
using detail::fail_key;
using detail::RawScene;

std::string num(double v) { return detail::number_text(v); }

// Typed reads of validated keys; absent keys take the schema's default (a
// value, or another key's value), the only defaults there are.
class Reader {
 public:
  explicit Reader(const RawScene& raw) : raw_(raw) {}

  const toml::node* node(const std::string& path) const { return raw_.root.at_path(path).node(); }
  bool has(const std::string& path) const { return node(path) != nullptr; }

  /// A key with a default in the schema, or one required before it is read.
  double number(const std::string& path) const {
    if (const std::optional<double> v = lookup(path)) return *v;
    throw std::logic_error("scene key without a default read as if it had one: " + path);
  }
  /// A key without a default: `neutral` ("not given") where the file has none.
  double number_or(const std::string& path, double neutral) const {
    return lookup(path).value_or(neutral);
  }
  int integer(const std::string& path) const { return int(number(path)); }
  bool boolean(const std::string& path) const {
    if (const toml::node* n = node(path)) return n->as_boolean()->get();
    return spec(path).default_text == "true";
  }
  std::string text(const std::string& path) const {
    if (const toml::node* n = node(path)) return n->as_string()->get();
    const std::string from = default_key(spec(path), path);
    if (!from.empty()) return text(from);
    std::string d = spec(path).default_text;
    return d == "\"\"" ? std::string() : d;
  }
  std::vector<double> numbers(const std::string& path) const {
    std::vector<double> out;
    const std::string& def = spec(path).default_text;
    const toml::table parsed = has(path) || def.empty() ? toml::table{} : toml::parse("v = " + def);
    const toml::node* n = has(path) ? node(path) : parsed.get("v");
    if (n)
      for (auto&& v : *n->as_array()) out.push_back(as_number(v));
    return out;
  }
  std::vector<std::string> strings(const std::string& path) const {
    std::vector<std::string> out;
    if (const toml::node* n = node(path))
      for (auto&& v : *n->as_array()) out.push_back(v.as_string()->get());
    return out;
  }
  std::map<std::string, std::string> string_map(const std::string& path) const {
    std::map<std::string, std::string> out;
    if (const toml::node* n = node(path))
      for (auto&& [k, v] : *n->as_table()) out[std::string(k.str())] = v.as_string()->get();
    return out;
  }
  /// Requires a key that has no default in this context.
  void require(const std::string& path, const std::string& why) const {
    if (!has(path))
      throw InputError(raw_.source + ": missing key '" + path + "' (" + why +
                       "); allowed: " + describe_allowed(spec(path)));
  }
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    fail_key(raw_, path, node(path), problem);
  }
  /// Whether the user changed `path` with --set.
  bool changed(const std::string& path) const { return detail::from_command_line(raw_, path); }
  /// A check between two keys blames `second` when only it came from --set:
  /// the key the user just changed is the one to name.
  bool blame_second(const std::string& first, const std::string& second) const {
    return changed(second) && !changed(first);
  }
  const std::string& source() const { return raw_.source; }
  const RawScene& raw() const { return raw_; }
  /// The key whose value `path` holds: itself where the file gives it,
  /// else the key its default names, followed (the invert's the lining's).
  std::string given_at(const std::string& path) const {
    if (has(path)) return path;
    const std::string from = default_key(spec(path), path);
    return from.empty() ? path : given_at(from);
  }

 private:
  static const KeySpec& spec(const std::string& path) {
    const KeySpec* k = find_key(detail::normalise(path));
    if (!k) throw std::logic_error("scene key not in schema: " + path);
    return *k;
  }
  static double as_number(const toml::node& n) {
    return n.is_integer() ? double(n.as_integer()->get()) : n.as_floating_point()->get();
  }
  // The file's value, else the schema's default; nullopt where neither is.
  std::optional<double> lookup(const std::string& path) const {
    if (const toml::node* n = node(path)) return as_number(*n);
    const KeySpec& k = spec(path);
    const std::string from = default_key(k, path);
    if (!from.empty()) return lookup(from);
    if (k.default_text.empty()) return std::nullopt;
    return std::stod(k.default_text);
  }
  const RawScene& raw_;
};

void read_references(const Reader& r, ReferenceSettings& ref) {
  for (const char* name : {"vault", "left_shoulder", "right_shoulder", "left_wall", "right_wall",
                           "invert", "wall_chord", "shoulder_chord"})
    if (r.has(std::string("references.") + name))
      ref.mm[name] = r.number(std::string("references.") + name);
  ref.from_support = r.text("references.from") == "support";
  ref.survey = r.text("references.reading") == "survey";
  ref.source = r.text("references.source");
}

mesh::TunnelShape tunnel_shape(const std::string& s) {
  if (s == "circular") return mesh::TunnelShape::kCircular;
  if (s == "horseshoe") return mesh::TunnelShape::kHorseshoe;
  if (s == "rectangular") return mesh::TunnelShape::kRectangular;
  return mesh::TunnelShape::kArched;  // "arched" and "d-shaped"
}

// The key to name when the opening does not fit the domain: the one the
// user changed with --set (the opening's size, the fracture zone or the
// domain's centre), else the domain's size where the file gives it.
std::string outside_key(const Reader& r, const std::string& domain, const std::string& tunnel,
                        const std::string& center) {
  for (const std::string& k : {tunnel, std::string("tunnel.fracture_zone"), center})
    if (r.blame_second(domain, k)) return k;
  return r.has(domain) || r.changed(domain) ? domain : tunnel;
}

// An arched opening's rise: at most span/2 and below the height.
void read_arch_rise(const Reader& r, mesh::TunnelSpec& t) {
  const double w = t.span, h = t.height;
  r.require("tunnel.rise", "tunnel.shape is \"arched\"");
  t.rise = r.number("tunnel.rise");
  if (t.rise <= w / 2 && t.rise < h) return;
  const char* other = t.rise > w / 2 ? "tunnel.span" : "tunnel.height";
  if (r.blame_second("tunnel.rise", other))
    r.fail(other, std::string("leaves the arch's rise (tunnel.rise = ") + num(t.rise) +
                      " m) above " + (t.rise > w / 2 ? "span/2" : "the height") + "; allowed: " +
                      (t.rise > w / 2 ? "at least " + num(2 * t.rise) : "above " + num(t.rise)) +
                      " m");
  r.fail("tunnel.rise",
         "must be at most span/2 = " + num(w / 2) + " m and below the height " + num(h) + " m");
}

// A curved invert: horseshoe and arched openings only; its rise at most
// span/2 and, with the arch's, within the height (the walls keep a length).
void read_invert(const Reader& r, mesh::TunnelSpec& t) {
  t.invert_rise = r.number("tunnel.invert_rise");
  if (t.invert_rise == 0) return;
  const bool arched =
      t.shape == mesh::TunnelShape::kHorseshoe || t.shape == mesh::TunnelShape::kArched;
  if (!arched)
    r.fail("tunnel.invert_rise", "applies to horseshoe and arched openings only; allowed: 0 here");
  const double arch = t.shape == mesh::TunnelShape::kHorseshoe ? t.span / 2 : t.rise;
  if (t.invert_rise > t.span / 2)
    r.fail("tunnel.invert_rise", "must be at most span/2 = " + num(t.span / 2) + " m");
  if (arch + t.invert_rise > t.height) {
    const double room = std::floor((t.height - arch) * 1000 + 1e-6) / 1000;  // to the mm
    r.fail("tunnel.invert_rise", "plus the arch's rise (" + num(arch) + " m) exceeds the height " +
                                     num(t.height) + " m; allowed: at most " + num(room) + " m");
  }
  if (t.lining_thickness >= t.invert_rise)
    r.fail("tunnel.invert_rise",
           "must exceed the lining thickness " + num(t.lining_thickness) + " m");
}

bool has_floor(const mesh::TunnelSpec& t) {
  return t.shape == mesh::TunnelShape::kHorseshoe || t.shape == mesh::TunnelShape::kArched;
}

// The ring's floor part: as thick as the rest unless the scene says, and
// only where there is a floor and a ring.
void read_invert_thickness(const Reader& r, mesh::TunnelSpec& t) {
  t.invert_thickness = r.number("tunnel.invert_thickness");
  if (t.invert_thickness == t.lining_thickness) return;
  if (!has_floor(t) || !(t.lining_thickness > 0))
    r.fail("tunnel.invert_thickness",
           "applies to the lining ring's floor part of a horseshoe or arched opening with "
           "tunnel.lining_thickness > 0; allowed here: tunnel.lining_thickness (" +
               num(t.lining_thickness) + " m)");
  if (!(t.invert_thickness > 0))
    r.fail("tunnel.invert_thickness", "allowed: > 0 where there is a ring");
  if (t.invert_rise > 0 && t.invert_thickness >= t.invert_rise)
    r.fail("tunnel.invert_thickness",
           "must be below tunnel.invert_rise (" + num(t.invert_rise) + " m)");
  try {
    mesh::lining_inner_outline(t);
  } catch (const InputError& e) {
    r.fail("tunnel.invert_thickness", std::string(e.what()) + "; allowed: a thinner invert");
  }
}

void read_tunnel(const Reader& r, mesh::MeshSpec& m) {
  mesh::TunnelSpec& t = m.tunnel;
  t.shape = tunnel_shape(r.text("tunnel.shape"));
  t.lining_thickness = r.number("tunnel.lining_thickness");
  t.fracture_zone = r.number("tunnel.fracture_zone");
  double w = 0, h = 0;
  const bool circular = t.shape == mesh::TunnelShape::kCircular;
  if (circular) {
    r.require("tunnel.radius", "tunnel.shape is \"circular\"");
    t.radius = r.number("tunnel.radius");
    w = h = 2 * t.radius;
  } else {
    w = t.span = r.number("tunnel.span");
    h = t.height = r.number("tunnel.height");
    if (t.shape == mesh::TunnelShape::kHorseshoe && h < w / 2) {
      if (r.blame_second("tunnel.height", "tunnel.span"))
        r.fail("tunnel.span", "a horseshoe's span is at most twice its height (tunnel.height = " +
                                  num(h) + " m); allowed: at most " + num(2 * h) + " m");
      r.fail("tunnel.height", "a horseshoe's height must be at least span/2 (tunnel.span = " +
                                  num(w) + " m); allowed: at least " + num(w / 2) + " m");
    }
    if (t.shape == mesh::TunnelShape::kArched) read_arch_rise(r, t);
  }
  read_invert(r, t);
  read_invert_thickness(r, t);
  m.domain.width = r.number("domain.width");
  m.domain.height = r.number("domain.height");
  m.domain.center_x = r.number("domain.center_x");
  m.domain.center_y = r.number("domain.center_y");
  // The opening plus its fracture zone must sit inside the domain.
  const double margin = t.fracture_zone;
  const double half_w = m.domain.width / 2, half_h = m.domain.height / 2;
  if (w / 2 + margin + std::abs(m.domain.center_x) >= half_w)
    r.fail(outside_key(r, "domain.width", circular ? "tunnel.radius" : "tunnel.span",
                       "domain.center_x"),
           "the tunnel (width " + num(w) + " m plus fracture zone " + num(margin) +
               " m each side) must lie inside the domain (width " + num(m.domain.width) + " m)");
  if (h / 2 + margin + std::abs(m.domain.center_y) >= half_h)
    r.fail(outside_key(r, "domain.height", circular ? "tunnel.radius" : "tunnel.height",
                       "domain.center_y"),
           "the tunnel (height " + num(h) + " m plus fracture zone " + num(margin) +
               " m each side) must lie inside the domain (height " + num(m.domain.height) + " m)");
  if (t.lining_thickness > 0 && 2 * t.lining_thickness >= std::min(w, h) * 0.9)
    r.fail("tunnel.lining_thickness",
           "the lining must leave a core: thickness below 45% of "
           "the opening's smaller dimension " +
               num(std::min(w, h)) + " m");
}

// The geometry's smallest feature, which two elements must span, and what it is.
struct Feature {
  double size = 0;  ///< 0: a mesh from a file
  std::string what;
};

Feature smallest_feature(const mesh::MeshSpec& m) {
  const mesh::TunnelSpec& t = m.tunnel;
  switch (m.kind) {
    case mesh::ModelKind::kTunnel: {
      const bool circular = t.shape == mesh::TunnelShape::kCircular;
      const Feature opening =
          circular ? Feature{2 * t.radius, "2 x tunnel.radius"}
                   : Feature{std::min(t.span, t.height), "the opening's smaller side"};
      if (t.lining_thickness > 0 && 4 * t.lining_thickness < opening.size)
        return {4 * t.lining_thickness, "4 x tunnel.lining_thickness"};
      return opening;
    }
    case mesh::ModelKind::kUcs:
      return {std::min(m.specimen.width, m.specimen.height), "the specimen's smaller side"};
    case mesh::ModelKind::kBrazilian:
      return {m.specimen.diameter, "specimen.diameter"};
    case mesh::ModelKind::kMshFile:
      break;
  }
  return {};
}

void read_mesh_sizes(const Reader& r, mesh::MeshSpec& m) {
  const Feature feature = smallest_feature(m);
  // 0.5 m suits tunnels; a specimen centimetres across has no size to default to.
  const bool specimen = m.kind == mesh::ModelKind::kUcs || m.kind == mesh::ModelKind::kBrazilian;
  if (specimen && !r.has("mesh.size_near"))
    throw InputError(r.source() +
                     ": missing key 'mesh.size_near' (a specimen has no default "
                     "element size); allowed: > 0 and at most " +
                     num(feature.size / 2) + " m (half " + feature.what + ")");
  m.size.size_near = r.number("mesh.size_near");
  m.size.size_far = r.number("mesh.size_far");
  m.size.grading_distance = r.number("mesh.grading_distance");
  m.size.algorithm = r.integer("mesh.algorithm");
  if (m.size.algorithm != 1 && m.size.algorithm != 5 && m.size.algorithm != 6)
    r.fail("mesh.algorithm",
           "only 1 (MeshAdapt), 5 (Delaunay) or 6 (Frontal-Delaunay) make "
           "triangles");
  if (m.size.size_far < m.size.size_near) {
    if (r.blame_second("mesh.size_far", "mesh.size_near"))
      r.fail("mesh.size_near", "must be at most mesh.size_far = " + num(m.size.size_far) + " m");
    r.fail("mesh.size_far", "must be at least mesh.size_near = " + num(m.size.size_near) + " m");
  }
  if (feature.size > 0 && m.size.size_near > feature.size / 2)
    r.fail("mesh.size_near", "must resolve the geometry: at most " + num(feature.size / 2) +
                                 " m here (half " + feature.what + " = " + num(feature.size) +
                                 " m)");
}

// The zone or edge tag of `all` called `name` (the schema allows no other).
template <class Named, std::size_t N>
Named named(const Named (&all)[N], std::string (*name_of)(int), const std::string& name) {
  for (Named v : all)
    if (name_of(v) == name) return v;
  throw std::logic_error("no mesh zone or edge tag is called " + name);
}

void read_msh(const Reader& r, const std::string& base_dir, mesh::MeshSpec& m) {
  r.require("msh.file", "model.kind is \"msh\"");
  std::string file = r.text("msh.file");
  if (!file.empty() && file[0] != '/' && !base_dir.empty()) file = base_dir + "/" + file;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec) || !std::ifstream(file))
    r.fail("msh.file", "cannot open " + file +
                           " as a file; allowed: the path of a readable "
                           "gmsh .msh file, relative to the scene file");
  m.msh.path = file;
  for (auto& [group, zone] : r.string_map("msh.zones"))
    m.msh.zone_groups[group] = named(mesh::kZones, mesh::zone_name, zone);
  for (auto& [group, tag] : r.string_map("msh.edges"))
    m.msh.edge_groups[group] = named(mesh::kEdgeTags, mesh::edge_tag_name, tag);
  if (m.msh.zone_groups.empty())
    throw InputError(r.source() + ": missing key 'msh.zones' (model.kind is \"msh\"); allowed: " +
                     describe_allowed(*find_key("msh.zones")));
  m.msh.fracture_group = r.text("msh.fracture_group");
  m.msh.joint_groups = r.strings("msh.joints");
}

// The keys of each kind of section with steel; a part's own table giving
// one its section does not take is a slip, refused.
const char* const kBarKeys[] = {"bar_area", "bar_cover"};
const char* const kSetKeys[] = {"set_area", "set_inertia", "set_depth", "set_spacing"};

// The ring part's thickness where the scene generates the ring; 0 for a
// user's mesh (measured per segment in the run).
double part_thickness(const Scene& s, const std::string& name) {
  if (s.mesh.kind != mesh::ModelKind::kTunnel) return 0;
  return name == "invert" ? s.mesh.tunnel.invert_thickness : s.mesh.tunnel.lining_thickness;
}

// A value the section's kind needs (its own or, for the invert, the
// lining's); missing: refused.
double needed(const Reader& r, const std::string& path, const std::string& why) {
  const double v = r.number_or(path, 0);
  if (!(v > 0)) r.require(path, why);
  return v;
}

// Where a key the section needs is out of place for the part's thickness.
[[noreturn]] void fail_at(const Reader& r, const std::string& path, const std::string& problem) {
  const std::string at = r.given_at(path);
  r.fail(at, problem + (at == path ? "" : " (" + path + " takes " + at + ")"));
}

void read_bars(const Reader& r, const std::string& p, double h, LiningSectionSpec& sec) {
  const std::string why = p + "section = \"reinforced\"";
  sec.bar_area = needed(r, p + "bar_area", why);
  sec.bar_cover = needed(r, p + "bar_cover", why);
  if (h <= 0) return;
  if (sec.bar_cover >= h / 2)
    fail_at(r, p + "bar_cover",
            "would put the layers across the mid-line of the part's " + num(h) + " m; allowed: < " +
                num(h / 2) + " m");
  // EN 1992-1-1 9.2.1.1(3): As,max = 0.04 Ac; more is a unit slip or no section.
  if (2 * sec.bar_area > 0.04 * h)
    fail_at(r, p + "bar_area",
            "two layers exceed 4% of the section (EN 1992-1-1 9.2.1.1, As,max = 0.04 Ac); "
            "allowed: <= " +
                num(0.02 * h) + " m^2/m per layer for " + num(h) + " m");
}

void read_sets(const Reader& r, const std::string& p, double h, LiningSectionSpec& sec) {
  const std::string why = p + "section = \"steel_sets\"";
  sec.set_area = needed(r, p + "set_area", why);
  sec.set_inertia = needed(r, p + "set_inertia", why);
  sec.set_depth = needed(r, p + "set_depth", why);
  sec.set_spacing = needed(r, p + "set_spacing", why);
  if (h > 0 && sec.set_depth > h)
    fail_at(r, p + "set_depth",
            "is deeper than the part (the sets are embedded in the shotcrete); allowed: <= " +
                num(h) + " m, the part's thickness");
  // All the area at the extreme fibres is the most any section holds.
  if (sec.set_inertia > sec.set_area * sec.set_depth * sec.set_depth / 4)
    fail_at(r, p + "set_inertia",
            "exceeds set_area x set_depth^2 / 4, the most a section of that area and depth has "
            "(a unit slip?); allowed: <= " +
                num(sec.set_area * sec.set_depth * sec.set_depth / 4) + " m^4");
}

// The ring part's section (materials.lining or materials.invert, `name`),
// with strength `fc` of its concrete or shotcrete.
LiningSectionSpec read_section(const Reader& r, const Scene& s, const std::string& name,
                               double fc) {
  const std::string p = "materials." + name + ".";
  LiningSectionSpec sec;
  sec.kind = r.text(p + "section");
  sec.steel_young = r.number(p + "steel_young");
  const bool bars = sec.kind == "reinforced", sets = sec.kind == "steel_sets";
  const std::string is = "; this part's section is \"" + sec.kind + "\"";
  for (const char* key : kBarKeys)
    if (!bars && r.has(p + key)) r.fail(p + key, "applies with section = \"reinforced\"" + is);
  for (const char* key : kSetKeys)
    if (!sets && r.has(p + key)) r.fail(p + key, "applies with section = \"steel_sets\"" + is);
  if (!bars && !sets) {
    for (const char* key : {"steel_young", "steel_yield_strength"})
      if (r.has(p + key))
        r.fail(p + key, "applies with section = \"reinforced\" or \"steel_sets\"" + is);
    return sec;
  }
  const std::string why = p + "section = \"" + sec.kind + "\"";
  if (!(fc > 0)) r.require(p + "compressive_strength", why);
  sec.steel_yield_strength = needed(r, p + "steel_yield_strength", why);
  const double h = part_thickness(s, name);
  if (bars) read_bars(r, p, h, sec);
  if (sets) read_sets(r, p, h, sec);
  return sec;
}

// `name` is a zone's or "invert" (the ring's floor part, an elastic liner
// too, its keys defaulting to the lining's).
MaterialSpec read_material(const Reader& r, const Scene& s, const std::string& name) {
  const std::string p = "materials." + name + ".";
  const bool liner = name == mesh::zone_name(mesh::kLining) || name == "invert";
  // The core's keys default to the rock's, the invert's to the lining's.
  if (name != mesh::zone_name(mesh::kCore) && name != "invert") {
    r.require(p + "young", "every zone of the model needs its material");
    r.require(p + "poisson", "every zone of the model needs its material");
  }
  MaterialSpec m;
  m.density = r.number(p + "density");
  m.young = r.number(p + "young");
  m.poisson = r.number(p + "poisson");
  m.tensile_strength = r.number_or(p + "tensile_strength", 0);
  m.friction_angle = r.number(p + "friction_angle");
  m.residual_friction_angle = r.number(p + "residual_friction_angle");
  // The lining is an elastic liner (no crack elements): its strengths are
  // for the capacity check alone, its friction for its contacts.
  if (liner) {
    m.compressive_strength = r.number_or(p + "compressive_strength", 0);
    m.section = read_section(r, s, name, m.compressive_strength);
    return m;
  }
  m.cohesion = r.number_or(p + "cohesion", 0);
  m.fracture_energy_I = r.number_or(p + "fracture_energy_I", 0);
  m.fracture_energy_II = r.number_or(p + "fracture_energy_II", 0);
  m.penalty_factor = r.number(p + "penalty_factor");
  m.heterogeneity = r.number(p + "heterogeneity");
  m.heterogeneity_seed = std::uint64_t(r.number(p + "heterogeneity_seed"));
  return m;
}

// A ring in the geometry, whether or not the scene gives its material.
bool has_ring(const mesh::MeshSpec& m) {
  if (m.kind == mesh::ModelKind::kTunnel) return m.tunnel.lining_thickness > 0;
  if (m.kind != mesh::ModelKind::kMshFile) return false;
  for (const auto& [group, zone] : m.msh.zone_groups)
    if (zone == mesh::kLining) return true;
  return false;
}

// [materials.invert]: the ring's floor part, of a generated horseshoe or
// arched opening with a lining ring.
void read_invert_material(const Reader& r, Scene& s) {
  if (!r.has("materials.invert")) return;
  const mesh::TunnelSpec& t = s.mesh.tunnel;
  if (s.mesh.kind != mesh::ModelKind::kTunnel || !has_floor(t) || !(t.lining_thickness > 0))
    r.fail("materials.invert",
           "is the lining ring's floor part: it needs a horseshoe or arched tunnel with "
           "tunnel.lining_thickness > 0; allowed here: no [materials.invert]");
  if (!r.has("materials.lining"))
    r.fail("materials.invert", "needs [materials.lining] (the rest of the ring)");
  s.invert = read_material(r, s, "invert");
  if (s.invert->compressive_strength > 0 &&
      !(s.materials.at(mesh::kLining).compressive_strength > 0))
    r.fail("materials.invert.compressive_strength",
           "the ring's capacity check needs materials.lining.compressive_strength too");
}

bool needs_fracture(const mesh::MeshSpec& m) {
  return m.kind == mesh::ModelKind::kUcs || m.kind == mesh::ModelKind::kBrazilian ||
         (m.kind == mesh::ModelKind::kTunnel && m.tunnel.fracture_zone > 0);
}

void read_materials(const Reader& r, Scene& s) {
  s.materials[mesh::kRock] = read_material(r, s, mesh::zone_name(mesh::kRock));
  if (needs_fracture(s.mesh)) {
    for (const char* key :
         {"tensile_strength", "cohesion", "fracture_energy_I", "fracture_energy_II"})
      r.require(std::string("materials.rock.") + key, "the model allows fracture");
  }
  const bool tunnel_like =
      s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile;
  if (tunnel_like) s.materials[mesh::kCore] = read_material(r, s, mesh::zone_name(mesh::kCore));
  if (has_ring(s.mesh) || r.has("materials.lining"))
    s.materials[mesh::kLining] = read_material(r, s, mesh::zone_name(mesh::kLining));
  read_invert_material(r, s);
}

// materials.rock.gsi: the section's figures are the lab's; the model's
// rock (and the core, key by key where it gives none) is the rock mass.
void read_rock_mass(const Reader& r, Scene& s) {
  const char* const mi_key = "materials.rock.hoek_brown_mi";
  if (!r.has("materials.rock.gsi")) {
    for (const char* key :
         {mi_key, "materials.rock.disturbance", "materials.rock.mass_ft_over_ucs"})
      if (r.has(key)) r.fail(key, "applies with materials.rock.gsi (the rock mass's GSI)");
    return;
  }
  if (s.mesh.kind != mesh::ModelKind::kTunnel && s.mesh.kind != mesh::ModelKind::kMshFile)
    r.fail("materials.rock.gsi",
           "is a rock mass's: a laboratory specimen is intact rock; allowed: no gsi");
  r.require(mi_key, "the rock mass's Hoek-Brown strength needs the intact rock's mi");
  MaterialSpec& rock = s.materials.at(mesh::kRock);
  if (!(rock.cohesion > 0)) r.require("materials.rock.cohesion", "its UCS is the lab's sigma_ci");
  RockMassSpec m;
  m.gsi = r.number("materials.rock.gsi");
  m.disturbance = r.number("materials.rock.disturbance");
  m.mi = r.number(mi_key);
  m.gamma_h = s.insitu.sigma_v;
  m.lab = rock;
  m.intact = {rock.young, mohr_coulomb_ucs(rock.cohesion, rock.friction_angle), m.mi};
  m.mass = rock_mass(m.intact, m.gsi, m.disturbance, m.gamma_h);
  if (r.has("materials.rock.mass_ft_over_ucs")) {
    m.ft_over_ucs = r.number("materials.rock.mass_ft_over_ucs");
    m.mass.tensile_strength =
        m.ft_over_ucs * mohr_coulomb_ucs(m.mass.cohesion, m.mass.friction_angle);
  }
  // The rock takes every figure of the mass; the core each it does not give.
  const auto reduce = [&](MaterialSpec& x, const std::function<bool(const char*)>& given) {
    if (!given("young")) x.young = m.mass.young;
    if (!given("cohesion")) x.cohesion = m.mass.cohesion;
    if (!given("friction_angle")) x.friction_angle = m.mass.friction_angle;
    if (!given("tensile_strength")) x.tensile_strength = m.mass.tensile_strength;
    x.residual_friction_angle = std::min(x.residual_friction_angle, x.friction_angle);
  };
  reduce(rock, [](const char*) { return false; });
  const auto core = s.materials.find(mesh::kCore);
  if (core != s.materials.end())
    reduce(core->second,
           [&](const char* key) { return r.has(std::string("materials.core.") + key); });
  s.rock_mass = m;
}

void read_insitu(const Reader& r, Scene& s) {
  InsituSettings& in = s.insitu;
  // The implicit stage needs compression in both directions; specimens start stress-free.
  const bool loaded =
      s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile;
  if (loaded) {
    r.require("insitu.sigma_h", "a tunnel or .msh model is loaded by its in-situ stress");
    r.require("insitu.sigma_v", "a tunnel or .msh model is loaded by its in-situ stress");
  }
  in.sigma_h = r.number_or("insitu.sigma_h", 0);
  in.sigma_v = r.number_or("insitu.sigma_v", 0);
  in.angle_deg = r.number("insitu.angle");
  in.unit_weight = r.number("insitu.unit_weight");
  in.kirsch_boundary = r.text("insitu.boundary") == "kirsch";
  in.lining_active = r.boolean("insitu.lining_active");
  in.rollers = r.boolean("insitu.rollers");
  in.solver = r.text("insitu.solver");
  in.tolerance = r.number("insitu.tolerance");
  in.continuum = r.text("insitu.continuum");
  in.dilation_angle = r.number("insitu.dilation_angle");
  in.continuum_post_peak = r.boolean("insitu.continuum_post_peak");
  if (in.continuum_post_peak && !(s.materials.at(mesh::kRock).cohesion > 0))
    r.fail("insitu.continuum_post_peak",
           "the post-peak continuum needs materials.rock.cohesion > 0 (its peak strength)");
  in.alpha = r.numbers("insitu.alpha");
  in.handoff_first_crack = r.text("insitu.handoff") == "first_crack";
  if (in.handoff_first_crack && !needs_fracture(s.mesh))
    r.fail("insitu.handoff",
           "first_crack needs crack elements: a tunnel with "
           "tunnel.fracture_zone > 0; allowed here: last");
  // Each alpha is a whole implicit solve and output (about 12 us per
  // triangle, 107 s for 1000 on the default tunnel): a list past this is a
  // mistake, not a study.
  if (in.alpha.size() > kMaxAlphas)
    r.fail("insitu.alpha", "holds " + std::to_string(in.alpha.size()) +
                               " values; allowed: at most " + std::to_string(kMaxAlphas) +
                               " (each is a full implicit solve)");
  for (std::size_t i = 1; i < in.alpha.size(); ++i)
    if (!(in.alpha[i] < in.alpha[i - 1])) r.fail("insitu.alpha", "must be strictly decreasing");
  if (s.mesh.kind == mesh::ModelKind::kTunnel) {
    if (in.kirsch_boundary && (s.mesh.tunnel.shape != mesh::TunnelShape::kCircular ||
                               in.unit_weight > 0 || in.angle_deg != 0))
      r.fail("insitu.boundary",
             "exact Kirsch tractions need a circular tunnel, no gradient "
             "and angle 0");
  }
  if (in.lining_active && !s.materials.count(mesh::kLining))
    r.fail("insitu.lining_active", "the model has no lining ring (tunnel.lining_thickness = 0)");
  if (in.lining_active && s.invert)
    r.fail("insitu.lining_active",
           "the implicit stage solves the ring with materials.lining alone; allowed: false "
           "with [materials.invert]");
  if (in.continuum == "mohr_coulomb" &&
      in.dilation_angle > s.materials.at(mesh::kRock).friction_angle)
    r.fail("insitu.dilation_angle", "must not exceed materials.rock.friction_angle");
  if (in.continuum == "mohr_coulomb" && !(s.materials.at(mesh::kRock).cohesion > 0))
    r.fail("insitu.continuum",
           "the Mohr-Coulomb continuum needs materials.rock.cohesion > 0 (without it the "
           "unsupported opening collapses)");
}

// Gravity in a loaded model: the body force rho g of the explicit stages
// and the in-situ gradient that holds it are one choice. The in-situ field
// grows with depth by the rock's unit weight rho g (below the tunnel's
// centre, where sigma_h and sigma_v hold), so that it is in equilibrium with
// the weight from the first step; a unit weight left out is taken as rho g,
// one given must be it. The sides carry a stress that grows with depth: the
// rollers hold it (uniform side tractions cannot).
void relate_gravity(const Reader& r, Scene& s) {
  const double g = s.engine.gravity, rho = s.materials.at(mesh::kRock).density;
  InsituSettings& in = s.insitu;
  if (!(g > 0)) return;
  const double gamma = rho * g;
  if (!r.has("insitu.unit_weight")) in.unit_weight = gamma;
  if (std::fabs(in.unit_weight - gamma) > 1e-6 * gamma)
    r.fail("insitu.unit_weight",
           "the in-situ gradient must hold the weight the explicit stages apply: "
           "insitu.unit_weight = materials.rock.density x engine.gravity = " +
               num(gamma) + " N/m^3 (or leave insitu.unit_weight out)");
  if (!in.rollers)
    r.fail("insitu.rollers",
           "gravity needs the rollers: the sides carry the in-situ stress, "
           "which grows with depth (set engine.gravity = 0 to drop them)");
  if (in.angle_deg != 0)
    r.fail("insitu.angle", "gravity needs vertical principal stresses (angle 0)");
  if (in.kirsch_boundary)
    r.fail("insitu.boundary", "exact Kirsch tractions need a uniform field: no gravity");
}

// A platen moving at a tenth of the rock's P-wave speed strikes the
// specimen instead of loading it (a 0.1 m specimen at 300 m/s: a strain
// rate of 6000 /s): above that the value is a unit slip, refused before a
// run fails at its first step with an inverted triangle.
constexpr double kMostPlatenSpeedFraction = 0.1;

void check_platen_speed(const Reader& r, const Scene& s) {
  const MaterialSpec& rock = s.materials.at(mesh::kRock);
  const double nu = rock.poisson;
  const double modulus = s.plane_stress ? rock.young / (1 - nu * nu)
                                        : rock.young * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double cp = std::sqrt(modulus / rock.density);
  // Four digits, rounded down: the bound checked is the one the message states.
  const double unit = std::pow(10.0, std::floor(std::log10(kMostPlatenSpeedFraction * cp)) - 3);
  const double most = std::floor(kMostPlatenSpeedFraction * cp / unit) * unit;
  if (s.engine.platen_velocity <= most) return;
  char allowed[200];
  std::snprintf(allowed, sizeof allowed, "%.4g m/s (0.1 x the rock's P-wave speed %.4g m/s", most,
                cp);
  r.fail("loading.platen_velocity",
         "the platens would strike the specimen, not load it; allowed: 0 < "
         "loading.platen_velocity <= " +
             std::string(allowed) + ", from materials.rock.young, poisson and density)");
}

std::array<double, 2> point(const Reader& r, const std::string& path) {
  const std::vector<double> v = r.numbers(path);
  if (v.size() != 2) r.fail(path, "a point is [x, y]");
  return {v[0], v[1]};
}

// Bolts from [[bolt]] segments and [[bolt_fan]] patterns; each must be a
// real segment inside the rock domain.
SteelSettings read_steel(const Reader& r, const std::string& section) {
  SteelSettings b;
  b.diameter = r.number(section + ".diameter");
  b.row_spacing = r.number(section + ".row_spacing");
  b.young = r.number(section + ".young");
  b.yield_strength = r.number(section + ".yield_strength");
  b.ultimate_strength = r.number(section + ".ultimate_strength");
  b.tangent_modulus = r.number(section + ".tangent_modulus");
  b.shear_yield_strength = r.number(section + ".shear_yield_strength");
  b.shear_fracture_energy = r.number(section + ".shear_fracture_energy");
  // The hardening law runs from sigma_y to sigma_u over a positive range
  // with a modulus below the elastic one (seed eqs. 11-19; fdem checks it too).
  if (b.ultimate_strength <= b.yield_strength)
    r.fail(section + ".ultimate_strength", "must be above " + section + ".yield_strength");
  if (b.tangent_modulus >= b.young)
    r.fail(section + ".tangent_modulus", "must be below " + section + ".young");
  return b;
}

BondSettings read_bond(const Reader& r, const std::string& section) {
  BondSettings g;
  for (auto [key, field] : {std::pair{".young", &BondSettings::young},
                            {".tensile_strength", &BondSettings::tensile_strength},
                            {".cohesion", &BondSettings::cohesion},
                            {".friction_angle", &BondSettings::friction_angle},
                            {".fracture_energy_I", &BondSettings::fracture_energy_I},
                            {".fracture_energy_II", &BondSettings::fracture_energy_II}})
    g.*field = r.number(section + key);
  return g;
}

void read_bolts(const Reader& r, Scene& s) {
  BoltSettings& b = s.bolts;
  b.bolt = read_steel(r, "bolts");
  b.cable = read_steel(r, "cables");
  b.keep_current_stress = r.text("bolts.install_stress") == "current";
  s.grout = read_bond(r, "grout");
  s.lining_interface = read_bond(r, "lining_interface");
  std::vector<BoltPlacement> found;
  const auto is_cable = [&](const std::string& p) { return r.text(p + ".kind") == "cable"; };
  std::vector<std::uint8_t> cables;
  if (const toml::node* list = r.node("bolt")) {
    for (std::size_t i = 0; i < list->as_array()->size(); ++i) {
      const std::string p = "bolt[" + std::to_string(i) + "]";
      r.require(p + ".start", "a bolt needs its head");
      r.require(p + ".end", "a bolt needs its end");
      const auto a = point(r, p + ".start"), e = point(r, p + ".end");
      found.push_back({p + ".start", p + ".end", p, {a[0], a[1], e[0], e[1]}});
      cables.push_back(is_cable(p));
    }
  }
  if (const toml::node* list = r.node("bolt_fan")) {
    for (std::size_t i = 0; i < list->as_array()->size(); ++i) {
      const std::string p = "bolt_fan[" + std::to_string(i) + "]";
      for (const char* k : {".radius", ".count", ".length"})
        r.require(p + k, "a bolt fan needs radius, count and length");
      const std::array<double, 2> c = point(r, p + ".centre");
      const int count = r.integer(p + ".count");
      const double radius = r.number(p + ".radius"), length = r.number(p + ".length");
      const double a0 = r.number(p + ".first_deg"), a1 = r.number(p + ".last_deg");
      for (int k = 0; k < count; ++k) {
        const double deg = count == 1 ? a0 : a0 + (a1 - a0) * k / (count - 1);
        const double cs = std::cos(deg * M_PI / 180), sn = std::sin(deg * M_PI / 180);
        found.push_back({p + (r.has(p + ".centre") ? ".centre" : ".radius"),
                         p + ".length",
                         "bolt " + std::to_string(k + 1) + " of " + std::to_string(count) + " of " +
                             p + " (" + num(deg) + " deg)",
                         {c[0] + radius * cs, c[1] + radius * sn, c[0] + (radius + length) * cs,
                          c[1] + (radius + length) * sn}});
        cables.push_back(is_cable(p));
      }
    }
  }
  for (std::size_t i = 0; i < found.size(); ++i) {
    detail::check_bolt_placement(r.raw(), s.mesh, found[i]);
    b.segments.push_back(found[i].seg);
    b.is_cable.push_back(cables[i]);
  }
  if (!b.segments.empty() && s.mesh.kind != mesh::ModelKind::kTunnel)
    r.fail("bolt", "bolts need a tunnel model");
}

// [[monitor]] and [[extensometer]]: names fit for history.csv's columns,
// points inside the rock domain and out of the excavated core, as far as
// the scene alone tells (a generated tunnel's outline; a user's mesh is
// checked against its triangles when the run places them).
void check_instrument_name(const Reader& r, const std::string& key, std::set<std::string>& seen) {
  const std::string name = r.text(key);
  bool safe = !name.empty() && name.size() <= 40 && std::isalpha((unsigned char)name[0]);
  for (char c : name) safe = safe && (std::isalnum((unsigned char)c) || c == '_');
  if (!safe)
    r.fail(key,
           "not a name for history.csv's columns; allowed: a letter, then letters, digits or "
           "'_', at most 40 characters");
  for (const char* k :
       {"vault", "crown", "left_shoulder", "right_shoulder", "left_wall", "right_wall", "invert"})
    if (name == k) r.fail(key, "a key point has that name; allowed: any other name");
  if (!seen.insert(name).second)
    r.fail(key, "another monitor or extensometer has that name; allowed: a unique name");
}

// Why the point (x, y) of instrument `what` cannot be read, or empty.
std::string misplaced(const Scene& s, const std::string& what, double x, double y) {
  const std::string at = what + " at (" + num(x) + ", " + num(y) + ") m ";
  const mesh::DomainSpec& d = s.mesh.domain;
  // A user's .msh has no domain until it is read; its points are placed
  // (and refused when outside every triangle) once the mesh is.
  const bool generated = s.mesh.msh.path.empty();
  if (generated &&
      (std::abs(x - d.center_x) >= d.width / 2 || std::abs(y - d.center_y) >= d.height / 2))
    return at + "lies outside the rock domain; allowed: x in (" + num(d.center_x - d.width / 2) +
           ", " + num(d.center_x + d.width / 2) + "), y in (" + num(d.center_y - d.height / 2) +
           ", " + num(d.center_y + d.height / 2) + ")";
  const mesh::TunnelSpec& t = s.mesh.tunnel;
  if (s.mesh.kind == mesh::ModelKind::kTunnel &&
      mesh::inside_outline(mesh::lining_inner_outline(t), x, y))
    return at + "lies inside the opening, in the excavated core; allowed: a point in the rock " +
           "or the lining";
  return "";
}

// An instrument's relative_to_support: only where a stage installs support.
bool read_relative_to_support(const Reader& r, const Scene& s, const std::string& p) {
  const bool relative = r.boolean(p + ".relative_to_support");
  if (relative && std::none_of(s.stages.begin(), s.stages.end(),
                               [](auto& st) { return stage_kind(st.kind).installs_support(); }))
    r.fail(p + ".relative_to_support",
           "the stages install no support; allowed: true only with a `lining` or `bolts` stage");
  return relative;
}

void read_monitors(const Reader& r, Scene& s, std::set<std::string>& names) {
  const toml::node* list = r.node("monitor");
  for (std::size_t i = 0; list && i < list->as_array()->size(); ++i) {
    const std::string p = "monitor[" + std::to_string(i) + "]";
    for (const char* k : {".name", ".x", ".y"}) r.require(p + k, "a monitor needs name, x and y");
    check_instrument_name(r, p + ".name", names);
    MonitorSpec m;
    m.name = r.text(p + ".name");
    m.x = r.number(p + ".x");
    m.y = r.number(p + ".y");
    m.relative_to_support = read_relative_to_support(r, s, p);
    const std::string where = misplaced(s, p + " \"" + m.name + "\"", m.x, m.y);
    if (!where.empty()) r.fail(p + ".x", where);
    s.monitors.push_back(m);
  }
}

ExtensometerSpec read_extensometer(const Reader& r, const Scene& s, const std::string& p) {
  ExtensometerSpec x;
  x.name = r.text(p + ".name");
  x.length = r.number(p + ".length");
  x.anchors = r.integer(p + ".anchors");
  x.relative_to_support = read_relative_to_support(r, s, p);
  if (r.has(p + ".from")) {
    if (r.has(p + ".head") || r.has(p + ".direction"))
      r.fail(p + ".from", "the head is the key point's; allowed: `from` or `head` and `direction`");
    x.from = r.text(p + ".from") == "crown" ? "vault" : r.text(p + ".from");
    return x;
  }
  r.require(p + ".head", "an extensometer needs `from`, or `head` and `direction`");
  r.require(p + ".direction", "an extensometer needs `from`, or `head` and `direction`");
  const auto h = point(r, p + ".head"), d = point(r, p + ".direction");
  const double len = std::hypot(d[0], d[1]);
  if (!(len > 0)) r.fail(p + ".direction", "no direction; allowed: a non-zero [dx, dy]");
  x.head_x = h[0], x.head_y = h[1], x.dir_x = d[0] / len, x.dir_y = d[1] / len;
  for (int k = 0; k <= x.anchors; ++k) {
    const double depth = x.length * k / x.anchors;
    const std::string what =
        p + " \"" + x.name + "\"" + (k ? " anchor " + std::to_string(k) : " head");
    const std::string where =
        misplaced(s, what, x.head_x + depth * x.dir_x, x.head_y + depth * x.dir_y);
    if (!where.empty()) r.fail(p + (k ? ".length" : ".head"), where);
  }
  return x;
}

void read_instruments(const Reader& r, Scene& s) {
  std::set<std::string> names;
  const bool tunnel =
      s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile;
  for (const char* table : {"monitor", "extensometer"})
    if (r.has(table) && !tunnel)
      r.fail(table, "monitors and extensometers need a tunnel or msh model; allowed: none here");
  read_monitors(r, s, names);
  const toml::node* list = r.node("extensometer");
  for (std::size_t i = 0; list && i < list->as_array()->size(); ++i) {
    const std::string p = "extensometer[" + std::to_string(i) + "]";
    for (const char* k : {".name", ".length"})
      r.require(p + k, "an extensometer needs name and length");
    check_instrument_name(r, p + ".name", names);
    s.extensometers.push_back(read_extensometer(r, s, p));
  }
}

// [[joint_set]] entry p: the set's statistics, its spacing no finer than
// the mesh (a joint every element or two leaves no rock between them).
mesh::JointSetSpec read_joint_set(const Reader& r, const Scene& s, const std::string& p) {
  for (const char* k : {".dip", ".spacing"}) r.require(p + k, "a joint set needs dip and spacing");
  mesh::JointSetSpec j;
  j.dip_deg = r.number(p + ".dip");
  j.spacing = r.number(p + ".spacing");
  j.trace_length = r.number(p + ".trace_length");
  j.persistence = r.number(p + ".persistence");
  j.dip_scatter_deg = r.number(p + ".dip_scatter");
  j.spacing_scatter = r.number(p + ".spacing_scatter");
  j.length_scatter = r.number(p + ".length_scatter");
  if (j.spacing < s.mesh.size.size_near)
    r.fail(p + ".spacing", "finer than the mesh (mesh.size_near = " + num(s.mesh.size.size_near) +
                               " m); allowed: >= mesh.size_near");
  if (j.persistence < 1 && j.trace_length == 0)
    r.fail(p + ".persistence",
           "a persistence below 1 needs traces of a length; allowed: 1 with trace_length = 0");
  return j;
}

// A user's .msh brings its joints as lines (msh.joints): rockfdem does not
// remesh it, so sets and a DFN, which need traces meshed in, are refused,
// and so is a joint material with no joint lines to take it.
void check_msh_joints(const Reader& r, const Scene& s) {
  const std::string why =
      " (model.kind = \"msh\": rockfdem does not remesh a user's .msh, so generated or "
      "listed traces cannot be meshed in); allowed: none, with the joints drawn in the .msh "
      "as 1D physical groups named in msh.joints";
  if (r.has("joint_set")) r.fail("joint_set", "joint sets need a generated tunnel" + why);
  for (const char* key : {"joints.dfn_file", "joints.seed", "joints.margin"})
    if (r.has(key)) r.fail(key, "applies to joint sets and DFN files only" + why);
  if (r.has("joints") && s.mesh.msh.joint_groups.empty())
    r.fail("joints",
           "a joint material but no joint lines to take it; allowed: [joints] with msh.joints "
           "naming the .msh's 1D physical groups that are joints");
}

// [joints], [[joint_set]] and the DFN file: the joint material and the
// traces (generated in the opening's box grown by joints.margin, within
// the domain), into s.mesh.joints. Tunnels; a .msh brings its own lines.
void read_joints(const Reader& r, const std::string& base_dir, Scene& s) {
  JointSettings& j = s.joints;
  j.tensile_strength = r.number("joints.tensile_strength");
  j.cohesion = r.number("joints.cohesion");
  j.friction_angle = r.number("joints.friction_angle");
  j.residual_friction_angle = r.number("joints.residual_friction_angle");
  j.fracture_energy_I = r.number("joints.fracture_energy_I");
  j.fracture_energy_II = r.number("joints.fracture_energy_II");
  j.penalty_factor = r.number("joints.penalty_factor");
  j.seed = std::uint64_t(r.number("joints.seed"));
  j.margin = s.mesh.kind == mesh::ModelKind::kTunnel ? r.number("joints.margin") : 0;
  j.barton_bandis = r.text("joints.shear_strength") == "barton_bandis";
  if (j.barton_bandis) {
    for (const char* key : {"joints.jrc", "joints.jcs"})
      r.require(key, "joints.shear_strength = \"barton_bandis\" needs joints.jrc and joints.jcs");
    j.jrc = r.number_or("joints.jrc", 0);
    j.jcs = r.number_or("joints.jcs", 0);
    if (j.residual_friction_angle >= 70)  // crack_law_joint.hpp's cap
      r.fail(r.given_at("joints.residual_friction_angle"),
             "at or above the Barton-Bandis cap of the total friction angle; allowed: below 70 "
             "deg with joints.shear_strength = \"barton_bandis\"");
  } else {
    for (const char* key : {"joints.jrc", "joints.jcs"})
      if (r.has(key))
        r.fail(key, "applies with joints.shear_strength = \"barton_bandis\"; allowed: no " +
                        std::string(key) + " with mohr_coulomb");
  }
  if (!j.barton_bandis && j.residual_friction_angle > j.friction_angle)
    r.fail(r.given_at("joints.residual_friction_angle"),
           "above joints.friction_angle = " + num(j.friction_angle) +
               " deg; allowed: at most the peak friction angle");
  if (s.mesh.kind == mesh::ModelKind::kMshFile)
    check_msh_joints(r, s);
  else if ((r.has("joint_set") || r.has("joints")) && s.mesh.kind != mesh::ModelKind::kTunnel)
    r.fail(r.has("joint_set") ? "joint_set" : "joints",
           "joints need a tunnel or a .msh model (model.kind = \"tunnel\" or \"msh\"); "
           "allowed: none here");
  const toml::node* list = r.node("joint_set");
  for (std::size_t i = 0; list && i < list->as_array()->size(); ++i)
    j.sets.push_back(read_joint_set(r, s, "joint_set[" + std::to_string(i) + "]"));
  const mesh::HalfExtent e = s.mesh.kind == mesh::ModelKind::kTunnel
                                 ? mesh::opening_half_extent(s.mesh.tunnel)
                                 : mesh::HalfExtent{};
  const mesh::DomainSpec& d = s.mesh.domain;
  const mesh::JointRegion region{std::max(-e.hx - j.margin, d.center_x - d.width / 2),
                                 std::max(-e.hy - j.margin, d.center_y - d.height / 2),
                                 std::min(e.hx + j.margin, d.center_x + d.width / 2),
                                 std::min(e.hy + j.margin, d.center_y + d.height / 2)};
  for (std::size_t i = 0; i < j.sets.size(); ++i) {
    const auto traces = mesh::generate_joint_set(j.sets[i], region, j.seed, int(i));
    s.mesh.joints.insert(s.mesh.joints.end(), traces.begin(), traces.end());
    if (s.mesh.joints.size() > kMaxDfnTraces)
      r.fail("joint_set[" + std::to_string(i) + "].spacing",
             "the sets generate more than " + std::to_string(kMaxDfnTraces) +
                 " traces; allowed: a larger spacing or trace_length, or a smaller joints.margin");
  }
  j.set_traces = long(s.mesh.joints.size());
  std::string file = r.text("joints.dfn_file");
  if (!file.empty()) {
    if (file[0] != '/' && !base_dir.empty()) file = base_dir + "/" + file;
    j.dfn_file = file;
    const auto dfn = read_dfn_csv(file, "joints.dfn_file");
    j.dfn_traces = long(dfn.size());
    s.mesh.joints.insert(s.mesh.joints.end(), dfn.begin(), dfn.end());
  }
}

// A [[stages]] entry's keys for its kind (StageKind::read).
class EntryKeys : public StageEntry {
 public:
  EntryKeys(const Reader& r, std::string prefix) : r_(r), p_(std::move(prefix)) {}
  bool has(const std::string& key) const override { return r_.has(p_ + key); }
  double number(const std::string& key) const override { return r_.number(p_ + key); }

 private:
  const Reader& r_;
  std::string p_;
};

// One stage's keys at `p` ("stages[2]"); absent keys take the schema's
// defaults (max_steps engine.steps, every_steps output.every_steps).
StageSpec read_stage(const Reader& r, const std::string& p, const std::string& kind) {
  StageSpec st;
  st.kind = kind;
  for (auto [key, field] : {std::pair{".ratio", &StageSpec::ratio},
                            {".time", &StageSpec::time},
                            {".settle", &StageSpec::settle},
                            {".broken_settle", &StageSpec::broken_settle},
                            {".unstable_fraction", &StageSpec::unstable_fraction}})
    st.*field = r.number(p + key);
  st.max_steps = long(r.number(p + ".max_steps"));
  st.every_steps = r.integer(p + ".every_steps");
  st.hold = r.integer(p + ".hold");
  st.stop_when_unstable = r.boolean(p + ".stop_when_unstable");
  // The kind's own keys; another kind's is a key that would do nothing.
  for (const std::string& other : stage_kinds()) {
    if (other == kind) continue;
    for (const KeySpec& k : stage_kind(other).entry_keys()) {
      const std::string key = p + k.path.substr(std::string("stages[]").size());
      if (r.has(key))
        r.fail(key, "only a stage of kind \"" + other + "\" reads it, not \"" + kind +
                        "\": remove it from this entry");
    }
  }
  st.own = stage_kind(kind).read(EntryKeys(r, p));
  return st;
}

// Without [[stages]]: the stages the reference lists, each with the keys'
// defaults (read at an index the file does not have). Installing a support
// and removing the core take no steps; equilibrium runs to its cap. A
// specimen's one stage loads it for engine.steps (the post-peak stop).
void default_stages(const Reader& r, Scene& s) {
  const auto stage = [&](const char* kind) {
    StageSpec st = read_stage(r, "stages[0]", kind);
    if (st.kind != "equilibrium" && st.kind != "load_platens") st.max_steps = 0;
    return st;
  };
  if (s.mesh.kind == mesh::ModelKind::kUcs || s.mesh.kind == mesh::ModelKind::kBrazilian)
    return s.stages.push_back(stage("load_platens"));
  // A ring that carried load in the implicit stage is installed already.
  if (s.lining_ring && !s.insitu.lining_active) s.stages.push_back(stage("lining"));
  if (!s.bolts.segments.empty()) s.stages.push_back(stage("bolts"));
  s.stages.push_back(stage("remove_core"));
  s.stages.push_back(stage("equilibrium"));
}

// One entry of [[stages]] checked by its kind's Stage, which refuses
// through the reader: the message names the entry's key.
class EntryCheck : public StageCheck {
 public:
  EntryCheck(const Reader& r, std::string prefix, const Scene& s, const StageSpec& st,
             StageOrder& at)
      : StageCheck(s, st, at), r_(r), p_(std::move(prefix)) {}
  [[noreturn]] void refuse(const std::string& key, const std::string& why) const override {
    r_.fail(p_ + key, why);
  }
  void require(const std::string& key, const std::string& why) const override {
    r_.require(p_ + key, why);
  }

 private:
  const Reader& r_;
  std::string p_;
};

// The explicit stages after the implicit hand-off.
void read_stages(const Reader& r, Scene& s) {
  const toml::node* list = r.node("stages");
  if (!list) return default_stages(r, s);
  if (s.mesh.kind != mesh::ModelKind::kTunnel && s.mesh.kind != mesh::ModelKind::kMshFile)
    r.fail("stages", "construction stages need a tunnel model");
  // Each stage costs a stage change and an output beyond its steps: a
  // list past this is a generated mistake, not a construction sequence.
  if (list->as_array() && list->as_array()->size() > kMaxStages)
    r.fail("stages", "holds " + std::to_string(list->as_array()->size()) +
                         " entries; allowed: at most " + std::to_string(kMaxStages) +
                         " (each costs a stage change and an output beyond its steps)");
  StageOrder at;
  // With the hand-off found at run time, soften stages may start from the top.
  at.alpha = s.insitu.handoff_first_crack ? s.insitu.alpha.front() : s.insitu.alpha.back();
  for (std::size_t i = 0; i < list->as_array()->size(); ++i) {
    const std::string p = "stages[" + std::to_string(i) + "]";
    r.require(p + ".kind", "every stage has a kind");
    const std::string kind = r.text(p + ".kind");
    if (kind == "insitu") {
      if (i != 0) r.fail(p + ".kind", "the implicit in-situ stage comes first");
      continue;
    }
    const StageSpec st = read_stage(r, p, kind);
    EntryCheck check(r, p, s, st, at);
    stage_kind(kind).check(check);
    s.stages.push_back(st);
  }
  if (!s.bolts.segments.empty() && !at.bolted)
    r.fail("stages", "the scene has bolts but no stage of kind \"bolts\" installs them");
  // The outputs number the implicit stage 0 and these from 1: a list that
  // leaves it out would number its entries one above their stages[N].
  if (!list->as_array()->empty() && r.text("stages[0].kind") != "insitu")
    s.warnings.push_back(
        "stages: the list does not begin with kind = \"insitu\"; the run still solves the "
        "implicit stage and numbers it 0 in its outputs, so stages[N] is numbered N + 1 there: "
        "list the implicit stage first");
}

// insitu.install_at_face_distance sets the hand-off alpha, so the support
// must go in at the hand-off: a lining or bolts stage before any soften
// stage, the list's last alpha handed over, no lining in the implicit stage.
void read_face_distance(const Reader& r, Scene& s) {
  const char* key = "insitu.install_at_face_distance";
  if (!r.has(key)) return;
  s.insitu.install_at_face_distance = r.number(key);
  if (s.mesh.kind != mesh::ModelKind::kTunnel && s.mesh.kind != mesh::ModelKind::kMshFile)
    r.fail(key, "applies to tunnels and .msh models");
  if (s.insitu.handoff_first_crack)
    r.fail(key, "sets the hand-off alpha itself; allowed with insitu.handoff = \"last\"");
  if (s.insitu.lining_active)
    r.fail(key, "installs the support at the hand-off; allowed with insitu.lining_active = false");
  for (const StageSpec& st : s.stages) {
    if (st.kind == "lining" || st.kind == "bolts") return;
    if (st.kind == "soften" || st.kind == "remove_core")
      r.fail(key, "the support must go in at the hand-off: a lining or bolts stage before any " +
                      st.kind + " stage");
  }
  r.fail(key, "needs a lining or bolts stage: there is no support to install");
}

mesh::ModelKind model_kind(const std::string& s) {
  if (s == "ucs") return mesh::ModelKind::kUcs;
  if (s == "brazilian") return mesh::ModelKind::kBrazilian;
  if (s == "msh") return mesh::ModelKind::kMshFile;
  return mesh::ModelKind::kTunnel;
}

// The sections a kind does not use must not be given: a stray [specimen] in
// a tunnel scene is almost always a mistake worth reporting.
void reject_unused_sections(const Reader& r, mesh::ModelKind kind) {
  const bool tunnel = kind == mesh::ModelKind::kTunnel;
  const bool specimen = kind == mesh::ModelKind::kUcs || kind == mesh::ModelKind::kBrazilian;
  const std::pair<const char*, bool> used[] = {{"tunnel", tunnel},
                                               {"domain", tunnel},
                                               {"specimen", specimen},
                                               {"msh", kind == mesh::ModelKind::kMshFile}};
  for (auto [section, ok] : used)
    if (!ok && r.has(section))
      r.fail(section, std::string("section [") + section + "] is not used by model.kind = \"" +
                          r.text("model.kind") + "\"");
}

// The validated tree as TOML, with a .msh scene's mesh file as an absolute
// path, so that the copy in a run folder runs from anywhere.
std::string scene_as_run(toml::table root, const mesh::MeshSpec& m) {
  if (m.kind == mesh::ModelKind::kMshFile) {
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::absolute(m.msh.path, ec).lexically_normal();
    root["msh"].as_table()->insert_or_assign("file", ec ? m.msh.path : file.string());
  }
  std::ostringstream out;
  out << root << '\n';
  return out.str();
}

void read_output(const Reader& r, OutputSettings& o) {
  o.every_steps = r.integer("output.every_steps");
  o.vtk = r.boolean("output.vtk");
  o.plots = r.boolean("output.plots");
  o.checkpoint_every = static_cast<long>(r.number("output.checkpoint_every"));
  o.convergence_from_support = r.text("output.convergence_from") == "support";
}

Scene build_scene(const RawScene& raw, const std::string& base_dir) {
  const Reader r(raw);
  Scene s;
  s.source = raw.source;
  s.title = r.text("model.title");
  s.plane_stress = r.text("model.analysis") == "plane_stress";
  s.mesh.kind = model_kind(r.text("model.kind"));
  reject_unused_sections(r, s.mesh.kind);
  s.mesh.specimen.width = r.number("specimen.width");
  s.mesh.specimen.height = r.number("specimen.height");
  s.mesh.specimen.diameter = r.number("specimen.diameter");
  s.mesh.specimen.load_arc_deg = r.number("specimen.load_arc_deg");
  if (s.mesh.kind == mesh::ModelKind::kTunnel) read_tunnel(r, s.mesh);
  if (s.mesh.kind == mesh::ModelKind::kMshFile) read_msh(r, base_dir, s.mesh);
  read_mesh_sizes(r, s.mesh);
  read_materials(r, s);
  s.lining_ring = has_lining_ring(s);
  read_insitu(r, s);
  read_rock_mass(r, s);
  s.engine.steps = long(r.number("engine.steps"));
  s.engine.dt = r.number("engine.dt");
  s.engine.dt_safety = r.number("engine.dt_safety");
  s.engine.damping_ratio = r.number("engine.damping_ratio");
  s.engine.local_damping = r.number_or("engine.local_damping", -1);
  s.engine.mass_damping = r.number("engine.mass_damping");
  s.engine.kinetic_damping = r.boolean("engine.kinetic_damping");
  s.engine.gravity = r.number("engine.gravity");
  if (s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile)
    relate_gravity(r, s);
  const std::string scaling = r.text("engine.mass_scaling");
  const bool specimen =
      s.mesh.kind == mesh::ModelKind::kUcs || s.mesh.kind == mesh::ModelKind::kBrazilian;
  s.engine.mass_scaling = scaling == "on" || (scaling == "auto" && !specimen);
  s.engine.mass_scaling_dt = r.number("engine.mass_scaling_dt");
  s.engine.platen_velocity = r.number("loading.platen_velocity");
  if (specimen) check_platen_speed(r, s);
  s.engine.rough_platens = r.text("loading.platen_friction") == "rough";
  s.engine.stop_after_peak = r.number("loading.stop_after_peak");
  s.engine.contact = r.boolean("contact.enabled");
  s.engine.contact_penalty_factor = r.number("contact.penalty_factor");
  s.engine.contact_damping = r.number("contact.damping_ratio");
  s.engine.contact_friction = r.boolean("contact.friction");
  read_output(r, s.output);
  read_references(r, s.references);
  read_bolts(r, s);
  read_stages(r, s);
  read_face_distance(r, s);
  read_instruments(r, s);
  read_joints(r, base_dir, s);
  std::ostringstream canonical;
  canonical << raw.root;
  s.canonical = canonical.str();
  // How often to checkpoint does not change the results a restart continues.
  toml::table keyed = raw.root;
  if (toml::table* out = keyed["output"].as_table()) out->erase("checkpoint_every");
  std::ostringstream key;
  key << keyed;
  s.restart_key = key.str();
  // Nor do the pictures and ParaView files change a result a study keeps.
  if (toml::table* out = keyed["output"].as_table()) {
    out->erase("plots");
    out->erase("vtk");
  }
  std::ostringstream results;
  results << keyed;
  s.results_key = results.str();
  s.as_run = scene_as_run(raw.root, s.mesh);
  s.warnings = detail::unit_warnings(raw);
  for (std::string& w : detail::damping_warnings(raw, s)) s.warnings.push_back(std::move(w));
  if (!s.mesh.joints.empty() && s.mesh.tunnel.fracture_zone <= 0)
    s.warnings.push_back(s.source +
                         ": the joints are meshed but act nowhere: joint crack elements exist "
                         "only within tunnel.fracture_zone, which is 0");
  return s;
}

std::string directory_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

bool has_lining_ring(const Scene& s) {
  return s.materials.count(mesh::kLining) && has_ring(s.mesh);
}

namespace {

// A check between keys that fails only with the --set values applied is the
// override's fault, even when the key it names is in the file: the first
// override whose addition makes the scene fail is named.
[[noreturn]] void blame_override(const std::string& text, const std::string& source,
                                 const std::string& base_dir,
                                 const std::vector<std::string>& overrides,
                                 const InputError& error) {
  const auto fails = [&](std::size_t n) {
    try {
      build_scene(detail::read_raw_scene(text, source, {overrides.begin(), overrides.begin() + n}),
                  base_dir);
      return false;
    } catch (const InputError&) {
      return true;
    }
  };
  if (fails(0)) throw error;  // the file itself is at fault
  std::size_t n = 1;
  while (n < overrides.size() && !fails(n)) ++n;
  throw InputError(detail::printable("--set " + overrides[n - 1] +
                                     ": makes the scene invalid: " + error.what()));
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source, const std::string& base_dir,
                  const std::vector<std::string>& overrides) {
  try {
    Scene s = build_scene(detail::read_raw_scene(text, source, overrides), base_dir);
    s.overrides = overrides;
    return s;
  } catch (const InputError& e) {
    if (overrides.empty() || std::string(e.what()).rfind("--set ", 0) == 0) throw;
    blame_override(text, source, base_dir, overrides, e);
  }
}

namespace {

constexpr std::uintmax_t kMaxSceneBytes = std::uintmax_t(1) << 20;  // as the scene reader's bound

// `-`: the scene from stdin, read up to one byte past the bound a file has.
Scene load_stdin_scene(const std::vector<std::string>& overrides) {
  std::string text(kMaxSceneBytes + 1, '\0');
  std::cin.read(&text[0], std::streamsize(text.size()));
  text.resize(std::size_t(std::cin.gcount()));
  if (text.size() > kMaxSceneBytes)
    throw InputError("<stdin>: the scene holds more than " + std::to_string(kMaxSceneBytes) +
                     " bytes; allowed: at most " + std::to_string(kMaxSceneBytes) +
                     " bytes (1 MiB)");
  return parse_scene(text, "<stdin>", ".", overrides);
}

}  // namespace

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  if (path == "-") return load_stdin_scene(overrides);
  // A FIFO, a device or a huge file is refused before anything is read:
  // reading first would block or grow without bound.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(path + ": not a regular file; a scene is a TOML text file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxSceneBytes)
    throw InputError(path + ": the scene file has " + std::to_string(size) +
                     " bytes; allowed: at most " + std::to_string(kMaxSceneBytes) +
                     " bytes (1 MiB)");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path, directory_of(path), overrides);
}

Scene load_default_scene(const std::vector<std::string>& overrides) {
  Scene s = parse_scene(default_scene_text(), "default", ".", overrides);
  return s;
}

}  // namespace rockfdem::workflows
