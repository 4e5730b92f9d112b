#include "outputs/lining_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "rockfdem/coupling/atomic_file.hpp"
#include "run/output_dir.hpp"

namespace rockfdem::workflows {
namespace {

// Index of the segment where `value` of the forces is largest.
template <class F>
std::size_t arg_max(const std::vector<SectionForces>& f, F value) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (value(f[i]) > value(f[best])) best = i;
  return best;
}

// Of the segments in the floor part (`invert`) or out of it; 0 where none.
double median_thickness(const LiningGeometry& g, const std::vector<char>& in_invert, bool invert) {
  std::vector<double> t;
  for (std::size_t i = 0; i < g.segments.size(); ++i)
    if (bool(in_invert[i]) == invert) t.push_back(g.segments[i].thickness);
  if (t.empty()) return 0;
  std::nth_element(t.begin(), t.begin() + long(t.size() / 2), t.end());
  return t[t.size() / 2];
}

}  // namespace

std::optional<RingStrength> ring_strength(const Scene& scene) {
  const auto it = scene.materials.find(mesh::kLining);
  if (it == scene.materials.end() || !(it->second.compressive_strength > 0)) return std::nullopt;
  RingStrength r;
  r.lining = {it->second.compressive_strength, it->second.tensile_strength};
  if (scene.invert)
    r.invert =
        ShotcreteStrength{scene.invert->compressive_strength, scene.invert->tensile_strength};
  return r;
}

