#include "outputs/continuum_counterpart.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "outputs/continuum_comparison.hpp"
#include "outputs/continuum_yield.hpp"
#include "outputs/rock_locator.hpp"
#include "outputs/run_plots.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/insitu_grid.hpp"
#include "rockfdem/coupling/mesh_grid.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/insitu/plastic.hpp"
#include "rockfdem/mesh/outline.hpp"

namespace rockfdem::workflows {
namespace {

// ---------------------------------------------------------------------------
// The comparison.
// ---------------------------------------------------------------------------

double dot_sym(const std::array<double, 3>& s, double ax, double ay, double bx, double by) {
  return s[0] * ax * bx + s[1] * ay * by + s[2] * (ax * by + ay * bx);
}

std::array<double, 3> as_array(const insitu::Stress& s) { return {s.sxx, s.syy, s.sxy}; }

bool is_bolted(const std::vector<char>& bolted, std::size_t t) {
  return !bolted.empty() && bolted[t];
}

/// Relative L2 of `a` against `b` over the rock triangles active in both
/// within `reach` of the centre, bolt strips left out.
template <class StressA>
double stress_rel_l2(const mesh::Mesh& m, const StressA& a, const insitu::InsituField& b,
                     const std::vector<std::uint8_t>& active_a, const std::vector<char>& bolted,
                     double reach) {
  StressL2 l2;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock || !active_a[t] || !b.active[t] || is_bolted(bolted, t)) continue;
    const auto& tri = m.triangles[t];
    const double x = (m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3;
    const double y = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
    if (std::hypot(x, y) > reach) continue;
    l2.add(std::abs(mesh::signed_area(m, t)), a(t), as_array(b.stress[t]));
  }
  return l2.value();
}

struct Profile {
  std::string ray;
  std::vector<double> d, fdem_rr, fdem_tt, cont_rr, cont_tt;  // [m], [Pa]
  double yielded_depth = 0;                                   // [m]
};

/// The rock triangle at (x, y), or where that is a bolt strip the nearest
/// rock beside it across the ray (direction (tx, ty)), half a strip's
/// width at a time up to three widths: -1 if none.
int rock_beside_bolts(const mesh::Mesh& m, const RockLocator& rock, const std::vector<char>& bolted,
                      double x, double y, double tx, double ty) {
  const int t = rock.at(x, y);
  if (t < 0 || !is_bolted(bolted, std::size_t(t))) return t;
  const double width = std::sqrt(2 * std::abs(mesh::signed_area(m, std::size_t(t))));
  for (int k = 1; k <= 6; ++k)
    for (const double side : {1.0, -1.0}) {
      const double s = side * k * 0.5 * width;
      const int u = rock.at(x + s * tx, y + s * ty);
      if (u >= 0 && !is_bolted(bolted, std::size_t(u))) return u;
    }
  return -1;
}

/// Radial and tangential stress along the ray from the centre through a key
/// point, from the wall out to `reach`. A bolt on the ray (as at the vault)
/// would read the strip's scaled steel stress: the rock beside it is read.
Profile ray_profile(const mesh::Mesh& m, const RockLocator& rock, const fdem::Engine& e,
                    const ContinuumStates& c, const Monitor& mon, const std::vector<char>& bolted,
                    double reach) {
  Profile p;
  p.ray = mon.name;
  const double r0 = std::hypot(mon.x, mon.y), nx = mon.x / r0, ny = mon.y / r0;
  const int n = 60;
  for (int i = 0; i < n; ++i) {
    const double d = (i + 0.5) * reach / n;
    const int t = rock_beside_bolts(m, rock, bolted, mon.x + d * nx, mon.y + d * ny, -ny, nx);
    if (t < 0 || !e.active(t) || !c.end.active[t]) continue;
    const auto sf = e.triangle_stress(t);
    const auto sc = as_array(c.end.stress[t]);
    p.d.push_back(d);
    p.fdem_rr.push_back(dot_sym(sf, nx, ny, nx, ny));
    p.fdem_tt.push_back(dot_sym(sf, -ny, nx, -ny, nx));
    p.cont_rr.push_back(dot_sym(sc, nx, ny, nx, ny));
    p.cont_tt.push_back(dot_sym(sc, -ny, nx, -ny, nx));
    if (!c.yielded.empty() && c.yielded[t]) p.yielded_depth = d;
  }
  return p;
}

void write_profiles(const std::vector<Profile>& profiles, const std::string& path) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "ray,distance_from_wall_m,fdem_srr_Pa,fdem_stt_Pa,continuum_srr_Pa,continuum_stt_Pa\n";
  for (const Profile& p : profiles)
    for (std::size_t i = 0; i < p.d.size(); ++i)
      csv << p.ray << ',' << p.d[i] << ',' << p.fdem_rr[i] << ',' << p.fdem_tt[i] << ','
          << p.cont_rr[i] << ',' << p.cont_tt[i] << '\n';
  coupling::atomic_write_text(path, csv.str());
}

// Compression positive, as the pictures: the engine and deal.II give
// tension positive [Pa].
std::vector<double> compression_mpa(std::vector<double> v) {
  for (double& x : v) x *= -1e-6;
  return v;
}

