#include "outputs/run_plots.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "record/output_dir.hpp"

namespace rockfdem::workflows {
namespace {

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

bool starts_with(const std::string& s, const std::string& head) {
  return s.compare(0, head.size(), head) == 0;
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// An extensometer point's relative reading: "<name>_a<k>_mm" (the
// absolute one ends "_abs_mm", a monitor's "_ux_mm" and the like).
bool extensometer_point(const std::string& c) {
  if (!ends_with(c, "_mm")) return false;
  const std::string stem = c.substr(0, c.size() - 3);
  const std::size_t a = stem.rfind("_a");
  if (a == std::string::npos || a + 2 == stem.size()) return false;
  return stem.find_first_not_of("0123456789", a + 2) == std::string::npos;
}

constexpr double kLargestFactorShown = 5;  // larger safety factors are drawn at 5

// The lining ring's extremes over the run (history.csv's lining columns,
// "nan" before its installation): the largest thrust, the largest |moment|
// and, where its capacity is checked, the smallest safety factor with the
// line of 1; nothing while the ring was never installed.
void lining_history(PlotWriter& plots, const History& h, const std::vector<double>& t,
                    const std::vector<plots::PlotBand>& bands) {
  const std::vector<double> n = h.column("lining_max_thrust_kN_per_m");
  const std::vector<double> m = h.column("lining_max_abs_moment_kNm_per_m");
  const std::vector<double> fs = h.column("lining_min_safety_factor");
  plots::PlotSeries thrust{"largest thrust N", {}, {}}, moment{"largest |M|", {}, {}};
  plots::PlotSeries factor{"smallest safety factor", {}, {}};
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(n[i])) continue;  // not installed at this step
    thrust.x.push_back(t[i]), thrust.y.push_back(n[i]);
    moment.x.push_back(t[i]), moment.y.push_back(m[i]);
    // A ring just installed carries little: factors in the thousands
    // would leave the ones near 1 flat on the axis.
    if (std::isfinite(fs[i]))
      factor.x.push_back(t[i]), factor.y.push_back(std::min(fs[i], kLargestFactorShown));
  }
  if (thrust.x.empty()) return;
  std::vector<plots::PlotPanel> panels{{"largest N [kN/m]", {thrust}, {}},
                                       {"largest |M| [kNm/m]", {moment}, {}}};
  if (!factor.x.empty()) {
    const plots::PlotSeries capacity{
        "1: at capacity", {factor.x.front(), factor.x.back()}, {1.0, 1.0}};
    panels.push_back({"smallest safety factor [-], up to 5", {factor, capacity}, {}});
  }
  plots.panels("lining_history.png", "Lining ring over the run (N: compression +)", kStepAxis,
               panels, 900, bands);
}

// The support and the instruments over the run, where the history has
// them: each bolt's and cable's largest axial force, the lining ring's
// extremes, and each extensometer point's relative reading (the deepest
// anchor fixed).
void support_history(PlotWriter& plots, const History& h, const std::vector<double>& t,
                     const std::vector<plots::PlotBand>& bands) {
  const std::string bolt_tail = "_max_axial_kN";
  std::vector<plots::PlotSeries> bolts, points;
  for (const std::string& c : h.columns()) {
    if (starts_with(c, "bolt_") && ends_with(c, bolt_tail))
      bolts.push_back({c.substr(0, c.size() - bolt_tail.size()), t, h.column(c)});
    else if (extensometer_point(c))
      points.push_back({c.substr(0, c.size() - 3), t, h.column(c)});
  }
  if (!bolts.empty())
    plots.xy("bolt_forces_history.png", "Bolts and cables: largest axial force", kStepAxis,
             "axial force of largest magnitude along the bar [kN per bar], tension +", bolts, {},
             bands);
  const std::vector<std::string>& cols = h.columns();
  if (std::find(cols.begin(), cols.end(), "lining_max_thrust_kN_per_m") != cols.end())
    lining_history(plots, h, t, bands);
  if (!points.empty())
    plots.xy("extensometers.png", "Extensometers: each point against the deepest anchor", kStepAxis,
             "relative reading [mm], extension +", points, {}, bands);
}

}  // namespace

PlotWriter::PlotWriter(std::string dir, RunRecord& summary, bool quiet)
    : dir_(std::move(dir)), summary_(summary) {
  std::string why;  // ends with the advice to run under xvfb-run
  available_ = plots::rendering_available(&why);
  if (available_) return;
  summary_.skipped.push_back("plots: " + why);
  if (!quiet) std::cerr << "rockfdem: plots skipped: " << why << '\n';
}

