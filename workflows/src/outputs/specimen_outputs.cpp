#include "outputs/specimen_outputs.hpp"

#include <cstdio>
#include <iostream>

#include "outputs/engine_report.hpp"
#include "outputs/frame_restore.hpp"
#include "outputs/run_plots.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::workflows {
namespace {

std::vector<std::string> history_columns(bool disc) {
  std::vector<std::string> columns{
      "step",         "time",           "axial_strain", disc ? "tensile_stress" : "axial_stress",
      "platen_force", "kinetic_energy", "broken_I",     "broken_II",
      "broken_mixed"};
  for (const std::string& c : energy_columns()) columns.push_back(c);
  return columns;
}

}  // namespace

SpecimenOutputs::SpecimenOutputs(const Scene& scene, const RunContext& ctx, RunRecord& summary)
    : scene_(scene),
      ctx_(ctx),
      summary_(summary),
      disc_(scene.mesh.kind == mesh::ModelKind::kBrazilian),
      load_(scene),
      history_(output_path(ctx.output_dir, "history.csv"), history_columns(disc_)),
      pvd_(output_path(ctx.output_dir, "fdem.pvd")) {
  summary_.note_turned_off(scene.output, "fdem.pvd, fdem_NNNN.vtu", true);
}

void SpecimenOutputs::record_rows(const fdem::Engine& e, const mesh::Mesh&, const StageTag&, double,
                                  const fdem::EnergyBalance& energy) {
  const PlatenReading r = load_.read(e);
  const fdem::BrokenCounts b = e.broken_counts();
  std::vector<double> row{
      double(e.step_count()), e.time(),         r.strain,          r.stress,       r.force,
      e.kinetic_energy(),     double(b.mode_I), double(b.mode_II), double(b.mixed)};
  for (double v : energy_row(energy)) row.push_back(v);
  history_.add(row);
}

void SpecimenOutputs::record_frame(const fdem::Engine& e, const mesh::Mesh& m,
                                   const StageTag& stage, const fdem::EnergyBalance& energy,
                                   PhaseTimer& timer) {
  if (scene_.output.vtk) write_frame(e, m, stage.kind);
  last_good_.take(e, energy);
  timer.stamp("output");
}

void SpecimenOutputs::write_frame(const fdem::Engine& e, const mesh::Mesh& m,
                                  const std::string& stage) {
  char name[32];
  std::snprintf(name, sizeof name, "fdem_%04d.vtu", frame_++);
  coupling::VtkGrid g = coupling::fdem_grid(e, m);
  coupling::add_frame_info(g.field, stage, e.step_count(), e.time());
  coupling::write_vtu(g, output_path(ctx_.output_dir, name));
  pvd_.add(e.time(), name);
  pvd_.write();
}

nlohmann::json SpecimenOutputs::state() const {
  return {{"history", history_.rows()}, {"frames", frames_state(pvd_)}, {"load", load_.state()}};
}

void SpecimenOutputs::check_fits(const nlohmann::json& s) const {
  const std::size_t width = history_columns(disc_).size();
  for (const auto& row : s.at("history"))
    if (row.size() != width)
      throw InputError("corrupt run state: a history row has " + std::to_string(row.size()) +
                       " values; history.csv has " + std::to_string(width) + " columns");
}

void SpecimenOutputs::restore(const nlohmann::json& s, const std::string& from_dir) {
  history_.restore(s.at("history").get<std::vector<std::vector<double>>>());
  frame_ = restore_frames(s.at("frames"), from_dir, ctx_.output_dir, pvd_, summary_);
  load_.restore(s.at("load"));
}

void SpecimenOutputs::finish(const fdem::Engine& e, PhaseTimer& timer) {
  if (scene_.output.plots)
    specimen_plots(e, history_, disc_, ctx_.output_dir, summary_, ctx_.quiet);
  timer.stamp("output");
  summary_.status = "completed";
  report_engine(e, timer, summary_);
  summary_.specimen = load_.record();
  const SpecimenRecord& peak = *summary_.specimen;
  summary_.skipped.push_back("insitu: a specimen starts stress-free");
  write_summary(timer);
  if (!ctx_.quiet)
    std::cout << (disc_ ? "peak tensile stress " : "peak axial stress ") << peak.peak_stress / 1e6
              << " MPa at step " << peak.peak_step << " (upper platen, read every step), broken "
              << e.broken_counts().total() << " of " << e.n_cracks()
              << " crack elements, state hash " << e.state_hash() << '\n'
              << timer.table();
}

void SpecimenOutputs::report_failure(const fdem::Engine& e, PhaseTimer& timer,
                                     const std::string& why) {
  last_good_.report_failure(e, timer, why, summary_);
  write_summary(timer);
}

void SpecimenOutputs::report_interrupted(const fdem::Engine& e, PhaseTimer& timer,
                                         const std::string& why) {
  report_engine(e, timer, summary_);
  summary_.specimen = load_.record();
  summary_.status = "interrupted";
  summary_.failure = why;
  write_summary(timer);
}

void SpecimenOutputs::write_summary(PhaseTimer& timer) {
  summary_.set_timings(timer);
  summary_.write(output_path(ctx_.output_dir, "summary.json"));
}

}  // namespace rockfdem::workflows
