#include "outputs/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "outputs/broken_zone.hpp"
#include "outputs/continuum_comparison.hpp"
#include "outputs/convergence_confinement.hpp"
#include "outputs/engine_report.hpp"
#include "outputs/ground_reaction.hpp"
#include "outputs/joint_results.hpp"
#include "outputs/loading_frame.hpp"
#include "outputs/rock_plausibility.hpp"
#include "outputs/run_report.hpp"
#include "outputs/support_diagrams.hpp"
#include "record/output_dir.hpp"
#include "record/survey_reading.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/coupling/insitu_grid.hpp"
#include "rockfdem/fdem/bolt_output.hpp"
#include "scene/lining_parts.hpp"

namespace rockfdem::workflows {
namespace {

double mm(double metres) { return 1000 * metres; }

// %g with up to 6 digits: alpha as the scene gives it (0.01, 0.5).
std::string detail_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

// The joints' slip and opening at each stage's end (the run's end is
// joint_profile.csv), so that a stage's share of a joint's slip shows.
void RunOutputs::stage_done(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                            StageChanges& done) {
  if (!m.joint_edges.empty()) {
    const std::vector<mesh::JointTrace> none;
    const std::string name = "joint_profile_stage_" + std::to_string(stage.number) + ".csv";
    coupling::atomic_write_text(
        output_path(ctx_.output_dir, name),
        joint_profile_csv(e, m, summary_.mesh ? summary_.mesh->joint_traces : none));
    stage_joint_profiles_.push_back(name);
  }
  if (!done.rejoined) return;  // not a grout stage that fired
  if (instruments_) instruments_->cracks_grouted(done.grouted, e.n_cracks());
  std::string csv = "crack,x,y\n";
  for (const StageChanges::Grouted& g : done.grouted)
    csv += std::to_string(g.crack) + ',' + std::to_string(g.x) + ',' + std::to_string(g.y) + '\n';
  coupling::atomic_write_text(output_path(ctx_.output_dir, "grouted_cracks.csv"), csv);
  done.positions_file = "grouted_cracks.csv";
}

double RunOutputs::outer_rotation(const fdem::Engine& e) {
  const RigidFit fit = key_points_->boundary_fit(e);
  max_rotation_deg_ = std::max(max_rotation_deg_, std::abs(fit.rotation) * 180 / M_PI);
  return fit.rotation;
}

RunOutputs::RunOutputs(const Scene& scene, const RunContext& ctx, RunRecord& summary)
    : scene_(scene),
      ctx_(ctx),
      summary_(summary),
      vtk_(scene.output.vtk),
      lining_ring_(scene.lining_ring),
      insitu_(scene.insitu),
      is_cable_(scene.bolts.is_cable),
      sections_(ring_sections(scene)),
      invert_top_(invert_top(scene)) {
  insitu::KirschCase k;
  if (kirsch_case(scene, &k)) kirsch_ = k;
  summary_.note_turned_off(scene.output, "fdem.pvd, fdem_NNNN.vtu, insitu.vtu, continuum.vtu",
                           true);
  // Stage numbers: 0 the implicit stage, then the explicit ones in order.
  stage_names_.push_back("insitu");
  for (const StageSpec& st : scene.stages) stage_names_.push_back(st.kind);
}

void RunOutputs::record_insitu(const mesh::Mesh& m, const std::vector<insitu::InsituField>& fields,
                               std::vector<ImplicitSample> samples) {
  fields_ = &fields;
  samples_ = std::move(samples);
  if (frames_) frames_->set_implicit(fields.back());
  summary_.record_insitu(fields);
  if (vtk_)
    coupling::write_vtu(coupling::insitu_grid(m, fields.back()),
                        output_path(ctx_.output_dir, "insitu.vtu"));
  if (kirsch_ && fields.back().alpha == 0.0)
    summary_.insitu.kirsch_rel_l2 =
        insitu::compare_kirsch(m, fields.back(), *kirsch_).stress_rel_l2;
}

void RunOutputs::record_face_distance(const FaceDistanceFigures& f,
                                      std::vector<ImplicitSample> curve) {
  face_ = f;
  curve_samples_ = std::move(curve);
}

std::vector<std::string> RunOutputs::history_columns(const std::vector<Monitor>& monitors) const {
  std::vector<std::string> cols{
      "stage",    "step",      "time",        "kinetic_energy", "unbalanced_ratio",
      "broken_I", "broken_II", "broken_mixed"};
  for (const Monitor& mon : monitors)
    for (const char* c : {"_ux_mm", "_uy_mm", "_u_mm", "_radial_mm"}) cols.push_back(mon.name + c);
  cols.insert(cols.end(),
              {"vault_settlement_mm", "wall_chord_convergence_mm", "shoulder_chord_convergence_mm",
               "outer_rotation_deg", "support_pressure_ratio"});
  for (const std::string& c : energy_columns()) cols.push_back(c);
  for (const OutputStepObserver* o : observers())
    for (const std::string& c : o->history_columns()) cols.push_back(c);
  return cols;
}

void RunOutputs::begin(const mesh::Mesh& m, const KeyPoints& key_points,
                       const fdem::BoltPlan& bolts, std::unique_ptr<Instruments> instruments) {
  bolts_ = &bolts;
  if (!bolts.specs.empty())
    bolt_results_ = std::make_unique<BoltResults>(bolts, is_cable_, ctx_.output_dir);
  instruments_ = std::move(instruments);
  key_points_ = &key_points;
  if (lining_ring_) {
    lining_ = std::make_unique<LiningOutput>(m, invert_top_, sections_, ctx_.output_dir);
    if (!lining_->has_ring()) lining_.reset();
    if (lining_) lining_->set_installed(lining_installed_);
  }
  frames_ = std::make_unique<FrameOutput>(ctx_.output_dir, bolts_, bolt_results_.get());
  if (fields_) frames_->set_implicit(fields_->back());
  history_ = std::make_unique<History>(output_path(ctx_.output_dir, "history.csv"),
                                       history_columns(key_points.monitors()));
}

std::vector<OutputStepObserver*> RunOutputs::observers() const {
  std::vector<OutputStepObserver*> out;
  for (OutputStepObserver* o : std::initializer_list<OutputStepObserver*>{
           bolt_results_.get(), instruments_.get(), lining_.get()})
    if (o) out.push_back(o);
  return out;
}

void RunOutputs::set_lining_installed(bool installed) {
  lining_installed_ = installed;
  if (lining_) lining_->set_installed(installed);
}

void RunOutputs::record_rows(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                             double support_ratio, const fdem::EnergyBalance& energy) {
  const fdem::BrokenCounts b = e.broken_counts();
  std::vector<double> row{
      double(stage.number),       double(e.step_count()), e.time(),          e.kinetic_energy(),
      e.unbalanced_force_ratio(), double(b.mode_I),       double(b.mode_II), double(b.mixed)};
  for (const Monitor& mon : key_points_->monitors())
    for (double v : key_points_->figures(e, mon)) row.push_back(v);
  for (double v : key_points_->chords_mm(e)) row.push_back(v);
  row.push_back(key_points_->boundary_fit(e).rotation * 180 / M_PI);
  row.push_back(support_ratio);
  for (double v : energy_row(energy)) row.push_back(v);
  const NodeDisplacement u = key_points_->node_displacements(e);
  const OutputStep step{e, m, stage.kind, stage.number, u};
  for (OutputStepObserver* o : observers()) o->at_output_step(step, row);
  history_->add(row);
}

void RunOutputs::record_frame(const fdem::Engine& e, const mesh::Mesh& m, const StageTag& stage,
                              const fdem::EnergyBalance& energy, PhaseTimer& timer) {
  // The hand-off step's dt, once it passed (a failed one is no good state).
  if (stage.kind == "handoff") handoff_dt_ = e.dt();
  if (vtk_) {
    const NodeDisplacement u = key_points_->node_displacements(e);
    std::vector<double> no_columns;
    frames_->at_output_step({e, m, stage.kind, stage.number, u}, no_columns);
  }
  last_good_.take(e, energy, monitor_figures(e));
  timer.stamp("output");
}

MonitorRecord RunOutputs::monitor_figures(const fdem::Engine& e) const {
  MonitorRecord r;
  for (const Monitor& mon : key_points_->monitors()) {
    const auto k = key_points_->figures(e, mon);
    r.key_points[mon.name] = {k[0],         k[1],         k[2],         k[3],
                              mon.node_x,   mon.node_y,   mon.inward_x, mon.inward_y,
                              std::nullopt, std::nullopt, std::nullopt, std::nullopt};
  }
  // Per point (as field convergence points are read) and, apart, the
  // change of length of two chords between points.
  const std::array<double, 3> chords = key_points_->chords_mm(e);
  r.chords = ChordFigures{chords[0], chords[1], chords[2]};
  if (instruments_) instruments_->add_monitors(r, key_points_->node_displacements(e));
  return r;
}

void RunOutputs::report_dt() {
  // Steps and time add up: the hand-off step, then each stage's (dt is
  // constant within a stage: the limit changes only with a stage's changes).
  double lo = summary_.state.dt, hi = lo;
  if (handoff_dt_ > 0) {
    if (!summary_.fdem) summary_.fdem.emplace();
    summary_.fdem->handoff_dt = handoff_dt_;
    lo = std::min(lo, handoff_dt_);
    hi = std::max(hi, handoff_dt_);
  }
  if (summary_.fdem && summary_.fdem->stages)
    for (const StageRecord& stage : *summary_.fdem->stages)
      if (stage.dt) {
        lo = std::min(lo, *stage.dt);
        hi = std::max(hi, *stage.dt);
      }
  summary_.dt_range = std::make_pair(lo, hi);
}

void RunOutputs::report_failure(const fdem::Engine& e, PhaseTimer& timer, const std::string& why) {
  last_good_.report_failure(e, timer, why, summary_);
  report_dt();
  summary_.write(output_path(ctx_.output_dir, "summary.json"));
  write_report();
}

nlohmann::json RunOutputs::state() const {
  return {{"history", history_->rows()},
          {"stages", stage_names_},
          {"frames", frames_->state()},
          {"handoff_dt", handoff_dt_},
          {"joint_profiles", stage_joint_profiles_},
          {"max_rotation_deg", max_rotation_deg_},
          {"bolts", bolt_results_ ? bolt_results_->state() : nlohmann::json()},
          {"instruments", instruments_ ? instruments_->state() : nlohmann::json()}};
}

void RunOutputs::restore(const nlohmann::json& s, const std::string& from_dir) {
  namespace fs = std::filesystem;
  history_->restore(History::rows_from_json(s.at("history")));
  handoff_dt_ = s.value("handoff_dt", 0.0);  // 0: a checkpoint from before it was kept
  max_rotation_deg_ = s.value("max_rotation_deg", 0.0);
  if (instruments_ && s.contains("instruments") && s.at("instruments").is_object())
    instruments_->restore(s.at("instruments"));
  frames_->restore(s.at("frames"), from_dir, summary_);
  if (bolt_results_ && s.contains("bolts") && !s["bolts"].is_null())
    bolt_results_->restore(s["bolts"], from_dir);
  std::error_code same_ec;
  const bool same_dir = fs::equivalent(from_dir, ctx_.output_dir, same_ec);
  // Files an earlier stage wrote once, which the summary names, and the
  // lining's forces at the earlier outputs.
  stage_joint_profiles_ = s.value("joint_profiles", std::vector<std::string>{});
  std::vector<std::string> earlier{"grouted_cracks.csv"};
  earlier.insert(earlier.end(), stage_joint_profiles_.begin(), stage_joint_profiles_.end());
  for (const std::vector<double>& row : history_->rows()) {
    char name[40];
    std::snprintf(name, sizeof name, "lining_%06ld.csv", long(row.at(1)));
    earlier.push_back(name);
  }
  if (!same_dir)
    for (const std::string& name : earlier) {
      std::error_code ec;
      if (fs::exists(output_path(from_dir, name), ec))
        fs::copy_file(output_path(from_dir, name), output_path(ctx_.output_dir, name),
                      fs::copy_options::overwrite_existing, ec);
    }
}

bool RunOutputs::lining_outputs(const fdem::Engine& e, const mesh::Mesh& m) {
  LiningRecord& r = summary_.lining;
  r = LiningRecord{};
  r.interface = lining_bond(e, m);
  const bool forces = lining_ && lining_installed_ && lining_->installed(e);
  if (!r.interface && !forces && scene_.lining_ring)
    summary_.skipped.push_back("lining: the ring is not installed at the end of the run");
  return forces;
}

void RunOutputs::finish(const fdem::Engine& e, const mesh::Mesh& m, PhaseTimer& timer,
                        const fdem::BoltPlan& bolts) {
  report_engine(e, timer, summary_);
  report_dt();
  summary_.counts.bolts = long(bolts.specs.size());
  if (!bolt_results_) summary_.skipped.push_back("bolts: none in the scene");
  summary_.monitors = monitor_figures(e);
  add_since_support(summary_.monitors);
  add_at_handoff(summary_.monitors);
  add_from_unloaded(summary_.monitors);
  const RigidFit fit = key_points_->boundary_fit(e);
  summary_.outer_boundary = OuterBoundaryFigures{fit.rotation * 180 / M_PI,
                                                 max_rotation_deg_,
                                                 kRigidRotationLimitDeg,
                                                 {mm(fit.tx), mm(fit.ty)},
                                                 scene_.insitu.rollers ? "rollers" : "tractions"};
  record_ground_reaction();
  record_convergence_confinement(e, m);
  const bool lining_forces = lining_outputs(e, m);
  damage_outputs(e, m);
  if (instruments_) instruments_->finish(summary_, e, m, key_points_->node_displacements(e));
  summary_.history_stages = stage_names_;  // history.csv's "stage" column indexes this list
  // The run's curves, then the support's outputs (each with its plots),
  // then the pictures of the final state.
  const std::unique_ptr<PlotWriter> plots = curves();
  if (lining_forces) summary_.lining.forces = lining_->finish(e, ctx_.output_dir, plots.get());
  if (bolt_results_) bolt_results_->finish(e, summary_, plots.get());
  summary_.support = support_verdict(summary_.lining, summary_.bolts);
  if (summary_.support && summary_.support->verdict == "overstressed") {
    summary_.warnings.push_back(summary_.support->line());
    if (!ctx_.quiet) std::cerr << "warning: " << summary_.support->line() << '\n';
  }
  if (plots) {
    const PictureContext pictures{e, m, scene_, bolts_, key_points_->node_displacements(e)};
    tunnel_pictures(*plots, pictures);
    if (lining_forces)
      support_forces_plot(*plots, pictures, &lining_->geometry(), &lining_->final_forces());
    else
      support_forces_plot(*plots, pictures, nullptr, nullptr);
    pictures_ = plots->rendered();
  }
  timer.stamp("output");
  summary_.set_timings(timer);
  summary_.write(output_path(ctx_.output_dir, "summary.json"));
  write_report();
  const fdem::BrokenCounts b = e.broken_counts();
  if (!ctx_.quiet)
    std::cout << "vault settlement " << summary_.monitors.chords->vault_settlement_mm
              << " mm, wall chord convergence "
              << summary_.monitors.chords->wall_chord_convergence_mm << " mm, broken cracks "
              << b.total() << ", state hash " << e.state_hash() << '\n'
              << timer.table();
}

// Ground reaction curve, implicit part: the core's share of the in-situ
// stress (alpha) against the vault settlement it allows.
void RunOutputs::record_ground_reaction() {
  const std::vector<Monitor>& monitors = key_points_->monitors();
  const std::size_t vault = std::size_t(&key_points_->find(KeyRole::kVault) - monitors.data());
  std::vector<GroundReactionPoint>& grc = summary_.ground_reaction_curve;
  grc.clear();
  for (const ImplicitSample& f : curve_samples_.empty() ? samples_ : curve_samples_) {
    if (f.key_points.size() != monitors.size())
      throw std::logic_error("an implicit field's sample lacks the key points");
    grc.push_back({f.alpha,
                   -mm(f.key_points[vault].uy),
                   "implicit stage, alpha = " + detail_number(f.alpha),
                   {}});
    // In pressure: the core's traction on the opening (0 once removed).
    for (std::size_t i = 0; i < monitors.size(); ++i) {
      const Monitor& k = monitors[i];
      const KeyPointSample& p = f.key_points[i];
      grc.back().key_points[k.name] = {mm(p.ux * k.inward_x + p.uy * k.inward_y), p.core_pressure,
                                       insitu_normal_stress(insitu_, k.inward_x, k.inward_y)};
    }
  }
  // The end: the core's factor then (0 once removed), the support carrying the rest.
  const double end_ratio =
      history_->rows().empty() ? 0.0 : history_->column("support_pressure_ratio").back();
  grc.push_back({end_ratio,
                 summary_.monitors.chords->vault_settlement_mm,
                 end_ratio > 0 ? "end of run (FDEM), core at alpha = " + detail_number(end_ratio)
                               : std::string("end of run (FDEM), core removed"),
                 {}});
}

// The key points' mean radial displacement at the support's installation
// (the history's row then; the hand-off's without a support stage) and at
// the end.
void RunOutputs::record_convergence_confinement(const fdem::Engine& e, const mesh::Mesh& m) {
  if (!history_ || history_->rows().empty() || !key_points_) return;
  const std::size_t row = support_row().value_or(0);
  ConvergenceConfinementState s;
  int n = 0;
  for (const Monitor& k : key_points_->monitors()) {
    const auto end = summary_.monitors.key_points.find(k.name);
    if (end == summary_.monitors.key_points.end()) continue;
    s.install_radial_mm += history_->column(k.name + "_radial_mm")[row];
    s.end_radial_mm += end->second.radial_mm;
    ++n;
  }
  if (n == 0) return;
  s.install_radial_mm /= n;
  s.end_radial_mm /= n;
  s.install_alpha = history_->column("support_pressure_ratio")[row];
  s.lining_installed = lining_ && lining_installed_ && lining_->installed(e);
  ConvergenceConfinementFigures c = convergence_confinement(scene_, m, e, s);
  if (face_)
    c.face = ConvergenceConfinementFigures::FaceDistance{
        face_->face_distance_m, face_->plastic_radius_m, face_->x_star,
        face_->r_star,          face_->u_star,           face_->alpha};
  summary_.record_convergence_confinement(std::move(c));
}

void RunOutputs::record_joints(const fdem::Engine& e, const mesh::Mesh& m) {
  if (m.joint_edges.empty()) return;
  const std::vector<mesh::JointTrace> none;
  const std::vector<mesh::JointTrace>& traces = summary_.mesh ? summary_.mesh->joint_traces : none;
  JointRecord& j = summary_.joints.emplace(
      joint_results(e, m, traces, output_path(ctx_.output_dir, "joints.csv")));
  coupling::atomic_write_text(output_path(ctx_.output_dir, "joint_profile.csv"),
                              joint_profile_csv(e, m, traces));
  j.set_traces = scene_.joints.set_traces;
  j.dfn_traces = scene_.joints.dfn_traces;
  if (summary_.mesh) j.traces = summary_.mesh->joints;
}

void RunOutputs::damage_outputs(const fdem::Engine& e, const mesh::Mesh& m) {
  const Resolution r = fracture_resolution(scene_, &m);
  summary_.resolution = ResolutionFigures{r.h, r.l_ch, r.ratio, kResolutionLimit};
  const auto warn = [&](const std::string& msg) {
    summary_.warnings.push_back(msg);
    if (!ctx_.quiet) std::cerr << "warning: " << msg << '\n';
  };
  summary_.rock_plausibility = rock_plausibility(scene_, r.ratio);
  // h / l_ch is said below, with h.
  for (const std::string& line : plausibility_warnings(*summary_.rock_plausibility, false))
    warn(line);
  char msg[500];
  if (r.ratio > kResolutionLimit) {
    std::snprintf(msg, sizeof msg,
                  "the fracture zone's elements (h = %.3g m) are %.2g times the rock's "
                  "characteristic length l_ch = E GfI / ft^2 = %.3g m (limit %g): crack "
                  "pattern and displacements depend on the mesh; refine mesh.size_near",
                  r.h, r.ratio, r.l_ch, kResolutionLimit);
    warn(msg);
  }
  record_joints(e, m);
  const BrokenZone z = broken_zone(e, m, r.h, bolt_triangles(bolts_, m.n_triangles()));
  BrokenZoneRecord& zone = summary_.broken_zone.emplace();
  zone.broken_rock_cracks = z.broken;
  zone.depth_m = z.depth;
  zone.fracture_zone_m = z.zone_depth;
  if (z.clearance >= 0) zone.clearance_m = z.clearance;
  zone.capped = z.at_edge;
  if (z.at_edge) {
    std::snprintf(msg, sizeof msg,
                  "broken crack elements reach %.2g m from the fracture zone's outer edge "
                  "(less than %g elements of %.3g m): the zone caps the damage; widen "
                  "tunnel.fracture_zone (now %.3g m deep)",
                  z.clearance, kEdgeElements, r.h, z.zone_depth);
    warn(msg);
  }
}

std::vector<StageSpan> RunOutputs::timeline() const {
  // The spans point into the record's stage reports: take them by reference.
  const std::optional<FdemRecord>& fdem = summary_.fdem;
  if (!history_ || history_->rows().empty() || !fdem || !fdem->stages) return {};
  return stage_spans(*fdem->stages, history_->column("time").front(),
                     history_->column("step").front());
}

std::optional<std::size_t> RunOutputs::support_row() const {
  const std::vector<StageSpan> spans = timeline();
  const StageSpan* support = support_stage(spans);
  if (!support) return std::nullopt;
  return row_at(history_->column("time"), support->start);
}

std::map<std::string, double> RunOutputs::since_support() const {
  const std::optional<std::size_t> row = support_row();
  const MonitorRecord& mon = summary_.monitors;
  std::map<std::string, double> out;
  if (!row) return out;
  const auto add = [&](const std::string& name, const std::string& column, double v) {
    out[name] = v - history_->column(column)[*row];
  };
  for (const Monitor& m : key_points_->monitors()) {
    const auto k = mon.key_points.find(m.name);
    if (k != mon.key_points.end() && !mon.points.count(m.name))
      add(m.name, m.name + "_radial_mm", k->second.radial_mm);
  }
  if (mon.chords) {
    add("wall_chord", "wall_chord_convergence_mm", mon.chords->wall_chord_convergence_mm);
    add("shoulder_chord", "shoulder_chord_convergence_mm",
        mon.chords->shoulder_chord_convergence_mm);
  }
  return out;
}

std::map<std::string, double> RunOutputs::survey_since_support() const {
  const std::optional<std::size_t> row = support_row();
  const MonitorRecord& mon = summary_.monitors;
  std::map<std::string, double> out;
  if (!row) return out;
  for (const auto& [name, k] : mon.key_points) {
    if (mon.points.count(name)) continue;
    const double ux = k.ux_mm - history_->column(name + "_ux_mm")[*row];
    const double uy = k.uy_mm - history_->column(name + "_uy_mm")[*row];
    out[name] = survey_reading(name, ux, uy, k.inward_x, k.inward_y);
  }
  return out;
}

// What monitoring installed with the support reads (field convergence
// data): a run without a lining or bolts stage adds nothing.
void RunOutputs::add_since_support(MonitorRecord& monitors) const {
  for (const auto& [name, mm] : since_support()) {
    const auto k = monitors.key_points.find(name);
    if (k != monitors.key_points.end() && !monitors.points.count(name))
      k->second.radial_since_support_mm = mm;
  }
  for (const auto& [name, mm] : survey_since_support())
    monitors.key_points[name].survey_since_support_mm = mm;
}

// History's first row is the hand-off step: the implicit stage's displacement.
void RunOutputs::add_at_handoff(MonitorRecord& monitors) const {
  if (!history_ || history_->rows().empty()) return;
  for (const Monitor& m : key_points_->monitors()) {
    const auto k = monitors.key_points.find(m.name);
    if (k != monitors.key_points.end() && !monitors.points.count(m.name))
      k->second.radial_at_handoff_mm = history_->column(m.name + "_radial_mm").front();
  }
}

void RunOutputs::add_from_unloaded(MonitorRecord& monitors) const {
  const std::optional<LoadingStrain> strain = loading_strain(scene_);
  if (!strain) return;
  for (auto& [name, k] : monitors.key_points) {
    if (monitors.points.count(name)) continue;
    const std::array<double, 2> load = loading_displacement(*strain, k.x, k.y);
    k.from_unloaded_mm = std::array<double, 2>{k.ux_mm + mm(load[0]), k.uy_mm + mm(load[1])};
  }
}

void RunOutputs::write_report() const {
  ReportExtras extras;
  extras.since_support_mm = since_support();
  extras.pictures = pictures_;
  workflows::write_report(ctx_.output_dir, scene_, summary_, extras);
}

std::unique_ptr<PlotWriter> RunOutputs::curves() {
  if (!scene_.output.plots) return nullptr;
  auto plots = std::make_unique<PlotWriter>(ctx_.output_dir, summary_, ctx_.quiet);
  if (!plots->available()) return nullptr;
  // From the support's installation where asked (and installed).
  const std::optional<std::size_t> from =
      scene_.output.convergence_from_support ? support_row() : std::nullopt;
  tunnel_curves(*plots, *history_, key_points_->monitors(), timeline(), from);
  ground_reaction_plot(*plots, summary_);
  return plots;
}

}  // namespace rockfdem::workflows
