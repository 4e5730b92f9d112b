// Bolt outputs from section forces (bolt_results.hpp).
#include "outputs/bolt_results.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "record/output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/fdem/bolt_output.hpp"

namespace rockfdem::workflows {
namespace {

constexpr const char* kCsvHeader =
    "step,time_s,stage,bolt,station_m,x_m,y_m,axial_force_kN,steel_stress_MPa,state\n";

/// The station whose bar force has the largest magnitude (the first of equals).
const fdem::BoltStation* peak(const std::vector<fdem::BoltStation>& st) {
  const fdem::BoltStation* best = nullptr;
  for (const fdem::BoltStation& s : st)
    if (!best || std::abs(s.bar_force) > std::abs(best->bar_force)) best = &s;
  return best;
}

// Tension and compression apart: a bar's signed peak alone hides one of them.
void add_tension_and_compression(const std::vector<fdem::BoltStation>& st,
                                 const fdem::BoltSteel& steel, BoltPeak& p) {
  double max_stress = 0;
  for (const fdem::BoltStation& s : st) {
    if (s.bar_force / 1e3 > p.max_tension_kN_per_bar) {
      p.max_tension_kN_per_bar = s.bar_force / 1e3;
      p.tension_station_m = s.station;
      max_stress = s.steel_stress;
    }
    if (-s.bar_force / 1e3 > p.max_compression_kN_per_bar) {
      p.max_compression_kN_per_bar = -s.bar_force / 1e3;
      p.compression_station_m = s.station;
    }
    if (s.state == 2 && !p.first_broken_station_m) p.first_broken_station_m = s.station;
  }
  p.tension_over_yield = max_stress / steel.yield_strength;
  p.tension_over_ultimate = max_stress / steel.ultimate_strength;
}

int worst_state(const std::vector<fdem::BoltStation>& st) {
  int worst = 0;
  for (const fdem::BoltStation& s : st) worst = std::max(worst, s.state);
  return worst;
}

/// One CSV row per station: the columns after `prefix`.
std::string station_rows(const std::string& prefix, const std::vector<fdem::BoltStation>& st) {
  std::string out;
  char line[200];
  for (const fdem::BoltStation& s : st) {
    std::snprintf(line, sizeof line, "%.6g,%.9g,%.9g,%.6g,%.6g,%d\n", s.station, s.x, s.y,
                  s.bar_force / 1e3, s.steel_stress / 1e6, s.state);
    out += prefix + line;
  }
  return out;
}

/// Profiles of the installed bolts (empty for the others).
std::vector<std::vector<fdem::BoltStation>> profiles(const fdem::Engine& e,
                                                     const fdem::BoltPlan& plan) {
  std::vector<std::vector<fdem::BoltStation>> out(plan.specs.size());
  for (std::size_t b = 0; b < plan.specs.size(); ++b)
    if (plan.installed[b]) out[b] = fdem::bolt_sections(e, plan, int(b));
  return out;
}

}  // namespace

std::string bolt_name(std::size_t b) {
  char name[32];
  std::snprintf(name, sizeof name, "bolt_%02zu", b);
  return name;
}

BoltResults::BoltResults(const fdem::BoltPlan& plan, std::vector<std::uint8_t> is_cable,
                         std::string dir)
    : plan_(plan),
      is_cable_(std::move(is_cable)),
      dir_(std::move(dir)),
      csv_(kCsvHeader),
      pvd_(output_path(dir_, "bolts.pvd")) {}

std::vector<std::string> BoltResults::history_columns() const {
  std::vector<std::string> cols;
  for (std::size_t b = 0; b < plan_.specs.size(); ++b)
    cols.push_back(bolt_name(b) + "_max_axial_kN");
  return cols;
}

std::vector<double> BoltResults::record(const fdem::Engine& e, long step, double time, int stage) {
  now_ = profiles(e, plan_);
  std::vector<double> row;
  bool any = false;
  for (std::size_t b = 0; b < now_.size(); ++b) {
    const fdem::BoltStation* p = peak(now_[b]);
    row.push_back(p ? p->bar_force / 1e3 : 0.0);
    char prefix[96];
    std::snprintf(prefix, sizeof prefix, "%ld,%.10g,%d,%zu,", step, time, stage, b);
    csv_ += station_rows(prefix, now_[b]);
    any |= p != nullptr;
  }
  if (any) coupling::atomic_write_text(output_path(dir_, "bolts.csv"), csv_);
  return row;
}

void BoltResults::at_output_step(const OutputStep& s, std::vector<double>& row) {
  for (double v : record(s.engine, s.engine.step_count(), s.engine.time(), s.stage_index))
    row.push_back(v);
}

void BoltResults::write_frame(const std::string& file, const coupling::VtkFieldData& frame) {
  coupling::VtkPolylines l;
  std::vector<double> force, stress, station;
  std::vector<std::int32_t> state, index, cable;
  for (std::size_t b = 0; b < now_.size(); ++b) {
    if (now_[b].size() < 2) continue;
    std::vector<int> ids;
    for (const fdem::BoltStation& s : now_[b]) {
      ids.push_back(int(l.x.size()));
      l.x.push_back(s.x);
      l.y.push_back(s.y);
      force.push_back(s.bar_force / 1e3);
      stress.push_back(s.steel_stress / 1e6);
      station.push_back(s.station);
      state.push_back(s.state);
    }
    l.polylines.push_back(std::move(ids));
    index.push_back(std::int32_t(b));
    cable.push_back(is_cable_[b]);
  }
  if (l.polylines.empty()) return;
  l.point_arrays = {coupling::scalar_array("axial_force_kN", std::move(force)),
                    coupling::scalar_array("steel_stress_MPa", std::move(stress)),
                    coupling::scalar_array("station_m", std::move(station)),
                    coupling::scalar_array("yield_state", std::move(state))};
  l.cell_arrays = {coupling::scalar_array("bolt", std::move(index)),
                   coupling::scalar_array("is_cable", std::move(cable))};
  // The frame's stage, step and time (and nothing else of its legend).
  for (const auto& t : frame.text)
    if (t.first == "stage") l.field.text.push_back(t);
  l.field.numbers = frame.numbers;
  l.field.text.push_back({"yield_state_codes", "0 elastic, 1 yielding (past sigma_y), 2 broken"});
  coupling::write_vtp(l, output_path(dir_, file));
  double time = 0;
  for (const auto& [name, value] : frame.numbers)
    if (name == "time_s") time = value;
  pvd_.add(time, file);
  pvd_.write();
}

std::vector<plots::PlotSeries> BoltResults::force_curves(const fdem::Engine& e) const {
  const auto now = profiles(e, plan_);
  std::vector<plots::PlotSeries> out;
  for (std::size_t b = 0; b < now.size(); ++b) {
    if (now[b].empty()) continue;
    plots::PlotSeries s{bolt_name(b) + (is_cable_[b] ? " (cable)" : ""), {}, {}};
    for (const fdem::BoltStation& st : now[b]) {
      s.x.push_back(st.station);
      s.y.push_back(st.bar_force / 1e3);
    }
    out.push_back(std::move(s));
  }
  return out;
}

BoltFigures BoltResults::summary_entry(const fdem::Engine& e, std::size_t b,
                                       const std::vector<fdem::BoltStation>& st) const {
  const fdem::Bolt& bolt = plan_.specs[b].bolt;
  const fdem::BoltCounts c = fdem::bolt_counts(e, plan_, int(b));
  BoltFigures f{bolt_name(b),
                is_cable_[b] ? "cable" : "bolt",
                {bolt.a[0], bolt.a[1]},
                {bolt.b[0], bolt.b[1]},
                plan_.installed[b] != 0,
                c.yielding,
                c.broken,
                c.grout_broken,
                std::nullopt};
  const fdem::BoltStation* p = peak(st);
  if (!p) return f;  // not installed: no force to report
  const std::string file = bolt_name(b) + ".csv";
  coupling::atomic_write_text(
      output_path(dir_, file),
      "station_m,x_m,y_m,axial_force_kN,steel_stress_MPa,state\n" + station_rows("", st));
  BoltPeak peak_figures;
  peak_figures.file = file;
  peak_figures.max_axial_force_kN_per_bar = p->bar_force / 1e3;
  peak_figures.max_steel_stress_MPa = p->steel_stress / 1e6;
  peak_figures.station_m = p->station;
  peak_figures.yielded = worst_state(st) >= 1;
  peak_figures.broken = worst_state(st) == 2;
  add_tension_and_compression(st, plan_.specs[b].steel, peak_figures);
  f.peak = peak_figures;
  return f;
}

void BoltResults::finish(const fdem::Engine& e, RunRecord& summary, PlotWriter* plots) const {
  const auto now = profiles(e, plan_);
  BoltRecord r;
  for (std::size_t b = 0; b < now.size(); ++b) r.each.push_back(summary_entry(e, b, now[b]));
  const fdem::BoltCounts all = fdem::bolt_counts(e, plan_, -1);
  r.count = long(plan_.specs.size());
  r.steel_cracks_yielding = all.yielding;
  r.steel_cracks_broken = all.broken;
  r.grout_cracks_broken = all.grout_broken;
  summary.bolts = std::move(r);
  if (!plots) return;
  const std::vector<plots::PlotSeries> curves = force_curves(e);
  const std::string title =
      "Bolt axial force (section force) at step " + std::to_string(e.step_count()) + ", end of run";
  if (!curves.empty())
    plots->xy("bolt_forces.png", title, "distance from the collar [m]",
              "axial force [kN per bar], tension +", curves);
}

nlohmann::json BoltResults::state() const {
  nlohmann::json frames = nlohmann::json::array();
  for (const coupling::PvdEntry& f : pvd_.entries()) frames.push_back({f.time, f.file});
  return {{"csv", csv_}, {"frames", frames}};
}

void BoltResults::restore(const nlohmann::json& s, const std::string& from_dir) {
  namespace fs = std::filesystem;
  csv_ = s.at("csv").get<std::string>();
  if (csv_ != kCsvHeader) coupling::atomic_write_text(output_path(dir_, "bolts.csv"), csv_);
  std::error_code same_ec;
  const bool same_dir = fs::equivalent(from_dir, dir_, same_ec);
  for (const auto& f : s.at("frames")) {
    const std::string name = f.at(1).get<std::string>();
    std::error_code ec;
    if (!same_dir)
      fs::copy_file(output_path(from_dir, name), output_path(dir_, name),
                    fs::copy_options::overwrite_existing, ec);
    pvd_.add(f.at(0).get<double>(), name);
  }
  if (!pvd_.entries().empty()) pvd_.write();
}

}  // namespace rockfdem::workflows
