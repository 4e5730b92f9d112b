#include "study/study_figures.hpp"

#include <algorithm>
#include <optional>

namespace rockfdem::workflows::study {
namespace {

bool is_specimen(const Scene& scene) {
  return scene.mesh.kind == mesh::ModelKind::kUcs || scene.mesh.kind == mesh::ModelKind::kBrazilian;
}

const char* const kChords[] = {"vault_settlement_mm", "wall_chord_convergence_mm",
                               "shoulder_chord_convergence_mm"};

// Means of a symmetric pair of key points: what a symmetric model is
// compared with when the two field readings differ.
struct Pair {
  const char* target;  ///< the --target name
  const char* column;  ///< sweep.csv's column
  const char* left;    ///< the columns it averages
  const char* right;
};
const Pair kPairs[] = {
    {"shoulders", "shoulders_radial_mm", "left_shoulder_radial_mm", "right_shoulder_radial_mm"},
    {"walls", "walls_radial_mm", "left_wall_radial_mm", "right_wall_radial_mm"},
    {"shoulders_horizontal", "shoulders_horizontal_mm", "left_shoulder_horizontal_mm",
     "right_shoulder_horizontal_mm"}};

// The shoulders as convergence monitoring reads them (horizontal, each
// point's own: record/survey_reading.hpp), where their rays are oblique.
const char* const kShoulders[] = {"left_shoulder", "right_shoulder"};

// Copies summary[section][key] (a number) into figures[column] when present.
void take(const nlohmann::json& summary, const char* section, const std::string& key,
          const std::string& column, double scale, nlohmann::json& figures) {
  const auto s = summary.find(section);
  if (s == summary.end() || !s->is_object()) return;
  const auto v = s->find(key);
  if (v != s->end() && v->is_number()) figures[column] = scale * v->get<double>();
}

// What a tunnel run says of its support and damage (summary.json's
// support, lining, bolts, broken_zone), beside the displacements.
const char* const kSupportColumns[] = {"vault_explicit_share",
                                       "broken_depth_m",
                                       "damaged_depth_least_ray_m",
                                       "lining_min_safety_factor",
                                       "max_bolt_tension_kN_per_bar",
                                       "bolts_with_broken_steel",
                                       "support_verdict"};

// The shallowest of the key points' rays: the zone broken at some time
// (grouted since, where a grout stage fired), else broken now.
void take_least_ray(const nlohmann::json& summary, nlohmann::json& f) {
  const auto z = summary.find("broken_zone");
  if (z == summary.end() || !z->contains("along_rays")) return;
  std::optional<double> least;
  for (const auto& [name, ray] : (*z)["along_rays"].items()) {
    const double d = ray.value("broken_or_grouted_depth_m", ray.value("depth_m", 0.0));
    least = std::min(least.value_or(d), d);
  }
  if (least) f["damaged_depth_least_ray_m"] = *least;
}

// The support columns of kSupportColumns from a tunnel's summary.
void take_support(const nlohmann::json& summary, nlohmann::json& f) {
  if (const auto m = summary.find("monitors"); m != summary.end() && m->contains("vault"))
    take((*m), "vault", "explicit_share", "vault_explicit_share", 1, f);
  take(summary, "broken_zone", "depth_m", "broken_depth_m", 1, f);
  take_least_ray(summary, f);
  take(summary, "lining", "min_safety_factor", "lining_min_safety_factor", 1, f);
  if (const auto b = summary.find("bolts"); b != summary.end() && b->contains("each")) {
    double most = 0;
    long broken = 0;
    for (const auto& bolt : (*b)["each"]) {
      most = std::max(most, bolt.value("max_tension_kN_per_bar", 0.0));
      broken += bolt.value("broken", false) ? 1 : 0;
    }
    f["max_bolt_tension_kN_per_bar"] = most;
    f["bolts_with_broken_steel"] = broken;
  }
  if (const auto s = summary.find("support"); s != summary.end() && s->contains("verdict"))
    f["support_verdict"] = (*s)["verdict"];
}

}  // namespace

const std::vector<std::string>& key_point_names() {
  static const std::vector<std::string> names{"vault",     "left_shoulder", "right_shoulder",
                                              "left_wall", "right_wall",    "invert"};
  return names;
}

std::vector<std::string> figure_columns(const Scene& scene) {
  std::vector<std::string> c;
  if (is_specimen(scene)) {
    c.push_back("peak_stress_MPa");
    if (scene.mesh.kind == mesh::ModelKind::kUcs) c.push_back("modulus_GPa");
  } else {
    for (const std::string& p : key_point_names()) c.push_back(p + "_radial_mm");
    for (const char* p : kShoulders) c.push_back(std::string(p) + "_horizontal_mm");
    for (const Pair& pair : kPairs) c.push_back(pair.column);
    c.insert(c.end(), std::begin(kChords), std::end(kChords));
    for (const std::string& p : key_point_names()) c.push_back(p + "_since_support_mm");
    c.insert(c.end(), std::begin(kSupportColumns), std::end(kSupportColumns));
  }
  c.insert(c.end(), {"broken_I", "broken_II", "broken_mixed", "steps", "state_hash"});
  return c;
}

nlohmann::json key_figures(const nlohmann::json& summary) {
  nlohmann::json f = nlohmann::json::object();
  if (const auto m = summary.find("monitors"); m != summary.end() && m->is_object()) {
    for (const std::string& p : key_point_names())
      if (m->contains(p)) {
        take(*m, p.c_str(), "radial_mm", p + "_radial_mm", 1, f);
        take(*m, p.c_str(), "radial_since_support_mm", p + "_since_support_mm", 1, f);
      }
    for (const char* p : kShoulders)
      if (m->contains(p)) take(*m, p, "survey_mm", std::string(p) + "_horizontal_mm", 1, f);
    for (const auto& [target, column, l, r] : kPairs)
      if (f.contains(l) && f.contains(r)) f[column] = (f[l].get<double>() + f[r].get<double>()) / 2;
    for (const char* c : kChords) take(summary, "monitors", c, c, 1, f);
    take_support(summary, f);
  }
  take(summary, "specimen", "peak_stress", "peak_stress_MPa", 1e-6, f);
  take(summary, "specimen", "modulus", "modulus_GPa", 1e-9, f);
  take(summary, "broken", "mode_I", "broken_I", 1, f);
  take(summary, "broken", "mode_II", "broken_II", 1, f);
  take(summary, "broken", "mixed", "broken_mixed", 1, f);
  if (summary.contains("steps")) f["steps"] = summary["steps"];
  if (summary.contains("state_hash")) f["state_hash"] = summary["state_hash"];
  return f;
}

std::vector<TargetName> target_names(const Scene& scene) {
  std::vector<TargetName> names;
  if (scene.mesh.kind == mesh::ModelKind::kBrazilian)
    return {{"peak_stress", "peak_stress_MPa", "MPa"},
            {"tensile_strength", "peak_stress_MPa", "MPa"}};
  if (scene.mesh.kind == mesh::ModelKind::kUcs)
    return {{"peak_stress", "peak_stress_MPa", "MPa"}, {"modulus", "modulus_GPa", "GPa"}};
  for (const std::string& p : key_point_names()) names.push_back({p, p + "_radial_mm", "mm"});
  for (const char* p : kShoulders)
    names.push_back({std::string(p) + "_horizontal", std::string(p) + "_horizontal_mm", "mm"});
  for (const Pair& pair : kPairs) names.push_back({pair.target, pair.column, "mm"});
  for (const char* c : kChords) {
    const std::string column = c;
    names.push_back({column.substr(0, column.size() - 3), column, "mm"});
  }
  for (const std::string& p : key_point_names())
    names.push_back({p + "_since_support", p + "_since_support_mm", "mm"});
  return names;
}

const TargetName* find_target(const std::vector<TargetName>& names, const std::string& name) {
  for (const TargetName& t : names)
    if (t.name == name) return &t;
  return nullptr;
}

std::string describe(const std::vector<TargetName>& names) {
  std::string s = "allowed for this scene's model: ";
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i].name;
  return s + (names.front().unit == "mm"
                  ? " (key points: radial displacement towards the opening; *_horizontal: the "
                    "shoulders' horizontal convergence, as monitoring reads it; chords: "
                    "closure; mm)"
                  : " (the specimen's peak stress, MPa; UCS modulus: its pre-peak modulus, GPa)");
}

}  // namespace rockfdem::workflows::study
