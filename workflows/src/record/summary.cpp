#include "record/summary.hpp"

#include <algorithm>
#include <variant>

#include "record/support_equilibrium.hpp"
#include "record/survey_reading.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/version.hpp"

namespace rockfdem::workflows {
namespace {

// (a0, b0, a1, b1, ...): the engine's layout, so the hashes read alike.
std::vector<double> interleave(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(2 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[2 * i] = a[i];
    out[2 * i + 1] = b[i];
  }
  return out;
}

// "fdem setup" -> "fdem_setup": a phase's name as a JSON key.
std::string snake_case(std::string name) {
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}

// {"checkpoint" or "last": path, "step": step}.
nlohmann::json mark_json(const char* path_key, const CheckpointMark& m) {
  return {{path_key, m.path}, {"step", m.step}};
}

template <class T>
nlohmann::json or_null(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json();
}

// The counts among a stage's changes, under their summary.json names.
struct ChangeCount {
  const char* key;
  std::optional<long> StageChanges::*member;
};
constexpr ChangeCount kChangeCounts[] = {{"interface_cracks", &StageChanges::interface_cracks},
                                         {"bolts", &StageChanges::bolts},
                                         {"bolt_triangles", &StageChanges::bolt_triangles},
                                         {"steel_cracks", &StageChanges::steel_cracks},
                                         {"grout_cracks", &StageChanges::grout_cracks},
                                         {"clipped_points", &StageChanges::clipped_points},
                                         {"broken_before", &StageChanges::broken_before},
                                         {"rejoined", &StageChanges::rejoined},
                                         {"broken_after", &StageChanges::broken_after},
                                         {"broken_at_install", &StageChanges::broken_at_install},
                                         {"trigger_step", &StageChanges::trigger_step},
                                         {"broken_at_support", &StageChanges::broken_at_support}};

// The numbers and texts among them.
struct ChangeNumber {
  const char* key;
  std::optional<double> StageChanges::*member;
};
constexpr ChangeNumber kChangeNumbers[] = {{"trigger_value", &StageChanges::trigger_value},
                                           {"trigger_time", &StageChanges::trigger_time}};
struct ChangeText {
  const char* key;
  std::optional<std::string> StageChanges::*member;
};
constexpr ChangeText kChangeTexts[] = {{"positions_file", &StageChanges::positions_file},
                                       {"trigger", &StageChanges::trigger}};

template <class T, std::size_t N>
const T* change_entry(const T (&table)[N], const std::string& key) {
  for (const T& c : table)
    if (key == c.key) return &c;
  return nullptr;
}

const ChangeCount* change_count(const std::string& key) {
  for (const ChangeCount& c : kChangeCounts)
    if (key == c.key) return &c;
  return nullptr;
}

StageChanges::Figure other_figure(const nlohmann::json& v) {
  if (v.is_boolean()) return v.get<bool>();
  if (v.is_number_integer()) return v.get<long>();
  if (v.is_number()) return v.get<double>();
  return v.get<std::string>();
}

nlohmann::json stage_json(const StageRecord& s) {
  return {{"kind", s.kind},
          {"stage", s.number},
          {"changes", stage_changes_json(s.changes)},
          {"steps", s.steps},
          {"simulated_time", s.simulated_time},
          {"dt", or_null(s.dt)},
          {"unbalanced_ratio", s.unbalanced_ratio},
          {"settle", or_null(s.settle)},
          {"broken_growth", or_null(s.broken_growth)},
          {"converged", or_null(s.converged)},
          {"max_steps", s.max_steps},
          {"criteria",
           {{"ratio", s.ratio},
            {"settle", s.settle_limit},
            {"broken_settle", s.broken_settle_limit},
            {"hold", s.hold},
            {"unstable_fraction", s.unstable_fraction}}},
          {"moving_most",
           s.moving_most ? nlohmann::json{{"key_point", s.moving_most->key_point},
                                          {"mm_per_1000_steps", s.moving_most->mm_per_1000_steps}}
                         : nlohmann::json()},
          {"support_pressure_ratio", s.support_pressure_ratio}};
}

template <class T>
std::optional<T> optional_at(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null()) return std::nullopt;
  return j.at(key).get<T>();
}

StageRecord stage_from_json(const nlohmann::json& j) {
  StageRecord s;
  s.kind = j.at("kind").get<std::string>();
  s.number = j.at("stage").get<int>();
  s.changes = stage_changes_from_json(j.at("changes"));
  s.steps = j.at("steps").get<long>();
  s.simulated_time = j.at("simulated_time").get<double>();
  s.dt = optional_at<double>(j, "dt");
  s.unbalanced_ratio = j.at("unbalanced_ratio").get<double>();
  s.settle = optional_at<double>(j, "settle");
  s.broken_growth = optional_at<double>(j, "broken_growth");
  s.converged = optional_at<bool>(j, "converged");
  s.max_steps = j.at("max_steps").get<long>();
  const nlohmann::json& c = j.at("criteria");
  s.ratio = c.at("ratio").get<double>();
  s.settle_limit = c.at("settle").get<double>();
  s.broken_settle_limit = c.value("broken_settle", 0.0);
  s.hold = c.at("hold").get<int>();
  s.unstable_fraction = c.at("unstable_fraction").get<double>();
  const nlohmann::json& m = j.value("moving_most", nlohmann::json());
  if (m.is_object())
    s.moving_most =
        MovingMost{m.at("key_point").get<std::string>(), m.at("mm_per_1000_steps").get<double>()};
  s.support_pressure_ratio = j.at("support_pressure_ratio").get<double>();
  return s;
}

nlohmann::json fdem_json(const FdemRecord& f) {
  nlohmann::json j = nlohmann::json::object();
  if (f.unbalanced_ratio_at_start) j["unbalanced_ratio_at_start"] = *f.unbalanced_ratio_at_start;
  if (f.unbalanced_ratio_at_end) j["unbalanced_ratio_at_end"] = *f.unbalanced_ratio_at_end;
  if (f.handoff_alpha) j["handoff_alpha"] = *f.handoff_alpha;
  if (f.handoff) {
    nlohmann::json solved = nlohmann::json::array();
    for (std::size_t i = 0; i < f.handoff->alphas.size(); ++i)
      solved.push_back(
          {{"alpha", f.handoff->alphas[i]}, {"strength_ratio", f.handoff->strength_ratio[i]}});
    j["handoff"] = {{"rule", f.handoff->rule},
                    {"solved", solved},
                    {"crack_points_over_strength", f.handoff->crack_points_over_strength}};
  }
  if (f.stages) j["stages"] = stage_records_json(*f.stages);
  if (f.handoff_dt)
    j["handoff_step"] = {{"steps", 1}, {"dt", *f.handoff_dt}, {"simulated_time", *f.handoff_dt}};
  return j;
}

nlohmann::json specimen_json(const SpecimenRecord& s) {
  return {{"kind", s.kind},
          {"peak_stress", s.peak_stress},
          {"peak_force", s.peak_force},
          {"peak_step", s.peak_step},
          {"peak_strain", s.peak_strain},
          {"strain_rate", s.strain_rate},
          {"stop_after_peak", s.stop_after_peak},
          {"stopped_after_peak_at_step", or_null(s.stopped_after_peak_at_step)},
          {"modulus", or_null(s.modulus)}};
}

nlohmann::json energy_json(const fdem::EnergyBalance& en) {
  return {{"external_work", en.external_work},
          {"kinetic", en.kinetic},
          {"strain", en.strain},
          {"crack_elastic", en.crack_elastic},
          {"contact_elastic", en.contact_elastic},
          {"initial_stored", en.initial_stored},
          {"damping", en.damping},
          {"fracture", en.fracture},
          {"friction", en.friction},
          {"joint_friction", en.joint_friction},
          {"absorbing", en.absorbing},
          {"softening", en.softening},
          {"removed_by_stages", en.removed},
          {"residual", en.residual()},
          {"relative_imbalance", en.imbalance()}};
}

// steps, dt, simulated_time, broken, energy, state_hash.
void add_state(nlohmann::json& j, const EngineState& s) {
  j["steps"] = s.steps;
  j["dt"] = s.dt;
  j["simulated_time"] = s.simulated_time;
  j["broken"] = {
      {"mode_I", s.broken.mode_I}, {"mode_II", s.broken.mode_II}, {"mixed", s.broken.mixed}};
  if (s.energy) j["energy"] = energy_json(*s.energy);
  j["state_hash"] = s.state_hash;
}

nlohmann::json key_point_json(const std::string& name, const KeyPointFigures& k) {
  nlohmann::json j = {{"ux_mm", k.ux_mm},
                      {"uy_mm", k.uy_mm},
                      {"u_mm", k.u_mm},
                      {"radial_mm", k.radial_mm},
                      {"survey_mm", survey_reading(name, k)},
                      {"survey_direction", survey_direction(name)},
                      {"x", k.x},
                      {"y", k.y},
                      {"inward", {k.inward_x, k.inward_y}}};
  if (k.radial_since_support_mm) j["radial_since_support_mm"] = *k.radial_since_support_mm;
  if (k.survey_since_support_mm) j["survey_since_support_mm"] = *k.survey_since_support_mm;
  if (k.radial_at_handoff_mm) {
    j["radial_at_handoff_mm"] = *k.radial_at_handoff_mm;
    // The share the explicit (fracturing) stages add; none for a point that did not move.
    if (k.radial_mm != 0)
      j["explicit_share"] = (k.radial_mm - *k.radial_at_handoff_mm) / k.radial_mm;
  }
  if (k.from_unloaded_mm) {
    const auto [ux, uy] = *k.from_unloaded_mm;
    j["from_unloaded_base_fixed"] = {{"ux_mm", ux}, {"uy_mm", uy}, {"u_mm", std::hypot(ux, uy)}};
  }
  return j;
}

// Key points, chords, then the scene's monitors (a name of both: the monitor's).
nlohmann::json monitors_json(const MonitorRecord& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, k] : m.key_points) j[name] = key_point_json(name, k);
  if (m.chords) {
    j["vault_settlement_mm"] = m.chords->vault_settlement_mm;
    j["wall_chord_convergence_mm"] = m.chords->wall_chord_convergence_mm;
    j["shoulder_chord_convergence_mm"] = m.chords->shoulder_chord_convergence_mm;
  }
  for (const auto& [name, p] : m.points)
    j[name] = {{"ux_mm", p.ux_mm}, {"uy_mm", p.uy_mm},       {"u_mm", p.u_mm}, {"x", p.x},
               {"y", p.y},         {"triangle", p.triangle}, {"from", p.from}};
  return j;
}