LiningOutput::LiningOutput(const mesh::Mesh& m, double invert_top,
                           std::optional<RingStrength> strength, std::string dir)
    : strength_(strength), dir_(std::move(dir)) {
  if (auto g = lining_geometry(m)) geometry_ = std::move(*g);
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (m.zone[t] == mesh::kLining) triangles_.push_back(int(t));
  for (const LiningSegment& s : geometry_.segments) {
    const bool invert = s.y < invert_top;
    segment_invert_.push_back(invert);
    if (strength_) segment_strength_.push_back(invert ? *strength_->invert : strength_->lining);
  }
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

void LiningOutput::at_output_step(const OutputStep& step, std::vector<double>&) {
  const fdem::Engine& e = step.engine;
  if (!installed_ || !installed(e)) return;
  char name[40];
  std::snprintf(name, sizeof name, "lining_%06ld.csv", e.step_count());
  coupling::atomic_write_text(
      output_path(dir_, name),
      lining_csv(e.step_count(), geometry_, forces(e), strength_ ? &segment_strength_ : nullptr));
}

LiningForceFigures LiningOutput::finish(const fdem::Engine& e, const std::string& dir,
                                        PlotWriter* plots) {
  const LiningForceFigures f = figures(e, dir);
  if (plots) this->plots(*plots);
  return f;
}

LiningForceFigures LiningOutput::figures(const fdem::Engine& e, const std::string& dir) {
  last_ = forces(e);
  coupling::atomic_write_text(
      output_path(dir, "lining.csv"),
      lining_csv(e.step_count(), geometry_, last_, strength_ ? &segment_strength_ : nullptr));
  const auto angle = [&](std::size_t i) { return geometry_.segments[i].angle_deg; };
  const std::size_t n_max = arg_max(last_, [](const SectionForces& f) { return f.thrust; });
  const std::size_t n_min = arg_max(last_, [](const SectionForces& f) { return -f.thrust; });
  const std::size_t m_max =
      arg_max(last_, [](const SectionForces& f) { return std::abs(f.moment); });
  const std::size_t v_max =
      arg_max(last_, [](const SectionForces& f) { return std::abs(f.shear); });
  LiningForceFigures f;
  f.step = e.step_count();
  f.segments = long(geometry_.segments.size());
  f.thickness_m = median_thickness(geometry_, segment_invert_, false);
  if (std::count(segment_invert_.begin(), segment_invert_.end(), 1))
    f.invert_thickness_m = median_thickness(geometry_, segment_invert_, true);
  f.corner_segments = std::count_if(geometry_.segments.begin(), geometry_.segments.end(),
                                    [](const LiningSegment& s) { return s.corner; });
  f.max_thrust_kN_per_m = last_[n_max].thrust / 1e3;
  f.max_thrust_angle_deg = angle(n_max);
  f.min_thrust_kN_per_m = last_[n_min].thrust / 1e3;
  f.min_thrust_angle_deg = angle(n_min);
  f.max_abs_moment_kNm_per_m = std::abs(last_[m_max].moment) / 1e3;
  f.max_abs_moment_angle_deg = angle(m_max);
  f.max_abs_shear_kN_per_m = std::abs(last_[v_max].shear) / 1e3;
  f.max_abs_shear_angle_deg = angle(v_max);
  check_capacity(f);
  return f;
}

void LiningOutput::check_capacity(LiningForceFigures& f) const {
  if (!strength_) {
    f.capacity = "not checked: materials.lining.compressive_strength not given";
    return;
  }
  std::vector<double> fs;
  for (std::size_t i = 0; i < last_.size(); ++i)
    fs.push_back(safety_factor(last_[i], geometry_.segments[i].thickness, segment_strength_[i]));
  const std::size_t i = std::size_t(std::min_element(fs.begin(), fs.end()) - fs.begin());
  const LiningSegment& s = geometry_.segments[i];
  f.capacity =
      "plain shotcrete section, elastic: N/t +- 6M/t^2 within [-tensile, compressive] strength";
  LiningCapacityFigures c;
  c.compressive_strength_Pa = strength_->lining.compressive;
  c.tensile_strength_Pa = strength_->lining.tensile;
  if (strength_->invert) {
    c.invert_compressive_strength_Pa = strength_->invert->compressive;
    c.invert_tensile_strength_Pa = strength_->invert->tensile;
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
  if (!strength_) return;
  std::vector<plots::PlotSeries> envelopes, points;
  std::string title = "Lining capacity (plain sections, elastic)";
  for (const bool invert : {false, true}) {
    if (invert && !strength_->invert) break;
    const ShotcreteStrength& st = invert ? *strength_->invert : strength_->lining;
    const std::string part = strength_->invert ? (invert ? "invert" : "arch and walls") : "ring";
    const double t = median_thickness(geometry_, segment_invert_, invert);
    for (double fs : {1.0, 1.5}) {
      char name[120];
      std::snprintf(name, sizeof name, "%s, safety factor %.1f", part.c_str(), fs);
      plots::PlotSeries c{name, {}, {}};
      for (const auto& p : capacity_envelope(t, st, fs)) {
        c.x.push_back(p[0] / 1e3);
        c.y.push_back(p[1] / 1e3);
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
    char line[160];
    std::snprintf(line, sizeof line, "; %s t = %.3g m, fc = %.3g MPa, ft = %.3g MPa", part.c_str(),
                  t, st.compressive / 1e6, st.tensile / 1e6);
    title += line;
  }
  plots.panels("lining_capacity.png", title, "bending moment M [kNm/m]",
               {{"thrust N [kN/m]", envelopes, points}}, 800);
}

std::vector<std::size_t> lining_interface_cracks(const fdem::Engine& e, const mesh::Mesh& m) {
  std::vector<std::size_t> out;
  for (std::size_t c = 0; c < e.n_cracks(); ++c) {
    const auto t = e.crack_triangles(c);
    if ((m.zone[t[0]] == mesh::kLining) != (m.zone[t[1]] == mesh::kLining)) out.push_back(c);
  }
  return out;
}

std::optional<std::pair<long, long>> lining_bond(const fdem::Engine& e, const mesh::Mesh& m) {
  // A bond acts only between two active triangles: a ring that was never
  // installed (or was removed) has none.
  long n_bond = 0, broken = 0;
  for (std::size_t c : lining_interface_cracks(e, m)) {
    const auto t = e.crack_triangles(c);
    if (!e.active(t[0]) || !e.active(t[1])) continue;
    ++n_bond;
    broken += e.crack_state(c) == fdem::CrackState::kBroken;
  }
  if (n_bond == 0) return std::nullopt;
  return std::make_pair(n_bond, broken);
}

}  // namespace rockfdem::workflows
