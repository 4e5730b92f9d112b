#include "outputs/lining_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "outputs/lining_extremes.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/lining_cracks.hpp"

namespace rockfdem::workflows {
namespace {

// Of the segments in the floor part (`invert`) or out of it; 0 where none.
double median_thickness(const LiningGeometry& g, const std::vector<char>& in_invert, bool invert) {
  std::vector<double> t;
  for (std::size_t i = 0; i < g.segments.size(); ++i)
    if (bool(in_invert[i]) == invert) t.push_back(g.segments[i].thickness);
  if (t.empty()) return 0;
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  return t[t.size() / 2];
}

// What the check is, for summary.json's "capacity": the plain ring's
// criterion, or each part's section.
std::string capacity_text(const RingSections& r) {
  const auto text = [](const LiningSection& s) -> std::string {
    switch (s.kind) {
      case SectionKind::kPlain:
        return "plain shotcrete section, elastic: N/t +- 6M/t^2 within [-tensile, compressive] "
               "strength";
      case SectionKind::kReinforced:
        return "reinforced section: M-N interaction diagram, EN 1992-1-1 rectangular stress "
               "block, two symmetric layers of bars, steel elastic-perfectly plastic";
      case SectionKind::kSteelSets:
        return "steel sets in shotcrete, composite: N and M shared by EA and EI, each part within "
               "its elastic limit (Carranza-Torres and Diederichs 2009)";
    }
    return "?";
  };
  if (!r.invert || r.invert->kind == r.lining.kind) return text(r.lining);
  return "arch and walls: " + text(r.lining) + "; invert: " + text(*r.invert);
}

// The plot title's words for a part's section at thickness t (short: the
// title is one line).
std::string section_caption(const LiningSection& s, double t) {
  char line[160];
  if (s.kind == SectionKind::kReinforced)
    std::snprintf(line, sizeof line,
                  "reinforced t = %.3g m, fck %.3g MPa, 2 x %.4g mm^2/m, fy %.3g MPa", t,
                  s.concrete.compressive / 1e6, s.bar_area * 1e6, s.steel_yield / 1e6);
  else if (s.kind == SectionKind::kSteelSets)
    std::snprintf(line, sizeof line,
                  "steel sets t = %.3g m, fc %.3g MPa, sets at %.3g m, fy %.3g MPa", t,
                  s.concrete.compressive / 1e6, s.set_spacing, s.steel_yield / 1e6);
  else
    std::snprintf(line, sizeof line, "t = %.3g m, fc = %.3g MPa, ft = %.3g MPa", t,
                  s.concrete.compressive / 1e6, s.concrete.tensile / 1e6);
  return line;
}

}  // namespace

std::optional<RingSections> ring_sections(const Scene& scene) {
  const auto it = scene.materials.find(mesh::kLining);
  if (it == scene.materials.end() || !(it->second.compressive_strength > 0)) return std::nullopt;
  RingSections r;
  r.lining = lining_section(it->second);
  if (scene.invert) r.invert = lining_section(*scene.invert);
  return r;
}

LiningOutput::LiningOutput(const mesh::Mesh& m, double invert_top,
                           std::optional<RingSections> sections, std::string dir)
    : sections_(std::move(sections)), dir_(std::move(dir)) {
  if (auto g = lining_geometry(m)) geometry_ = std::move(*g);
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == mesh::kLining) triangles_.push_back(int(t));
  for (const LiningSegment& s : geometry_.segments) segment_invert_.push_back(s.y < invert_top);
}

const LiningSection& LiningOutput::section_of(std::size_t i) const {
  return segment_invert_[i] ? *sections_->invert : sections_->lining;
}

std::vector<double> LiningOutput::safety_factors(const std::vector<SectionForces>& f) const {
  std::vector<double> fs;
  for (std::size_t i = 0; i < f.size(); ++i)
    fs.push_back(section_safety_factor(f[i], geometry_.segments[i].thickness, section_of(i)));
  return fs;
}

std::string LiningOutput::csv(long step, const std::vector<SectionForces>& f) const {
  if (!sections_) return lining_csv(step, geometry_, f, nullptr);
  const std::vector<double> fs = safety_factors(f);
  return lining_csv(step, geometry_, f, &fs);
}

bool LiningOutput::installed(const fdem::Engine& e) const {
  if (!has_ring()) return false;
  for (int t : triangles_)
    if (!e.active(std::size_t(t))) return false;
  return true;
}

std::vector<SectionForces> LiningOutput::forces(const fdem::Engine& e) const {
  std::vector<std::array<double, 3>> stress(e.n_triangles(), {0, 0, 0});
  for (int t : triangles_) stress[std::size_t(t)] = e.triangle_stress(std::size_t(t));
  return lining_forces(geometry_, stress);
}