nlohmann::json ground_reaction_json(const std::vector<GroundReactionPoint>& curve) {
  nlohmann::json j = nlohmann::json::array();
  for (const GroundReactionPoint& p : curve) {
    j.push_back({{"support_pressure_ratio", p.support_pressure_ratio},
                 {"vault_settlement_mm", p.vault_settlement_mm},
                 {"point", p.point}});
    for (const auto& [name, k] : p.key_points)
      j.back()["key_points"][name] = {{"radial_mm", k.radial_mm},
                                      {"pressure_Pa", k.pressure_Pa},
                                      {"insitu_Pa", k.insitu_Pa},
                                      {"pressure_ratio", k.pressure_Pa / k.insitu_Pa}};
  }
  return j;
}

// Where each support line meets the ground's curve (support_equilibrium.hpp).
void add_equilibria(nlohmann::json& j, const std::optional<SupportEquilibria>& eq) {
  if (!eq) return;
  const GroundCurve& g = eq->ground;
  j["ground_curve"] = {{"source", g.source}, {"extended_to_zero", g.extended_to_zero}};
  j["equilibrium"] = nlohmann::json::array();
  for (const SupportEquilibrium& e : eq->lines)
    j["equilibrium"].push_back({{"name", e.name},
                                {"found", e.found},
                                {"radial_mm", e.found ? nlohmann::json(e.radial_mm) : nullptr},
                                {"pressure_Pa", e.found ? nlohmann::json(e.pressure_Pa) : nullptr},
                                {"factor_of_safety", or_null(e.factor_of_safety)},
                                {"note", e.note}});
}

