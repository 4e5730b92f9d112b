#include "outputs/continuum_counterpart.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "outputs/continuum_comparison.hpp"
#include "outputs/continuum_ground_reaction.hpp"
#include "outputs/continuum_yield.hpp"
#include "outputs/run_plots.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/insitu_grid.hpp"
#include "rockfdem/coupling/mesh_grid.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/plastic.hpp"
#include "rockfdem/mesh/outline.hpp"
#include "stages/registry.hpp"
#include "stages/stage.hpp"
#include "stages/stage_inputs.hpp"

namespace rockfdem::workflows {
namespace {

// The stages' own checks walked again over the scene, for what each stage
// does to the core's factor and the lining. A stage the order does not
// allow changes nothing: the default sequence removes a core that an
// implicit alpha of 0 already took out.
class Replay : public StageCheck {
 public:
  struct Refused {};
  using StageCheck::StageCheck;
  [[noreturn]] void refuse(const std::string&, const std::string&) const override {
    throw Refused{};
  }
  void require(const std::string&, const std::string&) const override {}
};

/// The alphas of the scene's construction sequence, ending at 0, and the
/// alpha at which its lining stage installs the lining (-1: none).
std::vector<double> construction_alphas(const Scene& s, double* lining_alpha) {
  std::vector<double> alphas = s.insitu.alpha;
  StageOrder order;
  order.alpha = alphas.back();
  *lining_alpha = s.insitu.lining_active ? insitu::LiningStage{}.install_alpha : -1;
  for (const StageSpec& st : s.stages) {
    const StageOrder before = order;
    try {
      Replay replay(s, st, order);
      stage_of(st.kind).check(replay);
    } catch (const Replay::Refused&) {
      order = before;
    }
    if (order.alpha < before.alpha) alphas.push_back(order.alpha);
    if (order.lined && !before.lined && *lining_alpha < 0) *lining_alpha = before.alpha;
  }
  if (order.alpha > 0) alphas.push_back(0);
  return alphas;
}

insitu::InsituField field_of(const insitu::PlasticField& p) {
  insitu::InsituField f;
  f.alpha = 1 - p.lambda;
  f.lining_installed = p.lining_installed;
  f.stress = p.stress;
  f.active = p.active;
  f.ux = p.ux;
  f.uy = p.uy;
  f.unbalanced_ratio = p.unbalanced_ratio;
  return f;
}

void solve_elastic(const Scene& scene, const mesh::Mesh& m, ContinuumStates& c) {
  insitu::InsituSpec spec = insitu_spec(scene);
  spec.alphas = c.alphas;
  if (c.lining_alpha > 0 && !scene.insitu.lining_active) {
    // In the next stage, on the ground as this alpha left it (the engine's
    // lining stage installs on the state it finds).
    spec.lining.active = true;
    spec.lining.install_alpha = c.lining_alpha * (1 - 1e-9);
  }
  const std::vector<insitu::InsituField> fields = insitu::solve_insitu(m, spec);
  for (const auto& f : fields)
    if (f.alpha == scene.insitu.alpha.back()) c.handoff = f;
  c.end = fields.back();
}

/// The Mohr-Coulomb problem of the sequence c: the scene's loading with the
/// lining joining at c.lining_alpha, the rock's peak strength, the release
/// lambda = 1 - alpha of each alpha below 1.
void plastic_problem(const Scene& scene, const ContinuumStates& c, insitu::InsituSpec& spec,
                     insitu::PlasticSpec& p) {
  spec = insitu_spec(scene);
  spec.lining.active = c.lining_alpha > 0;
  if (spec.lining.active) spec.lining.install_alpha = c.lining_alpha;
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  p.rock = {rock.cohesion, rock.friction_angle, scene.insitu.dilation_angle};
  p.release.clear();
  for (const double a : c.alphas)
    if (a < 1) p.release.push_back(1 - a);
}

void solve_plastic(const Scene& scene, const mesh::Mesh& m, ContinuumStates& c) {
  insitu::InsituSpec spec;
  insitu::PlasticSpec p;
  plastic_problem(scene, c, spec, p);
  const std::vector<insitu::PlasticField> fields = insitu::solve_mohr_coulomb(m, spec, p);
  c.handoff.alpha = -1;  // none when the implicit stage stops at alpha = 1
  for (const auto& f : fields)
    if (std::abs(1 - f.lambda - scene.insitu.alpha.back()) < 1e-12) c.handoff = field_of(f);
  c.end = field_of(fields.back());
  c.yielded = fields.back().yielded;
  c.n_yielded = fields.back().n_yielded;
}

/// Whether a yielded triangle touches the outer boundary of the model.
bool yield_reaches_boundary(const mesh::Mesh& m, const std::vector<std::uint8_t>& yielded) {
  std::vector<std::uint8_t> outer(m.n_vertices(), 0);
  for (const auto& e : m.edges)
    if (e.tag >= mesh::kBottom && e.tag <= mesh::kLeft) outer[e.a] = outer[e.b] = 1;
  for (std::size_t t = 0; t < m.n_triangles(); ++t)
    if (yielded[t])
      for (const int v : m.triangles[t])
        if (outer[v]) return true;
  return false;
}

// ---------------------------------------------------------------------------
// The comparison.
// ---------------------------------------------------------------------------

double dot_sym(const std::array<double, 3>& s, double ax, double ay, double bx, double by) {
  return s[0] * ax * bx + s[1] * ay * by + s[2] * (ax * by + ay * bx);
}

std::array<double, 3> as_array(const insitu::Stress& s) { return {s.sxx, s.syy, s.sxy}; }

/// Relative L2 of `a` against `b` over the rock triangles active in both
/// within `reach` of the centre.
template <class StressA>
double stress_rel_l2(const mesh::Mesh& m, const StressA& a, const insitu::InsituField& b,
                     const std::vector<std::uint8_t>& active_a, double reach) {
  StressL2 l2;
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock || !active_a[t] || !b.active[t]) continue;
    const auto& tri = m.triangles[t];
    const double x = (m.x[tri[0]] + m.x[tri[1]] + m.x[tri[2]]) / 3;
    const double y = (m.y[tri[0]] + m.y[tri[1]] + m.y[tri[2]]) / 3;
    if (std::hypot(x, y) > reach) continue;
    l2.add(std::abs(mesh::signed_area(m, t)), a(t), as_array(b.stress[t]));
  }
  return l2.value();
}