std::vector<std::string> LiningOutput::history_columns() const {
  return {"lining_max_thrust_kN_per_m", "lining_max_abs_moment_kNm_per_m",
          "lining_min_safety_factor"};
}

std::array<double, 3> LiningOutput::history_values(const std::vector<SectionForces>& f) const {
  const double nan = std::nan("");
  if (f.empty()) return {nan, nan, nan};
  // The sections' extremes: a corner's are no beam section's.
  const ForceExtremes x = lining_extremes(geometry_, f).sections;
  const double n = x.max_thrust.value / 1e3;
  const double m = x.max_abs_moment.value / 1e3;
  double fs = nan;
  if (sections_) {
    const std::vector<double> all = safety_factors(f);
    const double least = *std::min_element(all.begin(), all.end());
    if (std::isfinite(least)) fs = least;  // an unloaded ring has no finite factor
  }
  return {n, m, fs};
}

void LiningOutput::at_output_step(const OutputStep& step, std::vector<double>& row) {
  const fdem::Engine& e = step.engine;
  std::vector<SectionForces> f;
  if (installed_ && installed(e)) {
    f = forces(e);
    char name[40];
    std::snprintf(name, sizeof name, "lining_%06ld.csv", e.step_count());
    coupling::atomic_write_text(output_path(dir_, name), csv(e.step_count(), f));
  }
  for (const double v : history_values(f)) row.push_back(v);
}

LiningForceFigures LiningOutput::finish(const fdem::Engine& e, const std::string& dir,
                                        PlotWriter* plots) {
  const LiningForceFigures f = figures(e, dir);
  if (plots) this->plots(*plots);
  return f;
}

LiningForceFigures LiningOutput::figures(const fdem::Engine& e, const std::string& dir) {
  last_ = forces(e);
  coupling::atomic_write_text(output_path(dir, "lining.csv"), csv(e.step_count(), last_));
  const auto angle = [&](const SegmentExtreme& x) {
    return geometry_.segments[x.segment].angle_deg;
  };
  const LiningExtremes x = lining_extremes(geometry_, last_);
  const ForceExtremes& s = x.sections;
  LiningForceFigures f;
  f.step = e.step_count();
  f.segments = long(geometry_.segments.size());
  f.thickness_m = median_thickness(geometry_, segment_invert_, false);
  if (std::count(segment_invert_.begin(), segment_invert_.end(), 1))
    f.invert_thickness_m = median_thickness(geometry_, segment_invert_, true);
  f.corner_segments = std::count_if(geometry_.segments.begin(), geometry_.segments.end(),
                                    [](const LiningSegment& g) { return g.corner; });
  f.max_thrust_kN_per_m = s.max_thrust.value / 1e3;
  f.max_thrust_angle_deg = angle(s.max_thrust);
  f.max_thrust_x_m = geometry_.segments[s.max_thrust.segment].x;
  f.max_thrust_y_m = geometry_.segments[s.max_thrust.segment].y;
  f.max_thrust_in_invert = segment_invert_[s.max_thrust.segment];
  f.min_thrust_kN_per_m = s.min_thrust.value / 1e3;
  f.min_thrust_angle_deg = angle(s.min_thrust);
  f.max_abs_moment_kNm_per_m = s.max_abs_moment.value / 1e3;
  f.max_abs_moment_angle_deg = angle(s.max_abs_moment);
  f.max_abs_shear_kN_per_m = s.max_abs_shear.value / 1e3;
  f.max_abs_shear_angle_deg = angle(s.max_abs_shear);
  if (const std::optional<ForceExtremes>& c = x.corners)
    f.corners = LiningCornerFigures{f.corner_segments,        c->max_thrust.value / 1e3,
                                    angle(c->max_thrust),     c->min_thrust.value / 1e3,
                                    angle(c->min_thrust),     c->max_abs_moment.value / 1e3,
                                    angle(c->max_abs_moment), x.corners_exceed};
  check_capacity(f);
  return f;
}