nlohmann::json convergence_confinement_json(const ConvergenceConfinementFigures& c) {
  nlohmann::json support = nlohmann::json::array();
  for (const SupportLineFigures& s : c.support) {
    support.push_back({{"name", s.name},
                       {"p_max_Pa", s.p_max_Pa},
                       {"stiffness_Pa_per_m", s.stiffness_Pa_per_m},
                       {"max_displacement_mm", s.max_displacement_mm}});
    if (!s.note.empty()) support.back()["note"] = s.note;
  }
  nlohmann::json install = {{"radial_mm", c.install_radial_mm}, {"alpha", c.install_alpha}};
  if (c.face)
    install["face"] = {{"face_distance_m", c.face->face_distance_m},
                       {"plastic_radius_m", c.face->plastic_radius_m},
                       {"x_star", c.face->x_star},
                       {"r_star", c.face->r_star},
                       {"u_star", c.face->u_star},
                       {"alpha", c.face->alpha}};
  return {{"radius_m", c.radius_m},
          {"lining_thickness_m", c.lining_thickness_m},
          {"support", support},
          {"installation", install},
          {"end", {{"radial_mm", c.end_radial_mm}, {"pressure_Pa", or_null(c.end_pressure_Pa)}}}};
}

nlohmann::json bolt_json(const BoltFigures& b) {
  nlohmann::json j = {{"name", b.name},
                      {"kind", b.kind},
                      {"head", b.head},
                      {"end", b.end},
                      {"installed", b.installed},
                      {"steel_cracks_yielding", b.steel_cracks_yielding},
                      {"steel_cracks_broken", b.steel_cracks_broken},
                      {"grout_cracks_broken", b.grout_cracks_broken}};
  if (!b.peak) return j;
  j["file"] = b.peak->file;
  j["max_axial_force_kN_per_bar"] = b.peak->max_axial_force_kN_per_bar;
  j["max_steel_stress_MPa"] = b.peak->max_steel_stress_MPa;
  j["max_tension_kN_per_bar"] = b.peak->max_tension_kN_per_bar;
  j["tension_station_m"] = b.peak->tension_station_m;
  j["tension_over_yield"] = b.peak->tension_over_yield;
  j["tension_over_ultimate"] = b.peak->tension_over_ultimate;
  j["max_compression_kN_per_bar"] = b.peak->max_compression_kN_per_bar;
  j["compression_station_m"] = b.peak->compression_station_m;
  j["first_broken_station_m"] = or_null(b.peak->first_broken_station_m);
  j["station_m"] = b.peak->station_m;
  j["yielded"] = b.peak->yielded;
  j["broken"] = b.peak->broken;
  return j;
}