void PlotWriter::note(bool rendered, const std::string& file, const std::string& why) {
  if (rendered)
    rendered_.push_back(file);
  else
    summary_.skipped.push_back("plot " + file + ": " + why);
}

void PlotWriter::xy(const std::string& file, const std::string& title, const std::string& x_label,
                    const std::string& y_label, const std::vector<plots::PlotSeries>& series,
                    const std::vector<plots::PlotMarker>& markers,
                    const std::vector<plots::PlotBand>& bands) {
  std::string why;
  note(plots::plot_xy_png(title, x_label, y_label, series, output_path(dir_, file), 900, 600, &why,
                          markers, bands),
       file, why);
}

void PlotWriter::panels(const std::string& file, const std::string& title,
                        const std::string& x_label, const std::vector<plots::PlotPanel>& panels,
                        int height, const std::vector<plots::PlotBand>& bands) {
  std::string why;
  note(plots::plot_panels_png(title, x_label, panels, output_path(dir_, file), 900, height, &why,
                              bands),
       file, why);
}

void PlotWriter::broken_cracks(const History& h, const std::string& x, const std::string& x_label,
                               const std::vector<plots::PlotBand>& bands) {
  const std::vector<double> t = h.column(x);
  xy("broken.png", "Broken crack elements by failure mode", x_label,
     "broken crack elements [count]",
     {{"mode I", t, h.column("broken_I")},
      {"mode II", t, h.column("broken_II")},
      {"mixed", t, h.column("broken_mixed")}},
     {}, bands);
}

void PlotWriter::picture(const std::string& file, const coupling::VtkGrid& grid,
                         const plots::MeshPicture& p) {
  std::string why;
  note(plots::render_picture_png(grid, p, output_path(dir_, file), 1000, 800, &why), file, why);
}

void PlotWriter::specimen_pictures(const fdem::Engine& e, bool most_tensile) {
  const coupling::VtkGrid grid = picture_grid(e);
  picture("final_mesh.png", grid, specimen_mesh_picture(e));
  picture(most_tensile ? "sigma_max_tensile.png" : "sigma_max_compressive.png", grid,
          whole_model_picture(e, most_tensile));
}

std::string time_axis_label(const fdem::Engine& e) {
  // Scaled masses make the simulated time a pseudo-time: say so on the axis.
  return e.mass_scaling_report().enabled ? "pseudo-time [s] (mass-scaled)" : "time [s]";
}

void tunnel_curves(PlotWriter& plots, const History& h, const std::vector<Monitor>& monitors,
                   const std::vector<StageSpan>& spans, std::optional<std::size_t> from) {
  std::vector<plots::PlotBand> bands = stage_bands(spans);
  const std::vector<double> t = h.column("step");
  // A run stopped inside a stage has no report of it; its rows get a band.
  if (!t.empty() && (bands.empty() || t.back() > bands.back().x1))
    bands.push_back({bands.empty() ? t.front() : bands.back().x1, t.back(),
                     std::to_string(int(h.column("stage").back())) + " (stopped in this stage)"});
  const std::size_t first = from.value_or(0);
  const auto curve = [&](const std::string& column) {
    return from ? since_row(h.column(column), first) : h.column(column);
  };
  const std::vector<double> tt(t.begin() + long(first), t.end());
  const std::string origin = from ? "since the support's installation" : "from the in-situ state";
  std::vector<plots::PlotSeries> points;
  for (const Monitor& mon : monitors)
    points.push_back({mon.name, tt, curve(mon.name + "_radial_mm")});
  plots.xy("convergence.png", "Key points: radial displacement towards the opening", kStepAxis,
           "radial displacement " + origin + " [mm]", points, {}, bands);
  plots.xy("chord_convergence.png", "Chord convergence (closure between key points)", kStepAxis,
           "closure " + origin + " [mm]",
           {{"walls (chord)", tt, curve("wall_chord_convergence_mm")},
            {"shoulders (chord)", tt, curve("shoulder_chord_convergence_mm")}},
           {}, bands);
  plots.broken_cracks(h, "step", kStepAxis, bands);
  support_history(plots, h, t, bands);
}