void LiningOutput::check_capacity(LiningForceFigures& f) const {
  if (!sections_) {
    f.capacity = "not checked: materials.lining.compressive_strength not given";
    return;
  }
  const std::vector<double> fs = safety_factors(last_);
  const std::size_t i = std::size_t(std::min_element(fs.begin(), fs.end()) - fs.begin());
  const LiningSegment& s = geometry_.segments[i];
  f.capacity = capacity_text(*sections_);
  LiningCapacityFigures c;
  c.section = section_name(sections_->lining.kind);
  c.compressive_strength_Pa = sections_->lining.concrete.compressive;
  c.tensile_strength_Pa = sections_->lining.concrete.tensile;
  if (sections_->invert) {
    c.invert_section = section_name(sections_->invert->kind);
    c.invert_compressive_strength_Pa = sections_->invert->concrete.compressive;
    c.invert_tensile_strength_Pa = sections_->invert->concrete.tensile;
  }
  c.min_safety_factor_in_invert = segment_invert_[i];
  // An unloaded ring has no finite factor: JSON null.
  if (std::isfinite(fs[i])) c.min_safety_factor = fs[i];
  c.min_safety_factor_angle_deg = s.angle_deg;
  c.min_safety_factor_x_m = s.x;
  c.min_safety_factor_y_m = s.y;
  c.min_safety_factor_at_corner = s.corner;
  c.segments_below_1 = std::count_if(fs.begin(), fs.end(), [](double v) { return v < 1; });
  f.check = c;
}

void LiningOutput::plots(PlotWriter& plots) const {
  if (last_.empty()) return;
  std::vector<double> angle, n, m, v;
  for (std::size_t i = 0; i < last_.size(); ++i) {
    angle.push_back(geometry_.segments[i].angle_deg);
    n.push_back(last_[i].thrust / 1e3);
    m.push_back(last_[i].moment / 1e3);
    v.push_back(last_[i].shear / 1e3);
  }
  plots.panels("lining_forces.png",
               "Lining forces per metre, end of run (N: compression +; M > 0: rock side "
               "compressed)",
               "angle about the opening's centroid [deg] (0: right springline, 90: crown)",
               {{"thrust N [kN/m]", {{"N", angle, n}}, {}},
                {"moment M [kNm/m]", {{"M", angle, m}}, {}},
                {"shear V [kN/m]", {{"V", angle, v}}, {}}},
               1000);
  if (sections_) capacity_plot(plots, m, n);
}

// Each part's diagram at its median thickness, for safety factors 1 and 1.5
// (the radial factor: the diagram shrunk about the origin), with the
// part's segments' (M, N) [kNm/m, kN/m].
void LiningOutput::capacity_plot(PlotWriter& plots, const std::vector<double>& m,
                                 const std::vector<double>& n) const {
  std::vector<plots::PlotSeries> envelopes, points;
  const bool all_plain = sections_->lining.kind == SectionKind::kPlain &&
                         (!sections_->invert || sections_->invert->kind == SectionKind::kPlain);
  std::string title = all_plain ? "Lining capacity (plain sections, elastic)" : "Lining capacity";
  for (const bool invert : {false, true}) {
    if (invert && !sections_->invert) break;
    const LiningSection& sec = invert ? *sections_->invert : sections_->lining;
    const std::string part = sections_->invert ? (invert ? "invert" : "arch and walls") : "ring";
    const double t = median_thickness(geometry_, segment_invert_, invert);
    const std::vector<MNPoint> diagram = capacity_diagram(sec, t);
    for (double fs : {1.0, 1.5}) {
      char name[120];
      std::snprintf(name, sizeof name, "%s, safety factor %.1f", part.c_str(), fs);
      plots::PlotSeries c{name, {}, {}};
      for (const MNPoint& p : diagram) {
        c.x.push_back(p[0] / fs / 1e3);
        c.y.push_back(p[1] / fs / 1e3);
      }
      envelopes.push_back(std::move(c));
    }
    plots::PlotSeries pts{part + " segments, end of run", {}, {}};
    for (std::size_t i = 0; i < last_.size(); ++i)
      if (bool(segment_invert_[i]) == invert) {
        pts.x.push_back(m[i]);
        pts.y.push_back(n[i]);
      }
    points.push_back(std::move(pts));
    title += "; " + part + " " + section_caption(sec, t);
  }
  plots.panels("lining_capacity.png", title, "bending moment M [kNm/m]",
               {{"thrust N [kN/m]", envelopes, points}}, 800);
}

std::optional<std::pair<long, long>> lining_bond(const fdem::Engine& e, const mesh::Mesh& m) {
  // A bond acts only between two active triangles: a ring that was never
  // installed (or was removed) has none.
  long n_bond = 0, broken = 0;
  for (std::size_t c : coupling::lining_interface_cracks(e, m)) {
    const auto t = e.crack_triangles(c);
    if (!e.active(t[0]) || !e.active(t[1])) continue;
    ++n_bond;
    broken += e.crack_state(c) == fdem::CrackState::kBroken;
  }
  if (n_bond == 0) return std::nullopt;
  return std::make_pair(n_bond, broken);
}

}  // namespace rockfdem::workflows