nlohmann::json bolts_json(const BoltRecord& r) {
  nlohmann::json each = nlohmann::json::array();
  for (const BoltFigures& b : r.each) each.push_back(bolt_json(b));
  return {{"count", r.count},
          {"steel_cracks_yielding", r.steel_cracks_yielding},
          {"steel_cracks_broken", r.steel_cracks_broken},
          {"grout_cracks_broken", r.grout_cracks_broken},
          {"each", each}};
}

void add_capacity(nlohmann::json& j, const LiningCapacityFigures& c) {
  j["section"] = c.section;
  if (c.invert_section) j["invert_section"] = *c.invert_section;
  j["compressive_strength_Pa"] = c.compressive_strength_Pa;
  j["tensile_strength_Pa"] = c.tensile_strength_Pa;
  if (c.invert_compressive_strength_Pa) {
    j["invert_compressive_strength_Pa"] = *c.invert_compressive_strength_Pa;
    j["invert_tensile_strength_Pa"] = *c.invert_tensile_strength_Pa;
    j["min_safety_factor_in_invert"] = c.min_safety_factor_in_invert;
  }
  j["min_safety_factor"] = or_null(c.min_safety_factor);
  j["min_safety_factor_angle_deg"] = c.min_safety_factor_angle_deg;
  j["min_safety_factor_x_m"] = c.min_safety_factor_x_m;
  j["min_safety_factor_y_m"] = c.min_safety_factor_y_m;
  j["min_safety_factor_at_corner"] = c.min_safety_factor_at_corner;
  j["segments_below_1"] = c.segments_below_1;
}

nlohmann::json corners_json(const LiningCornerFigures& c) {
  return {{"segments", c.segments},
          {"max_thrust_kN_per_m", c.max_thrust_kN_per_m},
          {"max_thrust_angle_deg", c.max_thrust_angle_deg},
          {"min_thrust_kN_per_m", c.min_thrust_kN_per_m},
          {"min_thrust_angle_deg", c.min_thrust_angle_deg},
          {"max_abs_moment_kNm_per_m", c.max_abs_moment_kNm_per_m},
          {"max_abs_moment_angle_deg", c.max_abs_moment_angle_deg},
          {"exceed_sections", c.exceed_sections}};
}

void add_lining_forces(nlohmann::json& j, const LiningForceFigures& f) {
  j["file"] = "lining.csv";
  j["step"] = f.step;
  j["segments"] = f.segments;
  j["thickness_m"] = f.thickness_m;
  if (f.invert_thickness_m) j["invert_thickness_m"] = *f.invert_thickness_m;
  j["corner_segments"] = f.corner_segments;
  j["max_thrust_kN_per_m"] = f.max_thrust_kN_per_m;
  j["max_thrust_angle_deg"] = f.max_thrust_angle_deg;
  j["max_thrust_x_m"] = f.max_thrust_x_m;
  j["max_thrust_y_m"] = f.max_thrust_y_m;
  j["max_thrust_in_invert"] = f.max_thrust_in_invert;
  j["min_thrust_kN_per_m"] = f.min_thrust_kN_per_m;
  j["min_thrust_angle_deg"] = f.min_thrust_angle_deg;
  j["max_abs_moment_kNm_per_m"] = f.max_abs_moment_kNm_per_m;
  j["max_abs_moment_angle_deg"] = f.max_abs_moment_angle_deg;
  j["max_abs_shear_kN_per_m"] = f.max_abs_shear_kN_per_m;
  j["max_abs_shear_angle_deg"] = f.max_abs_shear_angle_deg;
  if (f.corners) j["corners"] = corners_json(*f.corners);
  j["capacity"] = f.capacity;
  if (f.check) add_capacity(j, *f.check);
}

nlohmann::json lining_json(const LiningRecord& r) {
  nlohmann::json j = nlohmann::json::object();
  if (r.interface)
    j = {{"interface_cracks", r.interface->first}, {"interface_broken", r.interface->second}};
  if (r.forces) add_lining_forces(j, *r.forces);
  return j;
}