namespace {

/// The curve in pressure of one key point: the implicit solves' points.
plots::PlotSeries implicit_curve(const std::vector<GroundReactionPoint>& grc, const char* name) {
  plots::PlotSeries s{std::string(name) + " (elastic)", {}, {}};
  for (std::size_t i = 0; i + 1 < grc.size(); ++i) {
    const auto k = grc[i].key_points.find(name);
    if (k == grc[i].key_points.end()) continue;
    s.x.push_back(k->second.radial_mm);
    s.y.push_back(1e-6 * k->second.pressure_Pa);
  }
  return s;
}

plots::PlotSeries mohr_coulomb_curve(const std::vector<ContinuumGroundReactionPoint>& curve,
                                     const char* name) {
  plots::PlotSeries s{std::string(name) + " (Mohr-Coulomb)", {}, {}};
  for (const ContinuumGroundReactionPoint& p : curve) {
    const auto k = p.key_points.find(name);
    if (k == p.key_points.end()) continue;
    s.x.push_back(k->second.radial_mm);
    s.y.push_back(1e-6 * k->second.pressure_Pa);
  }
  return s;
}

/// The support lines from the installation, each flat past its maximum to
/// `x_end` [mm]; and the run's end point.
void add_support(std::vector<plots::PlotSeries>& series, const ConvergenceConfinementFigures& c,
                 double x_end) {
  const double u0 = c.install_radial_mm;
  for (const SupportLineFigures& l : c.support) {
    const double u1 = u0 + l.max_displacement_mm;
    series.push_back({"support: " + l.name,
                      {u0, u1, std::max(u1, x_end)},
                      {0.0, 1e-6 * l.p_max_Pa, 1e-6 * l.p_max_Pa}});
  }
  series.push_back({c.end_pressure_Pa ? "end of run: mean of key points, lining thrust / R"
                                      : "end of run: mean of key points (no lining)",
                    {c.end_radial_mm},
                    {1e-6 * c.end_pressure_Pa.value_or(0.0)},
                    true});
}

}  // namespace

void ground_reaction_plot(PlotWriter& plots, const RunRecord& r) {
  // Per key point, the implicit solves' curve and the Mohr-Coulomb
  // counterpart's; the support's lines on the equivalent circle from its
  // installation, and the run's end on the same axes.
  std::vector<plots::PlotSeries> series;
  double x_end = 0;
  const auto add = [&](plots::PlotSeries s) {
    if (s.x.empty()) return;
    for (const double x : s.x) x_end = std::max(x_end, x);
    series.push_back(std::move(s));
  };
  for (const char* name : {"vault", "right_wall", "invert"}) {
    add(implicit_curve(r.ground_reaction_curve, name));
    if (r.continuum_comparison)
      add(mohr_coulomb_curve(r.continuum_comparison->ground_reaction, name));
  }
  if (series.empty()) return;
  if (r.convergence_confinement)
    add_support(series, *r.convergence_confinement,
                std::max(x_end, r.convergence_confinement->end_radial_mm));
  plots.xy("ground_reaction.png", "Convergence-confinement: ground reaction and support",
           "radial displacement towards the opening from the in-situ state [mm]",
           "pressure on the opening [MPa]", series);
}

void tunnel_pictures(PlotWriter& plots, const PictureContext& c) {
  const coupling::VtkGrid grid = picture_grid(c.e);
  plots.picture("displacement.png", grid, displacement_picture(c));
  plots.picture("sigma_max_compressive.png", grid, principal_picture(c, true));
  plots.picture("sigma_min_compressive.png", grid, principal_picture(c, false));
  plots.picture("final_mesh.png", grid, mesh_picture(c));
}

void specimen_plots(const fdem::Engine& e, const History& h, bool disc, const std::string& dir,
                    RunRecord& summary, bool quiet) {
  PlotWriter plots(dir, summary, quiet);
  if (!plots.available()) return;
  const char* stress = disc ? "tensile_stress" : "axial_stress";
  plots.xy("stress_strain.png", disc ? "Brazilian test: tensile stress 2P/(pi D)" : "UCS test",
           "nominal axial strain (platen closure / length)",
           disc ? "tensile stress [MPa]" : "axial stress [MPa]",
           {{disc ? "tensile stress" : "axial stress", h.column("axial_strain"),
             scaled(h.column(stress), 1e-6)}});
  plots.broken_cracks(h, "time", time_axis_label(e));
  // A disc splits in tension (the major principal stress), a UCS specimen
  // is crushed (the minor).
  plots.specimen_pictures(e, disc);
}

}  // namespace rockfdem::workflows