/// The rock triangle containing (x, y), -1 if none.
int rock_triangle_at(const mesh::Mesh& m, double x, double y) {
  for (std::size_t t = 0; t < m.n_triangles(); ++t) {
    if (m.zone[t] != mesh::kRock) continue;
    const auto& tri = m.triangles[t];
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      inside = (m.x[b] - m.x[a]) * (y - m.y[a]) - (m.y[b] - m.y[a]) * (x - m.x[a]) >= 0;
    }
    if (inside) return static_cast<int>(t);
  }
  return -1;
}

struct Profile {
  std::string ray;
  std::vector<double> d, fdem_rr, fdem_tt, cont_rr, cont_tt;  // [m], [Pa]
  double yielded_depth = 0;                                   // [m]
};

/// Radial and tangential stress along the ray from the centre through a key
/// point, from the wall out to `reach`.
Profile ray_profile(const mesh::Mesh& m, const fdem::Engine& e, const ContinuumStates& c,
                    const Monitor& mon, double reach) {
  Profile p;
  p.ray = mon.name;
  const double r0 = std::hypot(mon.x, mon.y), nx = mon.x / r0, ny = mon.y / r0;
  const int n = 60;
  for (int i = 0; i < n; ++i) {
    const double d = (i + 0.5) * reach / n;
    const int t = rock_triangle_at(m, mon.x + d * nx, mon.y + d * ny);
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
    if (c.handoff.alpha >= 0) k.continuum_handoff_mm = mm(c.handoff.ux[v], c.handoff.uy[v]);
  }
  return out;
}

/// The Mohr-Coulomb ground reaction curve at the key points; one that
/// cannot be solved is named in "skipped" and the comparison stands.
void add_ground_reaction(const Scene& scene, const RunContext& ctx, const mesh::Mesh& m,
                         const fdem::Engine& e, const std::vector<Monitor>& monitors,
                         RunRecord& summary) {
  std::vector<WallPoint> points;
  for (const Monitor& mon : monitors)
    points.push_back({mon.name, e.node_vertex()[mon.node], mon.inward_x, mon.inward_y});
  try {
    summary.continuum_comparison->ground_reaction =
        keeping_threads(ctx, [&] { return mohr_coulomb_ground_reaction(scene, m, points); });
  } catch (const std::runtime_error& err) {
    summary.skipped.push_back(std::string("continuum ground reaction curve: ") + err.what());
  }
}

}  // namespace