nlohmann::json broken_zone_json(const BrokenZoneRecord& z) {
  nlohmann::json j = {{"broken_rock_cracks", z.broken_rock_cracks},
                      {"depth_m", z.depth_m},
                      {"fracture_zone_m", z.fracture_zone_m},
                      {"clearance_m", or_null(z.clearance_m)},
                      {"capped", z.capped}};
  if (!z.ray_half_width_m) return j;
  nlohmann::json rays = nlohmann::json::object();
  for (const auto& [name, r] : z.rays) {
    rays[name] = {{"depth_m", r.depth_m}, {"origin", r.origin}, {"direction", r.direction}};
    if (r.damaged_depth_m) rays[name]["broken_or_grouted_depth_m"] = *r.damaged_depth_m;
  }
  j["along_rays"] = rays;
  j["ray_half_width_m"] = *z.ray_half_width_m;
  return j;
}

nlohmann::json mass_scaling_json(const fdem::MassScalingReport& ms) {
  nlohmann::json j = {{"enabled", ms.enabled}};
  if (ms.enabled)
    j.update({{"target_dt", ms.target_dt},
              {"max_factor", ms.max_factor},
              {"mass_ratio", ms.mass_ratio},
              {"scaled_triangles", ms.scaled_triangles},
              {"note",
               "quasi-static: densities scaled, statics unchanged; "
               "simulated_time is pseudo-time"}});
  return j;
}

void add_engine(nlohmann::json& j, const EngineFigures& f) {
  const fdem::PhaseTimes& p = f.modules;
  j["fdem_modules"] = {
      {"triangles", p.triangles}, {"cracks", p.cracks}, {"nodes", p.nodes}, {"contact", p.contact}};
  const fdem::ContactCounters& c = f.contact;
  j["contact"] = {{"enabled", c.enabled},
                  {"detections", c.detections},
                  {"steps_with_pairs", c.steps_with_pairs},
                  {"steps_skipped", c.steps_skipped},
                  {"last_candidates", c.candidates},
                  {"last_pairs", c.pairs},
                  {"last_touching", c.touching},
                  {"kernel", c.kernel}};
  j["mass_scaling"] = mass_scaling_json(f.mass_scaling);
  j["memory_bytes"] = f.memory_bytes;
  j["memory_bytes_per_triangle"] = f.memory_bytes_per_triangle;
  // Nested by the name's dotted parts ("contact.grid.cell"), every key
  // snake_case; the empty arrays would only lengthen the file.
  nlohmann::json parts = nlohmann::json::object();
  for (const fdem::MemoryPart& p : f.memory_parts) {
    std::string path = "/" + p.name;
    std::replace(path.begin(), path.end(), '.', '/');
    if (p.bytes > 0) parts[nlohmann::json::json_pointer(path)] = p.bytes;
  }
  j["memory_breakdown_bytes"] = parts;
}

nlohmann::json insitu_json(const InsituRecord& r) {
  nlohmann::json j = {{"alpha", r.alpha},
                      {"solver_iterations", r.solver_iterations},
                      {"kirsch_rel_l2", or_null(r.kirsch_rel_l2)}};
  if (r.kirsch_wall_ur_rel_l2) j["kirsch_wall_ur_rel_l2"] = *r.kirsch_wall_ur_rel_l2;
  if (r.kirsch_triangles) j["kirsch_triangles"] = *r.kirsch_triangles;
  if (!r.stages) return j;
  j["stages"] = nlohmann::json::array();
  for (const InsituSolveFigures& s : *r.stages)
    j["stages"].push_back({{"alpha", s.alpha},
                           {"solver", s.solver},
                           {"dofs", s.dofs},
                           {"assembly_seconds", s.assembly_seconds},
                           {"solve_seconds", s.solve_seconds},
                           {"total_seconds", s.total_seconds},
                           {"preconditioner_seconds", s.preconditioner_seconds},
                           {"unbalanced_ratio", s.unbalanced_ratio}});
  return j;
}

nlohmann::json extensometer_json(const ExtensometerFigures& x) {
  nlohmann::json points = nlohmann::json::array();
  for (const ExtensometerPoint& p : x.points)
    points.push_back({{"point", p.point},
                      {"depth_m", p.depth_m},
                      {"relative_mm", p.relative_mm},
                      {"absolute_mm", p.absolute_mm}});
  return {{"head", x.head},         {"direction", x.direction}, {"from", or_null(x.from)},
          {"length_m", x.length_m}, {"read_from", x.read_from}, {"points", points}};
}

nlohmann::json comparison_json(const ContinuumComparison& c) {
  return {{"triangles", c.triangles},
          {"region", kComparisonRegion},
          {"fdem_vs_insitu_rel_l2", c.fdem_vs_insitu_rel_l2},
          {"fdem_vs_kirsch_rel_l2", or_null(c.fdem_vs_kirsch_rel_l2)}};
}