/// continuum_profiles.png: one chart per key point's ray, FDEM's and the
/// counterpart's radial and tangential stress; with Mohr-Coulomb,
/// continuum_yield.png.
void plot_profiles(const std::vector<Profile>& profiles, const ContinuumStates& c,
                   const mesh::Mesh& m, const std::string& dir, RunRecord& summary, bool quiet) {
  // Without a display the run's own plots say so, once.
  if (!plots::rendering_available()) return;
  PlotWriter plots(dir, summary, quiet);
  const std::string name = c.model == "mohr_coulomb" ? "Mohr-Coulomb" : c.model;
  std::vector<plots::PlotPanel> panels;
  for (const Profile& p : profiles) {
    if (p.d.empty()) continue;
    panels.push_back({p.ray + " [MPa]",
                      {{"FDEM radial", p.d, compression_mpa(p.fdem_rr)},
                       {"FDEM tangential", p.d, compression_mpa(p.fdem_tt)},
                       {name + " radial", p.d, compression_mpa(p.cont_rr)},
                       {name + " tangential", p.d, compression_mpa(p.cont_tt)}},
                      {}});
  }
  if (!panels.empty())
    plots.panels("continuum_profiles.png",
                 "Stress along each key point's ray, end of run: FDEM vs " + name +
                     " continuum (compression +)",
                 "distance from the wall along the ray [m]", panels, 260 * int(panels.size()));
  if (c.model == "mohr_coulomb" && !c.yielded.empty())
    plots.picture("continuum_yield.png", coupling::mesh_grid(m),
                  yield_picture(m, c.yielded, c.end.active));
}

/// The continuum's end state as insitu.vtu is written, with the model named
/// and, for Mohr-Coulomb, "yielded" per triangle.
void write_continuum_grid(const mesh::Mesh& m, const ContinuumStates& c, const std::string& path) {
  coupling::VtkGrid g = coupling::insitu_grid(m, c.end);
  g.field.text.push_back({"continuum_model", c.model});
  g.field.text.push_back({"yielded_codes", "1 the triangle flowed plastically, 0 it did not"});
  if (!c.yielded.empty())
    g.cell_arrays.push_back(coupling::scalar_array(
        "yielded", std::vector<std::int32_t>(c.yielded.begin(), c.yielded.end())));
  coupling::write_vtu(g, path);
}

std::map<std::string, CounterpartKeyPoint> key_points(const fdem::Engine& e,
                                                      const insitu::InsituField& fdem_handoff,
                                                      const ContinuumStates& c,
                                                      const std::vector<Monitor>& monitors) {
  std::map<std::string, CounterpartKeyPoint> out;
  const auto mm = [](double ux, double uy) { return std::array<double, 2>{1e3 * ux, 1e3 * uy}; };
  for (const Monitor& mon : monitors) {
    const int v = e.node_vertex()[mon.node];
    const auto fdem_end = monitor_displacement(e, mon, fdem_handoff.ux, fdem_handoff.uy);
    CounterpartKeyPoint& k = out[mon.name];
    k = {mm(fdem_end[0], fdem_end[1]), mm(c.end.ux[v], c.end.uy[v]),
         mm(fdem_handoff.ux[v], fdem_handoff.uy[v]), std::nullopt};
    const insitu::InsituField& h = c.handoff_field(fdem_handoff);
    if (h.alpha >= 0) k.continuum_handoff_mm = mm(h.ux[v], h.uy[v]);
  }
  return out;
}

}  // namespace

CounterpartComparison compare_with_counterpart(
    const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
    const insitu::InsituField& fdem_handoff, const ContinuumStates& c,
    const std::vector<Monitor>& monitors, const std::vector<char>& bolted, const std::string& dir,
    RunRecord& summary, bool quiet) {
  const mesh::HalfExtent h = mesh::opening_half_extent(scene.mesh.tunnel);
  const double span = std::max(h.hx, h.hy), reach = 5 * span;
  std::vector<std::uint8_t> engine_active(m.n_triangles());
  for (std::size_t t = 0; t < m.n_triangles(); ++t) engine_active[t] = e.active(t);
  const auto fdem_end = [&e](std::size_t t) { return e.triangle_stress(t); };
  const auto fdem_start = [&fdem_handoff](std::size_t t) {
    return as_array(fdem_handoff.stress[t]);
  };
  CounterpartComparison out;
  out.model = c.model;
  out.sequence_alpha = c.alphas;
  out.solve_seconds = c.seconds;
  if (c.lining_alpha >= 0) out.lining_alpha = c.lining_alpha;
  out.stress_rel_l2_end = stress_rel_l2(m, fdem_end, c.end, engine_active, bolted, reach);
  if (c.handoff.alpha >= 0)
    out.stress_rel_l2_handoff = stress_rel_l2(m, fdem_start, c.handoff_field(fdem_handoff),
                                              fdem_handoff.active, bolted, reach);
  out.key_points = key_points(e, fdem_handoff, c, monitors);
  std::vector<Profile> profiles;
  const RockLocator rock(m);
  for (const Monitor& mon : monitors)
    profiles.push_back(ray_profile(m, rock, e, c, mon, bolted, 2 * span));
  write_profiles(profiles, output_path(dir, "continuum_profiles.csv"));
  if (scene.output.vtk) write_continuum_grid(m, c, output_path(dir, "continuum.vtu"));
  if (scene.output.plots) plot_profiles(profiles, c, m, dir, summary, quiet);
  if (c.model == "mohr_coulomb") {
    out.yield = CounterpartYield{c.n_yielded, {}};
    for (const Profile& p : profiles) out.yield->depth_m[p.ray] = p.yielded_depth;
  }
  return out;
}

}  // namespace rockfdem::workflows
