#include "outputs/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "record/number_text.hpp"
#include "record/output_dir.hpp"
#include "record/support_equilibrium.hpp"
#include "record/survey_reading.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/printable.hpp"
#include "rockfdem/workflows/version.hpp"
#include "stages/registry.hpp"
#include "stages/stage.hpp"

namespace rockfdem::workflows {
namespace {

// Three significant digits (stresses, moduli, ratios).
std::string sig(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// A strength or stress [Pa] in MPa; "not given" for 0 (the scene's "none").
std::string mpa(double pa) { return pa == 0 ? "not given" : sig(pa / 1e6) + " MPa"; }

// A record's scalar as text; "-" where absent.
std::string value_text(long v) { return std::to_string(v); }
std::string value_text(double v) { return sig(v); }
template <class T>
std::string value_text(const std::optional<T>& v) {
  return v ? value_text(*v) : "-";
}

const char* shape_name(mesh::TunnelShape s) {
  switch (s) {
    case mesh::TunnelShape::kCircular:
      return "circular";
    case mesh::TunnelShape::kHorseshoe:
      return "horseshoe";
    case mesh::TunnelShape::kArched:
      return "arched";
    case mesh::TunnelShape::kRectangular:
      return "rectangular";
  }
  return "?";
}

void material_rows(std::ostream& md, const std::string& name, const MaterialSpec& m) {
  md << "| " << name << " | E " << sig(m.young / 1e9) << " GPa, nu " << sig(m.poisson)
     << ", density " << sig(m.density) << " kg/m^3 |\n";
  // The lining is an elastic liner: no crack elements, strengths for its check only.
  if (name == "lining" || name == "invert") {
    md << "| " << name << " strength (capacity check) | tension " << mpa(m.tensile_strength)
       << ", compression " << mpa(m.compressive_strength) << " |\n";
    return;
  }
  md << "| " << name << " cracks | ft " << mpa(m.tensile_strength) << ", c " << mpa(m.cohesion)
     << ", phi " << sig(m.friction_angle) << " deg (residual " << sig(m.residual_friction_angle)
     << " deg), GfI " << sig(m.fracture_energy_I) << " J/m^2, GfII " << sig(m.fracture_energy_II)
     << " J/m^2 |\n";
}

void opening_row(std::ostream& md, const Scene& s) {
  const mesh::TunnelSpec& t = s.mesh.tunnel;
  md << "| opening | " << shape_name(t.shape) << ", ";
  if (t.shape == mesh::TunnelShape::kCircular)
    md << "radius " << sig(t.radius) << " m";
  else
    md << "span " << sig(t.span) << " m, height " << sig(t.height) << " m";
  if (t.invert_rise > 0) md << ", curved invert rise " << sig(t.invert_rise) << " m";
  md << ", lining " << sig(1000 * t.lining_thickness) << " mm";
  if (t.invert_thickness != t.lining_thickness)
    md << " (" << sig(1000 * t.invert_thickness) << " mm in the floor part)";
  md << ", fracture zone " << sig(t.fracture_zone) << " m; domain " << sig(s.mesh.domain.width)
     << " x " << sig(s.mesh.domain.height) << " m |\n";
}

void inputs(std::ostream& md, const Scene& s, const RunRecord& r) {
  md << "## Inputs\n\n| what | value |\n|---|---|\n";
  if (s.mesh.kind == mesh::ModelKind::kTunnel) opening_row(md, s);
  const auto count = [&](std::size_t mesh::MeshReport::*n) {
    return r.mesh ? value_text(long((*r.mesh).*n)) : "-";
  };
  md << "| mesh | element size " << sig(s.mesh.size.size_near) << " m at the opening, "
     << sig(s.mesh.size.size_far) << " m at the boundary; " << count(&mesh::MeshReport::n_triangles)
     << " triangles, " << count(&mesh::MeshReport::n_vertices) << " vertices |\n";
  for (mesh::Zone z : {mesh::kLining, mesh::kRock})  // the core is excavated
    if (s.materials.count(z)) material_rows(md, mesh::zone_name(z), s.materials.at(z));
  if (s.invert) material_rows(md, "invert", *s.invert);
  if (const auto& m = s.rock_mass)
    md << "| rock: the rock mass of | GSI " << sig(m->gsi) << ", D " << sig(m->disturbance)
       << ", mi " << sig(m->mi) << " from the laboratory set E " << sig(m->lab.young / 1e9)
       << " GPa, UCS " << mpa(m->intact.ucs) << ", ft " << mpa(m->lab.tensile_strength)
       << " (E: Hoek and Diederichs 2006; c, phi: Hoek-Brown fit up to sigma3 "
       << mpa(m->mass.sigma_3max) << "; ft = s sigma_ci / mb) |\n";
  md << "| in-situ stress (compression +) | sigma_h " << mpa(s.insitu.sigma_h) << ", sigma_v "
     << mpa(s.insitu.sigma_v) << ", sigma_h at " << sig(s.insitu.angle_deg)
     << " deg from x |\n| core stiffness factors alpha (implicit) |";
  for (double a : s.insitu.alpha) md << ' ' << sig(a);
  md << " |\n";
  const BoltSettings& b = s.bolts;
  long cables = 0;
  for (auto c : b.is_cable) cables += c;
  if (!b.segments.empty())
    md << "| bolts | " << long(b.segments.size()) - cables << " bolts (diameter "
       << sig(1000 * b.bolt.diameter) << " mm, yield " << mpa(b.bolt.yield_strength) << "), "
       << cables << " cables (diameter " << sig(1000 * b.cable.diameter) << " mm, yield "
       << mpa(b.cable.yield_strength) << "), row spacing " << sig(b.bolt.row_spacing)
       << " m; grout E " << sig(s.grout.young / 1e9) << " GPa |\n";
}

void stages(std::ostream& md, const RunRecord& r) {
  md << "\n## Stages\n\n| # | stage | steps | simulated time [s] | unbalanced ratio at end | "
        "status |\n|---|---|---|---|---|---|\n";
  if (!r.fdem) return;
  if (r.fdem->handoff_dt) {
    md << "| 0 | insitu: hand-off step (implicit to explicit";
    if (r.fdem->handoff_alpha) md << ", alpha " << sig(*r.fdem->handoff_alpha);
    md << ") | 1 | " << sig(*r.fdem->handoff_dt) << " | - | ";
    if (r.fdem->handoff)
      md << value_text(r.fdem->handoff->crack_points_over_strength)
         << " crack points handed over beyond their strength";
    else
      md << "-";
    md << " |\n";
  }
  for (const StageRecord& st : r.fdem->stages.value_or(std::vector<StageRecord>{}))
    md << "| " << st.number << " | " << st.kind << " | " << value_text(st.steps) << " | "
       << value_text(st.simulated_time) << " | " << value_text(st.unbalanced_ratio) << " | "
       << stage_of(st.kind).outcome(st) << " |\n";
}

void status(std::ostream& md, const RunRecord& r) {
  md << "\n## Status\n\n**" << (r.status.empty() ? "unknown" : r.status) << "**";
  if (r.status_reason) md << ": " << *r.status_reason;
  if (r.failure) md << ": " << *r.failure;
  md << "\n\n";
  if (r.support) {
    md << "**Support " << r.support->verdict << "**" << r.support->findings_text() << "\n\n";
    for (const std::string& n : r.support->notes) md << "- " << n << '\n';
    if (!r.support->notes.empty()) md << '\n';
  }
  const std::optional<double> none;
  md << "- steps " << value_text(r.state.steps) << ", simulated time "
     << value_text(r.state.simulated_time) << " s (pseudo-time where masses are "
     << "scaled)\n- unbalanced-force ratio: "
     << value_text(r.fdem ? r.fdem->unbalanced_ratio_at_start : none)
     << " after the hand-off step, " << value_text(r.fdem ? r.fdem->unbalanced_ratio_at_end : none)
     << " at the end (a stage's equilibrium criterion: below its `ratio`, with the key points "
        "settled; whether it was met is the status above)\n";
  for (const std::string& w : r.warnings)  // the support's is stated above
    if (!r.support || w != r.support->line()) md << "- warning: " << w << '\n';
}

std::optional<double> find_in(const std::map<std::string, double>& m, const std::string& name) {
  const auto i = m.find(name);
  return i == m.end() ? std::nullopt : std::optional<double>(i->second);
}

// A key point's figures beside its radial one; a chord has none.
struct PointFigures {
  std::optional<double> at_handoff;    ///< what the implicit stage gave
  std::optional<double> survey;        ///< as monitoring reads it
  std::optional<double> survey_since;  ///< that since the support's installation
};

PointFigures point_figures(const std::string& name, const KeyPointFigures& k) {
  return {k.radial_at_handoff_mm, survey_reading(name, k), k.survey_since_support_mm};
}

// A row of the key-point table: the figure, since support, the reference.
void point_row(std::ostream& md, const std::string& name, double total, const ReportExtras& x,
               const ReferenceSettings& ref, const PointFigures& p = {}) {
  const auto& [at_handoff, survey, survey_since] = p;
  md << "| " << name << " | " << fixed(total, 2) << " | "
     << (at_handoff ? fixed(*at_handoff, 2) : std::string("-")) << " | ";
  const std::optional<double> since = find_in(x.since_support_mm, name);
  md << (since ? fixed(*since, 2) : std::string("-")) << " | ";
  if (ref.survey)
    md << (survey ? fixed(*survey, 2) + " (" + survey_direction(name) + ")" : std::string("-"))
       << " | ";
  const auto r = ref.mm.find(name);
  if (r == ref.mm.end()) {
    md << "- | - |\n";
    return;
  }
  // Like for like: the reading and the origin the references state.
  const bool read_survey = ref.survey && survey;
  const std::optional<double> from_support = read_survey ? survey_since : since;
  const double computed =
      ref.from_support && from_support ? *from_support : (read_survey ? *survey : total);
  md << fixed(r->second, 2) << " | " << fixed(computed - r->second, 2) << " ("
     << (r->second != 0 ? fixed(100 * (computed - r->second) / std::abs(r->second), 1) + "%"
                        : std::string("-"))
     << ") |\n";
}

// The key points in the tables' order: crown, arch, walls, floor.
constexpr const char* kKeyPointOrder[] = {"vault",     "left_shoulder", "right_shoulder",
                                          "left_wall", "right_wall",    "invert"};

// The key points as a model loaded from zero stress on a fixed base reads
// them, for comparison with figures reported that way.
void from_unloaded(std::ostream& md, const MonitorRecord& mon) {
  std::ostringstream rows;
  for (const char* p : kKeyPointOrder) {
    const auto k = mon.key_points.find(p);
    if (k == mon.key_points.end() || mon.points.count(p) || !k->second.from_unloaded_mm) continue;
    const auto [ux, uy] = *k->second.from_unloaded_mm;
    rows << "| " << p << " | " << fixed(ux, 1) << " | " << fixed(uy, 1) << " | "
         << fixed(std::hypot(ux, uy), 1) << " |\n";
  }
  if (rows.str().empty()) return;
  md << "\nThe same points as a model loaded from zero stress reads them (its outer boundary "
        "loaded with the in-situ stresses, its base held, displacement from the unloaded mesh): "
        "the above plus the intact box's own elastic compression under the in-situ stress. For "
        "comparison with figures reported that way only; the excavation's effect is the table "
        "above.\n\n| point | ux [mm] | uy [mm] | magnitude [mm] |\n|---|---|---|---|\n"
     << rows.str();
}

// A fracturing run compared with references: its figures are one mesh's.
void mesh_caveat(std::ostream& md, const ReferenceSettings& ref, const fdem::BrokenCounts& b) {
  if (ref.mm.empty() || b.total() == 0) return;
  md << "\nThese figures are this mesh's: crack paths follow its edges, and meshes of "
        "nearly the same element size read a fracturing tunnel's key points differently (on "
        "the default tunnel the vault by about 10%, one standard deviation, far more than a "
        "strength scatter on one mesh). For the answer with its spread, sweep nearby element "
        "sizes (`rockfdem sweep SCENE --vary mesh.size_near=...`, docs/studies.md).\n";
}

void key_points(std::ostream& md, const Scene& s, const MonitorRecord& mon, const ReportExtras& x,
                const fdem::BrokenCounts& broken) {
  const ReferenceSettings& ref = s.references;
  md << "\n## Key points and chords (end of run)\n\nRadial displacement: towards the opening "
        "positive, from the in-situ state (the implicit deconfinement included), at the "
        "hand-off (what the implicit elastic stage gave) and since the support's installation. "
        "Chords: closure between two key points.";
  if (!ref.mm.empty())
    md << " References" << (ref.source.empty() ? "" : " (" + ref.source + ")")
       << " are measured from "
       << (ref.from_support ? "the support's installation" : "the in-situ state")
       << (ref.survey ? " and read as monitoring reads them (the vault's settlement and the "
                        "invert's heave vertical, the shoulders' and walls' convergence "
                        "horizontal: the survey column)"
                      : "")
       << "; difference = computed - reference.";
  md << "\n\n| point | radial [mm] | at hand-off [mm] | since support [mm] | "
     << (ref.survey ? "survey [mm] | " : "") << "reference [mm] | difference [mm] |\n"
     << (ref.survey ? "|---|---|---|---|---|---|---|\n" : "|---|---|---|---|---|---|\n");
  for (const char* p : kKeyPointOrder) {
    const auto k = mon.key_points.find(p);
    // A scene monitor of the same name stands in the summary instead.
    if (k != mon.key_points.end() && !mon.points.count(p))
      point_row(md, p, k->second.radial_mm, x, ref, point_figures(p, k->second));
  }
  if (mon.chords) {
    point_row(md, "wall_chord", mon.chords->wall_chord_convergence_mm, x, ref);
    point_row(md, "shoulder_chord", mon.chords->shoulder_chord_convergence_mm, x, ref);
    md << "\nVault settlement (-uy): " << fixed(mon.chords->vault_settlement_mm, 2) << " mm.\n";
  }
  mesh_caveat(md, ref, broken);
  from_unloaded(md, mon);
}

std::string value_text(bool v) { return v ? "yes" : "no"; }

std::string percent(double share) { return fixed(100 * share, 0) + "%"; }

// How much of the vault's displacement is the implicit elastic stage's.
void vault_origin(std::ostream& md, const MonitorRecord& mon, const ReportExtras& x) {
  const auto v = mon.key_points.find("vault");
  if (v == mon.key_points.end() || mon.points.count("vault") || !v->second.radial_at_handoff_mm ||
      v->second.radial_mm == 0)
    return;
  const double total = v->second.radial_mm, implicit = *v->second.radial_at_handoff_mm;
  md << "Of the vault's " << fixed(total, 1) << " mm, " << fixed(implicit, 1) << " mm ("
     << percent(implicit / total) << ") came from the implicit elastic stage and "
     << fixed(total - implicit, 1) << " mm (" << percent((total - implicit) / total)
     << ") from the explicit stages";
  const auto since = x.since_support_mm.find("vault");
  if (since != x.since_support_mm.end())
    md << "; " << fixed(since->second, 1) << " mm since the support's installation";
  md << ".";
}

// The fit's truth: displacement by stage, fracture, the rock set's figures.
void answer_origin(std::ostream& md, const RunRecord& r, const ReportExtras& x) {
  const std::optional<RockPlausibilityFigures>& p = r.rock_plausibility;
  if (!p) return;
  md << "\n## Where the answer comes from\n\n";
  vault_origin(md, r.monitors, x);
  if (r.counts.crack_elements == 0) {
    md << " The model has no crack elements: the rock cannot fracture (no tensile strength or "
          "cohesion given, or no fracture zone).\n";
    return;
  }
  md << " Broken crack elements: " << value_text(r.state.broken.total())
     << (r.broken_zone ? " (" + value_text(r.broken_zone->broken_rock_cracks) + " in the rock)"
                       : std::string())
     << ".\n\nThe rock set against real rock, judged on " << p->of;
  if (p->ucs_Pa)
    md << ", UCS " << sig(*p->ucs_Pa / 1e6)
       << " MPa (Mohr-Coulomb, 2 c cos(phi) / (1 - sin(phi)), of its c and phi)";
  if (p->figures.empty()) {
    md << ": none to show (no cohesion and no fracture energy given).\n";
    return;
  }
  md << ":\n\n| figure | value | range | within |\n|---|---|---|---|\n";
  for (const PlausibilityFigure& f : p->figures)
    md << "| " << f.name << " | " << sig(f.value) << " | " << sig(f.low) << " - " << sig(f.high)
       << " (" << f.meaning << ") | " << value_text(f.in_range) << " |\n";
}

void bolts(std::ostream& md, const std::optional<BoltRecord>& r) {
  if (!r) return;
  md << "\n## Bolts and cables (end of run)\n\nForces per bar; a station is broken where a "
        "crack element of its steel failed, in tension or in shear.\n\n| bolt | kind | max "
        "tension [kN] | at [m from the collar] | tension / yield | tension / ultimate | max "
        "compression [kN] | at [m] | yielded | broken at [m from the collar] |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BoltFigures& b : r->each) {
    md << "| " << b.name << " | " << b.kind << " | ";
    if (const auto& p = b.peak)
      md << fixed(p->max_tension_kN_per_bar, 1) << " | " << fixed(p->tension_station_m, 2) << " | "
         << fixed(p->tension_over_yield, 2) << " | " << fixed(p->tension_over_ultimate, 2) << " | "
         << fixed(p->max_compression_kN_per_bar, 1) << " | " << fixed(p->compression_station_m, 2)
         << " | " << value_text(p->yielded) << " | "
         << (p->first_broken_station_m ? fixed(*p->first_broken_station_m, 2) : std::string("no"))
         << " |\n";
    else
      md << "- | - | - | - | - | - | - | - |\n";
  }
  md << "\nSteel crack elements yielding " << value_text(r->steel_cracks_yielding) << ", broken "
     << value_text(r->steel_cracks_broken) << "; grout crack elements broken "
     << value_text(r->grout_cracks_broken) << ".\n";
}

// A figure with its value (units in the text) and where it holds.
void figure_row(std::ostream& md, const std::string& figure, const std::string& value,
                const std::string& where = "") {
  md << "| " << figure << " | " << value << " | " << where << " |\n";
}

std::string at_angle(double deg) { return "at " + fixed(deg, 0) + " deg"; }

// A section force: whole units from 1000 up, else three significant digits.
std::string force(double v) { return std::abs(v) >= 1000 ? fixed(v, 0) : sig(v); }

void capacity_rows(std::ostream& md, const LiningForceFigures& f, const LiningCapacityFigures& c) {
  std::string strengths =
      "tension " + mpa(c.tensile_strength_Pa) + ", compression " + mpa(c.compressive_strength_Pa);
  if (c.invert_compressive_strength_Pa)
    strengths += "; floor part: tension " + mpa(*c.invert_tensile_strength_Pa) + ", compression " +
                 mpa(*c.invert_compressive_strength_Pa);
  figure_row(md, "strengths", strengths);
  figure_row(md, "section type",
             c.invert_section ? "arch and walls " + c.section + "; floor part " + *c.invert_section
                              : c.section);
  if (c.min_safety_factor)
    figure_row(md, "smallest safety factor", fixed(*c.min_safety_factor, 2),
               std::string(c.min_safety_factor_in_invert ? "in the floor part, " : "") +
                   at_angle(c.min_safety_factor_angle_deg) + " (x " +
                   fixed(c.min_safety_factor_x_m, 2) + " m, y " +
                   fixed(c.min_safety_factor_y_m, 2) + " m)" +
                   (c.min_safety_factor_at_corner ? ", at a corner" : ""));
  else
    figure_row(md, "smallest safety factor", "-", "the ring carries nothing");
  figure_row(md, "segments below 1",
             value_text(c.segments_below_1) + " of " + value_text(f.segments));
}

// The corners' extremes, where they pass the sections': stress
// concentrations at the kinks, not design figures.
void corner_rows(std::ostream& md, const LiningCornerFigures& c) {
  const std::string where = "at a corner (a kink, no beam section), ";
  figure_row(md, "corners: largest thrust", force(c.max_thrust_kN_per_m) + " kN/m",
             where + at_angle(c.max_thrust_angle_deg));
  figure_row(
      md, "corners: smallest thrust", force(c.min_thrust_kN_per_m) + " kN/m",
      where + at_angle(c.min_thrust_angle_deg) + (c.min_thrust_kN_per_m < 0 ? " (tension)" : ""));
  figure_row(md, "corners: largest moment (magnitude)",
             force(c.max_abs_moment_kNm_per_m) + " kNm/m",
             where + at_angle(c.max_abs_moment_angle_deg));
}

void lining(std::ostream& md, const LiningRecord& r) {
  if (r.empty()) return;
  md << "\n## Lining (end of run)\n\nSection forces per metre of tunnel; thrust "
        "compression positive; angles about the opening's centroid from +x, counter-clockwise (90 "
        "crown, 270 invert); figures per segment in lining.csv. The extremes are those of the "
        "beam sections; the ring's corners (where it turns sharply, at the floor) are given "
        "apart where theirs are larger.\n\n"
        "| figure | value | where |\n|---|---|---|\n";
  if (const auto& f = r.forces) {
    figure_row(md, "section",
               fixed(1000 * f->thickness_m, 0) + " mm" +
                   (f->invert_thickness_m
                        ? "; floor part " + fixed(1000 * *f->invert_thickness_m, 0) + " mm"
                        : std::string()));
    figure_row(md, "capacity check", f->capacity);
    if (f->check) capacity_rows(md, *f, *f->check);
    figure_row(md, "largest thrust", force(f->max_thrust_kN_per_m) + " kN/m",
               std::string(f->max_thrust_in_invert ? "in the floor part, " : "") +
                   at_angle(f->max_thrust_angle_deg) + " (x " + fixed(f->max_thrust_x_m, 2) +
                   " m, y " + fixed(f->max_thrust_y_m, 2) + " m)");
    figure_row(
        md, "smallest thrust", force(f->min_thrust_kN_per_m) + " kN/m",
        at_angle(f->min_thrust_angle_deg) + (f->min_thrust_kN_per_m < 0 ? " (tension)" : ""));
    figure_row(md, "largest moment (magnitude)", force(f->max_abs_moment_kNm_per_m) + " kNm/m",
               at_angle(f->max_abs_moment_angle_deg));
    figure_row(md, "largest shear (magnitude)", force(f->max_abs_shear_kN_per_m) + " kN/m",
               at_angle(f->max_abs_shear_angle_deg));
    figure_row(md, "segments",
               value_text(f->segments) + " (" + value_text(f->corner_segments) + " at corners)",
               "lining.csv, step " + value_text(f->step));
    if (f->corners && f->corners->exceed_sections) corner_rows(md, *f->corners);
  }
  if (r.interface)
    figure_row(md, "lining-rock bond",
               value_text(r.interface->second) + " of " + value_text(r.interface->first) +
                   " crack elements broken",
               "where broken, the ring slides on the rock");
}

void joint_rows(std::ostream& md, const std::optional<JointRecord>& j) {
  if (!j) return;
  figure_row(md, "joint traces meshed",
             value_text(j->traces.kept) + " (" + fixed(j->traces.length, 1) + " m; " +
                 value_text(j->set_traces) + " from the sets, " + value_text(j->dfn_traces) +
                 " from the file)",
             value_text(j->traces.merged) + " merged, " + value_text(j->traces.snapped) +
                 " snapped, " + value_text(j->traces.too_short) + " dropped as slivers");
  figure_row(md, "joint crack elements",
             value_text(j->elements) + " (" + value_text(j->active) + " active)",
             "not counted among the broken: a joint element never breaks");
  figure_row(md, "joint elements past the peak",
             value_text(j->yielding) + " softening, " + value_text(j->residual) +
                 " sliding on residual friction");
}

void broken_zone(std::ostream& md, const fdem::BrokenCounts& b,
                 const std::optional<BrokenZoneRecord>& z, const std::optional<JointRecord>& j) {
  md << "\n## Broken zone (end of run)\n\n| figure | value | note |\n|---|---|---|\n";
  figure_row(md, "broken crack elements, all",
             value_text(b.total()) + " (mode I " + value_text(b.mode_I) + ", mode II " +
                 value_text(b.mode_II) + ", mixed " + value_text(b.mixed) +
                 "): the rock's, the bolts' steel and grout, the lining-rock bond");
  joint_rows(md, j);
  if (!z) return;
  figure_row(md, "broken between two rock triangles",
             value_text(z->broken_rock_cracks) + " (in the fracture zone, away from bolts)");
  figure_row(md, "deepest from the opening", fixed(z->depth_m, 2) + " m");
  figure_row(md, "fracture zone depth", fixed(z->fracture_zone_m, 2) + " m",
             "crack elements exist within it");
  figure_row(md, "clearance to the zone's edge",
             z->clearance_m ? fixed(*z->clearance_m, 2) + " m" : std::string("- (none broken)"),
             z->capped ? "capped: the zone limits the damage" : "not capped");
  if (z->rays.empty()) return;
  const bool grouted = z->rays.begin()->second.damaged_depth_m.has_value();
  md << "\n| ray from | broken depth [m] |" << (grouted ? " broken or grouted [m] |" : "")
     << "\n|---|---|" << (grouted ? "---|" : "") << "\n";
  for (const auto& [name, r] : z->rays) {
    md << "| " << name << " | " << value_text(r.depth_m) << " |";
    if (r.damaged_depth_m) md << " " << value_text(*r.damaged_depth_m) << " |";
    md << "\n";
  }
  if (z->ray_half_width_m)
    md << "\nRays take broken elements within " << fixed(*z->ray_half_width_m, 3)
       << " m of them.\n";
}

// The scene's monitors and extensometers at the end.
void instruments(std::ostream& md, const RunRecord& r) {
  if (r.monitors.points.empty() && r.extensometers.empty()) return;
  md << "\n## Instruments (end of run)\n";
  if (!r.monitors.points.empty()) {
    md << "\n| monitor | x [m] | y [m] | read from | ux [mm] | uy [mm] | \\|u\\| [mm] |\n"
          "|---|---|---|---|---|---|---|\n";
    for (const auto& [name, p] : r.monitors.points)
      md << "| " << name << " | " << fixed(p.x, 2) << " | " << fixed(p.y, 2) << " | " << p.from
         << " | " << fixed(p.ux_mm, 2) << " | " << fixed(p.uy_mm, 2) << " | " << fixed(p.u_mm, 2)
         << " |\n";
  }
  if (r.extensometers.empty()) return;
  md << "\nExtensometers: the head's reading against the deepest anchor (what the instrument "
        "gives) and the head's own displacement towards the opening.\n\n| extensometer | from | "
        "read from | length [m] | head to deepest anchor [mm] | head [mm] |\n"
        "|---|---|---|---|---|---|\n";
  for (const auto& [name, x] : r.extensometers) {
    const bool any = !x.points.empty();
    md << "| " << name << " | "
       << x.from.value_or("(" + fixed(x.head[0], 2) + ", " + fixed(x.head[1], 2) + ")") << " | "
       << x.read_from << " | " << fixed(x.length_m, 2) << " | "
       << (any ? fixed(x.points.front().relative_mm, 2) : "-") << " | "
       << (any ? fixed(x.points.front().absolute_mm, 2) : "-") << " |\n";
  }
}

// Radial (towards the opening) of an [ux, uy] pair at key point k [mm].
double radial_of(const std::array<double, 2>& u, const KeyPointFigures& k) {
  return u[0] * k.inward_x + u[1] * k.inward_y;
}

// The FDEM against the continuum solution of the same sequence
// (summary continuum_comparison): what fracture changed.
void continuum(std::ostream& md, const RunRecord& r) {
  if (!r.continuum_comparison) return;
  const CounterpartComparison& c = *r.continuum_comparison;
  md << "\n## The continuum counterpart\n\nThe same construction sequence solved as a "
     << (c.model == "mohr_coulomb" ? "Mohr-Coulomb elasto-plastic" : "linear elastic")
     << " continuum (no cracks) to alpha 0, against the FDEM at the end of the run. Radial "
        "displacement from the in-situ state, towards the opening positive, at the key "
        "point's vertex (without the boundary fit of the key-point table above). Stresses: "
        "relative L2 difference over the "
     << kComparisonRegion << ", " << fixed(100 * c.stress_rel_l2_end, 1) << "% at the end";
  if (c.stress_rel_l2_handoff)
    md << " (" << fixed(100 * *c.stress_rel_l2_handoff, 1) << "% at the hand-off)";
  md << "; along the rays: continuum_profiles.csv.\n\n| point | FDEM [mm] | continuum [mm] | "
        "FDEM - continuum [mm] |";
  if (c.yield) md << " yielded depth [m] |";
  md << "\n|---|---|---|---|" << (c.yield ? "---|" : "") << "\n";
  for (const char* name : kKeyPointOrder) {
    const auto at = c.key_points.find(name);
    const auto fig = r.monitors.key_points.find(name);
    if (at == c.key_points.end() || fig == r.monitors.key_points.end()) continue;
    const CounterpartKeyPoint& k = at->second;
    const double f = radial_of(k.fdem_end_mm, fig->second);
    const double m = radial_of(k.continuum_end_mm, fig->second);
    md << "| " << name << " | " << fixed(f, 2) << " | " << fixed(m, 2) << " | " << fixed(f - m, 2)
       << " |";
    if (c.yield) {
      const auto d = c.yield->depth_m.find(name);
      md << " " << (d == c.yield->depth_m.end() ? "-" : fixed(d->second, 2)) << " |";
    }
    md << "\n";
  }
  if (c.yield)
    md << "\nYielded triangles in the continuum: " << value_text(long(c.yield->triangles)) << ".\n";
}

// The support lines against the ground's curve (summary
// convergence_confinement): the method's equilibrium beside the run's end.
void convergence_confinement(std::ostream& md, const RunRecord& r) {
  if (!r.convergence_confinement || r.convergence_confinement->support.empty()) return;
  const ConvergenceConfinementFigures& c = *r.convergence_confinement;
  const std::optional<SupportEquilibria>& eq = r.support_equilibria;
  md << "\n## Convergence-confinement\n\nThe support lines on the equivalent circle (R = "
     << fixed(c.radius_m, 2) << " m";
  const bool parts = std::any_of(c.support.begin(), c.support.end(),
                                 [](const SupportLineFigures& s) { return !s.note.empty(); });
  if (parts)
    md << ", the ring taken in its parts, below";
  else if (c.lining_thickness_m > 0)
    md << ", ring " << fixed(c.lining_thickness_m, 2) << " m thick";
  md << "), installed at the key points' mean radial displacement of "
     << fixed(c.install_radial_mm, 1) << " mm from the in-situ state (core at alpha "
     << sig(c.install_alpha) << ")";
  if (!eq) {
    md << "; no ground reaction curve to meet (fewer than two implicit solves).\n";
    return;
  }
  md << ", against the ground's curve: "
     << (eq->ground.source == "mohr_coulomb"
             ? "the Mohr-Coulomb counterpart's unsupported release"
             : std::string("the implicit (elastic) stage's") +
                   (eq->ground.extended_to_zero ? ", carried on straight to p = 0" : ""))
     << " (key points' mean). Where a line meets it is the method's equilibrium; p_max over "
        "the pressure there is the support's factor of safety.\n\n| support | p_max [MPa] | "
        "K [MPa/m] | p_max after [mm] | meets the ground at [mm] | pressure [MPa] | factor "
        "of safety | |\n|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < eq->lines.size(); ++i) {
    const SupportLineFigures& s = c.support[i];
    const SupportEquilibrium& e = eq->lines[i];
    md << "| " << s.name << " | " << sig(s.p_max_Pa / 1e6) << " | "
       << sig(s.stiffness_Pa_per_m / 1e6) << " | " << fixed(s.max_displacement_mm, 1) << " | "
       << (e.found ? fixed(e.radial_mm, 1) : "-") << " | "
       << (e.found ? sig(e.pressure_Pa / 1e6) : "-") << " | "
       << (e.factor_of_safety ? fixed(*e.factor_of_safety, 2) : "-") << " | " << e.note << " |\n";
  }
  for (const SupportLineFigures& s : c.support)
    if (!s.note.empty()) md << "\nThe " << s.name << ": " << s.note << ".\n";
  md << "\nThe run ended at " << fixed(c.end_radial_mm, 1) << " mm";
  if (c.end_pressure_Pa) {
    md << " with the ring's pressure (its mean thrust over R) at " << sig(*c.end_pressure_Pa / 1e6)
       << " MPa";
    for (const SupportLineFigures& s : c.support)
      if ((s.name == "shotcrete" || s.name == "lining ring") && s.p_max_Pa > 0)
        md << ", " << fixed(*c.end_pressure_Pa / s.p_max_Pa, 2) << " times the ring's p_max";
  }
  md << ": what differs from the equilibria above is what the continuum curve leaves out "
        "(fracture, gravity, the stages after the installation).\n";
}

// The post-peak continuum's verdict (insitu.continuum_post_peak).
void post_peak(std::ostream& md, const std::optional<PostPeakCounterpart>& p) {
  if (!p) return;
  md << "\n## Does the ground stand on its own post-peak strength?\n\nThe Mohr-Coulomb "
        "continuum, dropping to c = 0 and phi = "
     << sig(p->residual_friction_deg)
     << " deg where it yields (a broken crack element keeps friction only), "
     << (p->equilibrium
             ? "finds an equilibrium: " + value_text(long(p->n_yielded)) + " triangles yielded"
             : "finds no equilibrium: " + p->reason)
     << " (solved in " << sig(p->seconds) << " s).\n";
}

void pictures(std::ostream& md, const ReportExtras& x) {
  if (x.pictures.empty()) {
    md << "\n## Pictures\n\nNone rendered (see `skipped` in summary.json).\n";
    return;
  }
  md << "\n## Pictures\n\n";
  for (const std::string& p : x.pictures) md << "![" << p << "](" << p << ")\n\n";
}

}  // namespace