nlohmann::json counterpart_json(const CounterpartComparison& c) {
  nlohmann::json key_points = nlohmann::json::object();
  for (const auto& [name, k] : c.key_points)
    key_points[name] = {{"fdem_end_mm", k.fdem_end_mm},
                        {"continuum_end_mm", k.continuum_end_mm},
                        {"fdem_handoff_mm", k.fdem_handoff_mm},
                        {"continuum_handoff_mm", or_null(k.continuum_handoff_mm)}};
  nlohmann::json j = {{"model", c.model},
                      {"sequence_alpha", c.sequence_alpha},
                      {"solve_seconds", c.solve_seconds},
                      {"region", kComparisonRegion},
                      {"lining_alpha", or_null(c.lining_alpha)},
                      {"stress_rel_l2_end", c.stress_rel_l2_end},
                      {"stress_rel_l2_handoff", or_null(c.stress_rel_l2_handoff)},
                      {"key_points", key_points}};
  for (const ContinuumGroundReactionPoint& p : c.ground_reaction) {
    nlohmann::json point = {{"lambda", p.lambda}, {"key_points", nlohmann::json::object()}};
    for (const auto& [name, k] : p.key_points)
      point["key_points"][name] = {{"radial_mm", k.radial_mm}, {"pressure_Pa", k.pressure_Pa}};
    j["ground_reaction"].push_back(point);
  }
  if (!c.yield) return j;
  j["yielded_triangles"] = c.yield->triangles;
  for (const auto& [ray, depth] : c.yield->depth_m) j["yielded_depth_m"][ray] = depth;
  return j;
}

nlohmann::json plausibility_json(const RockPlausibilityFigures& p) {
  nlohmann::json j = {{"of", p.of},
                      {"ucs_Pa", p.ucs_Pa ? nlohmann::json(*p.ucs_Pa) : nlohmann::json()},
                      {"ucs_from",
                       "Mohr-Coulomb, 2 c cos(phi) / (1 - sin(phi)), of the rock's "
                       "crack elements"},
                      {"figures", nlohmann::json::object()},
                      {"outside", nlohmann::json::array()}};
  for (const PlausibilityFigure& f : p.figures) {
    j["figures"][f.name] = {{"value", f.value},
                            {"range", {f.low, f.high}},
                            {"in_range", f.in_range},
                            {"range_from", f.meaning}};
    if (!f.in_range) j["outside"].push_back(f.name);
  }
  return j;
}

nlohmann::json strength_json(double young, double c, double phi, double ft) {
  return {{"young_Pa", young},
          {"cohesion_Pa", c},
          {"friction_angle_deg", phi},
          {"tensile_strength_Pa", ft},
          {"ucs_Pa", mohr_coulomb_ucs(c, phi)}};
}

// The lab set, the rock mass the model uses, and the constants between them.
nlohmann::json rock_mass_json(const RockMassSpec& m) {
  const MaterialSpec& l = m.lab;
  const RockMassFigures& f = m.mass;
  return {{"gsi", m.gsi},
          {"disturbance", m.disturbance},
          {"hoek_brown_mi", m.mi},
          {"hoek_brown", {{"mb", f.mb}, {"s", f.s}, {"a", f.a}}},
          {"sigma_ci_Pa", m.intact.ucs},
          {"sigma_cm_Pa", f.sigma_cm},
          {"sigma_3max_Pa", f.sigma_3max},
          {"overburden_stress_Pa", m.gamma_h},
          {"laboratory", strength_json(l.young, l.cohesion, l.friction_angle, l.tensile_strength)},
          {"rock_mass", strength_json(f.young, f.cohesion, f.friction_angle, f.tensile_strength)},
          {"sources", m.ft_over_ucs > 0
                          ? "E: Hoek and Diederichs (2006); c, phi: Mohr-Coulomb fit of the "
                            "generalised Hoek-Brown criterion for tunnels (Hoek, Carranza-Torres "
                            "and Corkum 2002); ft = materials.rock.mass_ft_over_ucs x the mass's "
                            "Mohr-Coulomb UCS"
                          : "E: Hoek and Diederichs (2006); c, phi: Mohr-Coulomb fit of the "
                            "generalised Hoek-Brown criterion for tunnels, ft = s sigma_ci / mb "
                            "(Hoek, Carranza-Torres and Corkum 2002)"}};
}

nlohmann::json joints_json(const JointRecord& r) {
  const mesh::JointTraceReport& t = r.traces;
  return {{"traces",
           {{"generated", r.set_traces},
            {"from_file", r.dfn_traces},
            {"outside_rock", t.outside},
            {"split_by_opening", t.split},
            {"merged", t.merged},
            {"snapped", t.snapped},
            {"too_short", t.too_short},
            {"meshed", t.kept},
            {"length_m", t.length},
            {"sliver_tolerance_m", t.tolerance}}},
          {"elements", r.elements},
          {"active", r.active},
          {"yielding", r.yielding},
          {"residual", r.residual}};
}