ContinuumStates solve_continuum_counterpart(const Scene& scene, const mesh::Mesh& m) {
  const auto start = std::chrono::steady_clock::now();
  ContinuumStates c;
  c.model = scene.insitu.continuum;
  c.alphas = construction_alphas(scene, &c.lining_alpha);
  if (c.model == "mohr_coulomb")
    solve_plastic(scene, m, c);
  else
    solve_elastic(scene, m, c);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

PostPeakCounterpart solve_post_peak_counterpart(const Scene& scene, const mesh::Mesh& m) {
  ContinuumStates c;
  c.alphas = construction_alphas(scene, &c.lining_alpha);
  insitu::InsituSpec spec;
  insitu::PlasticSpec p;
  plastic_problem(scene, c, spec, p);
  PostPeakCounterpart out;
  out.residual_friction_deg = scene.materials.at(mesh::kRock).residual_friction_angle;
  p.residual = insitu::ResidualStrength{0, out.residual_friction_deg, 0};
  // A verdict, not a field: give up on a failing step sooner than the
  // counterpart itself does (25 iterations, 8 halvings); on the unlined test
  // scene 39 s instead of 130 s, the same verdict.
  p.max_newton = 12;
  p.max_halvings = 5;
  insitu::validate(p);  // InputError: the strengths cannot be posed this way
  std::vector<insitu::PlasticField> fields;
  try {
    fields = insitu::solve_mohr_coulomb(m, spec, p);
  } catch (const NumericalError& e) {
    out.reason = e.what();
    return out;
  }
  const insitu::PlasticField& f = fields.back();
  out.alpha = 1 - f.lambda;
  out.n_yielded = f.n_yielded;
  out.equilibrium = !yield_reaches_boundary(m, f.yielded);
  if (!out.equilibrium)
    out.reason = "the plastic zone reaches the model's outer boundary (" +
                 std::to_string(f.n_yielded) + " triangles yielded)";
  return out;
}

CounterpartComparison compare_with_counterpart(
    const Scene& scene, const mesh::Mesh& m, const fdem::Engine& e,
    const insitu::InsituField& fdem_handoff, const ContinuumStates& c,
    const std::vector<Monitor>& monitors, const std::string& dir, RunRecord& summary, bool quiet) {
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
  out.stress_rel_l2_end = stress_rel_l2(m, fdem_end, c.end, engine_active, reach);
  if (c.handoff.alpha >= 0)
    out.stress_rel_l2_handoff = stress_rel_l2(m, fdem_start, c.handoff, fdem_handoff.active, reach);
  out.key_points = key_points(e, fdem_handoff, c, monitors);
  std::vector<Profile> profiles;
  for (const Monitor& mon : monitors) profiles.push_back(ray_profile(m, e, c, mon, 2 * span));
  write_profiles(profiles, output_path(dir, "continuum_profiles.csv"));
  if (scene.output.vtk) write_continuum_grid(m, c, output_path(dir, "continuum.vtu"));
  if (scene.output.plots) plot_profiles(profiles, c, m, dir, summary, quiet);
  if (c.model == "mohr_coulomb") {
    out.yield = CounterpartYield{c.n_yielded, {}};
    for (const Profile& p : profiles) out.yield->depth_m[p.ray] = p.yielded_depth;
  }
  return out;
}

void compare_with_continuum_counterpart(const Scene& scene, const RunContext& ctx,
                                        const mesh::Mesh& m, const fdem::Engine& e,
                                        const insitu::InsituField& fdem_handoff,
                                        const std::vector<Monitor>& monitors, RunRecord& summary) {
  // A counterpart that cannot be solved leaves the run's own results standing.
  const auto skip = [&](const std::runtime_error& err) {
    summary.skipped.push_back(std::string("continuum comparison (insitu.continuum = ") +
                              scene.insitu.continuum + "): " + err.what());
  };
  try {
    const ContinuumStates c =
        keeping_threads(ctx, [&] { return solve_continuum_counterpart(scene, m); });
    summary.continuum_comparison = compare_with_counterpart(scene, m, e, fdem_handoff, c, monitors,
                                                            ctx.output_dir, summary, ctx.quiet);
    if (c.model == "mohr_coulomb") add_ground_reaction(scene, ctx, m, e, monitors, summary);
    if (scene.insitu.continuum_post_peak) {
      const auto start = std::chrono::steady_clock::now();
      summary.continuum_post_peak =
          keeping_threads(ctx, [&] { return solve_post_peak_counterpart(scene, m); });
      summary.continuum_post_peak->seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } catch (const InputError& err) {
    skip(err);
  } catch (const NumericalError& err) {
    skip(err);
  }
}

}  // namespace rockfdem::workflows