std::string report_markdown(const Scene& scene, const RunRecord& record,
                            const ReportExtras& extras) {
  std::ostringstream md;
  // The title is free text: its control characters are shown as escapes.
  md << "# Run report: " << printable(scene.title.empty() ? scene.source : scene.title) << "\n\n"
     << "Scene `" << printable(scene.source) << "`, rockfdem " << version_string() << ", "
     << record.threads << (record.threads == 1 ? " thread" : " threads") << ", state hash `"
     << record.state.state_hash << "`. Figures in full: summary.json, "
     << "history.csv.\n\n";
  inputs(md, scene, record);
  stages(md, record);
  status(md, record);
  key_points(md, scene, record.monitors, extras, record.state.broken);
  answer_origin(md, record, extras);
  bolts(md, record.bolts);
  lining(md, record.lining);
  broken_zone(md, record.state.broken, record.broken_zone, record.joints);
  instruments(md, record);
  continuum(md, record);
  convergence_confinement(md, record);
  post_peak(md, record.continuum_post_peak);
  pictures(md, extras);
  return printable(md.str(), true);  // any scene text above (group names, paths) too
}

void write_report(const std::string& dir, const Scene& scene, const RunRecord& record,
                  const ReportExtras& extras) {
  coupling::atomic_write_text(output_path(dir, "report.md"),
                              report_markdown(scene, record, extras));
}

}  // namespace rockfdem::workflows