// The support and damage figures at the end of a tunnel run.
void add_support(nlohmann::json& j, const RunRecord& r) {
  if (r.bolts) j["bolts"] = bolts_json(*r.bolts);
  if (!r.lining.empty()) j["lining"] = lining_json(r.lining);
  if (const auto& v = r.support)
    j["support"] = {{"verdict", v->verdict},
                    {"findings", v->findings},
                    {"notes", v->notes},
                    {"line", v->line()}};
  if (r.resolution)
    j["resolution"] = {{"h_m", r.resolution->h_m},
                       {"l_ch_m", r.resolution->l_ch_m},
                       {"h_over_l_ch", r.resolution->h_over_l_ch},
                       {"limit", r.resolution->limit}};
  if (r.rock_plausibility) j["rock_plausibility"] = plausibility_json(*r.rock_plausibility);
  if (r.rock_mass) j["rock_mass"] = rock_mass_json(*r.rock_mass);
  if (r.broken_zone) j["broken_zone"] = broken_zone_json(*r.broken_zone);
  if (r.joints) j["joints"] = joints_json(*r.joints);
  for (const auto& [name, x] : r.extensometers) j["extensometers"][name] = extensometer_json(x);
  if (const auto& b = r.outer_boundary)
    j["outer_boundary"] = {{"rotation_deg", b->rotation_deg},
                           {"max_rotation_deg", b->max_rotation_deg},
                           {"limit_deg", b->limit_deg},
                           {"translation_mm", b->translation_mm},
                           {"support", b->support}};
  if (const auto& d = r.damping)
    j["damping"] = {{"local", d->local},
                    {"mass_proportional", d->mass_proportional},
                    {"kinetic", d->kinetic},
                    {"local_given", d->local_given}};
}

}  // namespace

nlohmann::json stage_records_json(const std::vector<StageRecord>& stages) {
  nlohmann::json j = nlohmann::json::array();
  for (const StageRecord& s : stages) j.push_back(stage_json(s));
  return j;
}

std::vector<StageRecord> stage_records_from_json(const nlohmann::json& stages) {
  std::vector<StageRecord> out;
  for (const nlohmann::json& s : stages) out.push_back(stage_from_json(s));
  return out;
}

nlohmann::json stage_changes_json(const StageChanges& c) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, figure] : c.other)
    j[name] = std::visit([](const auto& v) { return nlohmann::json(v); }, figure);
  for (const ChangeCount& k : kChangeCounts)
    if (c.*k.member) j[k.key] = *(c.*k.member);
  for (const ChangeNumber& k : kChangeNumbers)
    if (c.*k.member) j[k.key] = *(c.*k.member);
  for (const ChangeText& k : kChangeTexts)
    if (c.*k.member) j[k.key] = *(c.*k.member);
  if (c.triggered) j["triggered"] = *c.triggered;
  if (c.skipped) j["skipped"] = *c.skipped;
  return j;
}

StageChanges stage_changes_from_json(const nlohmann::json& j) {
  StageChanges c;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const nlohmann::json& v = it.value();
    if (const ChangeCount* k = change_count(it.key()))
      c.*k->member = v.get<long>();
    else if (const ChangeNumber* n = change_entry(kChangeNumbers, it.key()))
      c.*n->member = v.get<double>();
    else if (const ChangeText* t = change_entry(kChangeTexts, it.key()))
      c.*t->member = v.get<std::string>();
    else if (it.key() == "triggered")
      c.triggered = v.get<bool>();
    else if (it.key() == "skipped")
      c.skipped = v.get<bool>();
    else
      c.other[it.key()] = other_figure(v);
  }
  return c;
}

std::string stage_change_mismatch(const std::string& key, const nlohmann::json& v) {
  if (change_count(key)) return v.is_number_integer() ? "" : "an integer";
  if (change_entry(kChangeNumbers, key)) return v.is_number() ? "" : "a number";
  if (change_entry(kChangeTexts, key)) return v.is_string() ? "" : "a string";
  if (key == "triggered" || key == "skipped") return v.is_boolean() ? "" : "true or false";
  return v.is_primitive() && !v.is_null() ? "" : "true, false, a number or a string";
}

RunRecord::RunRecord(const Scene& scene, int threads)
    : warnings(scene.warnings),
      threads(threads),
      counts{0, 0, 0, long(scene.bolts.segments.size())},
      rock_mass(scene.rock_mass),
      scene_source_(scene.source),
      overrides_(scene.overrides),
      title_(scene.title),
      timings_{{"mesh", 0.0}, {"insitu", 0.0}, {"fdem", 0.0}, {"output", 0.0}, {"total", 0.0}} {}

void RunRecord::note_turned_off(const OutputSettings& output, const std::string& paraview_files,
                                bool renders_plots) {
  if (!output.vtk) skipped.push_back("ParaView files (" + paraview_files + "): output.vtk = false");
  if (renders_plots && !output.plots) skipped.push_back("plots: output.plots = false");
}

void RunRecord::record_mesh(const mesh::Mesh& m, const mesh::MeshReport& report) {
  counts.triangles = long(m.n_triangles());
  counts.nodes = long(m.n_vertices());
  mesh = report;
  state.state_hash = fdem::bits_hash(interleave(m.x, m.y));
}

void RunRecord::record_insitu(const std::vector<insitu::InsituField>& fields) {
  insitu.alpha.clear();
  insitu.solver_iterations.clear();
  for (const insitu::InsituField& f : fields) {
    insitu.alpha.push_back(f.alpha);
    insitu.solver_iterations.push_back(f.iterations);
  }
  state.state_hash = fdem::bits_hash(interleave(fields.back().ux, fields.back().uy));
}

void RunRecord::record_convergence_confinement(ConvergenceConfinementFigures c) {
  support_equilibria = meet_ground_curve(c, ground_reaction_curve, continuum_comparison);
  convergence_confinement = std::move(c);
}

void RunRecord::set_timings(const PhaseTimer& timer) {
  for (const std::string& phase : timer.order()) {
    timings_[snake_case(phase)] = timer.seconds(phase);
    peak_memory_mib_[snake_case(phase)] = timer.peak_mib(phase);
  }
  timings_["total"] = timer.total();
}

nlohmann::json RunRecord::to_json() const {
  nlohmann::json j = {{"format_version", kSummaryFormatVersion},
                      {"rockfdem_version", version_string()},
                      {"scene", scene_source_},
                      {"overrides", overrides_},
                      {"title", title_},
                      {"threads", threads}};
  j["counts"] = {{"triangles", counts.triangles},
                 {"nodes", counts.nodes},
                 {"crack_elements", counts.crack_elements},
                 {"bolts", counts.bolts}};
  j["throughput"] = {{"triangle_steps_per_second", triangle_steps_per_second}};
  if (engine) add_engine(j, *engine);
  add_state(j, state);
  j["insitu"] = insitu_json(insitu);
  if (mesh)
    j["mesh"] = {{"triangles", mesh->n_triangles},
                 {"vertices", mesh->n_vertices},
                 {"min_altitude", mesh->min_altitude},
                 {"min_angle_deg", mesh->min_angle_deg},
                 {"seconds", mesh->seconds}};
  if (dt_range) {
    j["dt_min"] = dt_range->first;
    j["dt_max"] = dt_range->second;
  }
  if (fdem) j["fdem"] = fdem_json(*fdem);
  if (specimen) j["specimen"] = specimen_json(*specimen);
  j["monitors"] = monitors_json(monitors);
  if (!ground_reaction_curve.empty())
    j["ground_reaction_curve"] = ground_reaction_json(ground_reaction_curve);
  if (convergence_confinement) {
    j["convergence_confinement"] = convergence_confinement_json(*convergence_confinement);
    add_equilibria(j["convergence_confinement"], support_equilibria);
  }
  if (history_stages) j["history_stages"] = *history_stages;
  add_support(j, *this);
  if (comparison) j["comparison"] = comparison_json(*comparison);
  if (continuum_comparison) j["continuum_comparison"] = counterpart_json(*continuum_comparison);
  if (continuum_post_peak) {
    const PostPeakCounterpart& p = *continuum_post_peak;
    j["continuum_post_peak"] = {{"equilibrium", p.equilibrium},
                                {"alpha_reached", p.alpha},
                                {"yielded_triangles", p.n_yielded},
                                {"residual_friction_deg", p.residual_friction_deg},
                                {"reason", p.reason},
                                {"solve_seconds", p.seconds}};
  }
  if (!status.empty()) j["status"] = status;
  if (status_reason) j["status_reason"] = *status_reason;
  if (failure) j["failure"] = *failure;
  if (!warnings.empty()) j["warnings"] = warnings;
  j["skipped"] = skipped;
  if (restarted_from) j["restarted_from"] = mark_json("checkpoint", *restarted_from);
  if (checkpoint) j["checkpoint"] = mark_json("last", *checkpoint);
  j["timings"] = timings_;
  j["peak_memory_mib"] = peak_memory_mib_;
  return j;
}

void RunRecord::write(const std::string& path) const {
  coupling::atomic_write_text(path, to_json().dump(2) + "\n");
}

}  // namespace rockfdem::workflows
