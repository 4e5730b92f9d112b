// `rockfdem check SCENE`: the scene is valid (validation already ran), so
// print the figures a user wants before committing to a run: estimated
// triangle and crack-element counts, memory, run time and the stable time
// step. No meshing (a .msh scene's file is read: its counts are exact, and a
// bad file is refused here), nothing written. Every command also refuses,
// before meshing, a scene whose memory estimate exceeds this machine's memory.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "commands/check_probe.hpp"
#include "commands/commands.hpp"
#include "commands/expected_steps.hpp"
#include "commands/run_time_estimate.hpp"
#include "outputs/broken_zone.hpp"
#include "outputs/rock_plausibility.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "rockfdem/mesh/outline.hpp"
#include "run/engine_setup.hpp"

namespace rockfdem::workflows {
namespace {

struct Estimate {
  double triangles = 0;
  double fracture_triangles = 0;
  double min_altitude = 0;  ///< [m]; 0: not known before meshing
  double fracture_h = 0;    ///< fracture zone's mean edge [m]; 0: not known before meshing
  bool exact = false;       ///< counted from a .msh file
};

// Area of an equilateral triangle of edge h, the element gmsh aims for.
double triangle_area(double h) { return std::sqrt(3.0) / 4 * h * h; }

// Integrates 1 / (triangle area at the local size) over the domain on a
// sampling grid, with the size graded linearly from the tunnel outwards as
// the mesher does.
Estimate estimate_tunnel(const Scene& s) {
  const mesh::MeshSpec& m = s.mesh;
  const mesh::Outline outline = mesh::tunnel_outline(m.tunnel);
  const int n = 400;
  const double dx = m.domain.width / n, dy = m.domain.height / n;
  Estimate e;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = m.domain.center_x - m.domain.width / 2 + (i + 0.5) * dx;
      const double y = m.domain.center_y - m.domain.height / 2 + (j + 0.5) * dy;
      if (mesh::inside_outline(outline, x, y)) {
        e.triangles += dx * dy / triangle_area(m.size.size_near);
        continue;
      }
      const double d = mesh::distance_to_outline(outline, x, y);
      const double h = local_size(m, d);
      const double count = dx * dy / triangle_area(h);
      e.triangles += count;
      if (d <= m.tunnel.fracture_zone) e.fracture_triangles += count;
    }
  }
  return e;
}

// The in-situ traction loads the box on its four sides: a mesh without one
// of them cannot carry it.
void require_box_sides(const Scene& s, const mesh::Mesh& m) {
  for (mesh::EdgeTag tag : {mesh::kBottom, mesh::kRight, mesh::kTop, mesh::kLeft})
    if (std::none_of(m.edges.begin(), m.edges.end(),
                     [tag](const mesh::TaggedEdge& e) { return e.tag == tag; }))
      throw InputError(s.source + ": key 'msh.edges': no edge of " + s.mesh.msh.path +
                       " is tagged \"" + mesh::edge_tag_name(tag) +
                       "\", and the in-situ stress loads the box on "
                       "its bottom, right, top and left sides; allowed: a table mapping the "
                       "file's 1D physical groups to those four tags (and \"excavation\", "
                       "\"lining_inner\"), e.g. { Floor = \"bottom\" }");
}

// A user's mesh is read (cheap next to a run): its counts, and a bad file,
// group name or fracture group refused (InputError) before anything is written.
Estimate read_msh_figures(const Scene& s) {
  mesh::MeshReport report;
  const mesh::Mesh m = mesh::build_mesh(s.mesh, &report);
  require_box_sides(s, m);
  Estimate e;
  e.triangles = double(m.n_triangles());
  e.fracture_triangles = double(std::count(m.fracture.begin(), m.fracture.end(), 1));
  e.min_altitude = report.min_altitude;
  e.fracture_h = fracture_resolution(s, &m).h;  // mesh.size_near means nothing to a .msh
  e.exact = true;
  return e;
}

Estimate estimate(const Scene& s) {
  const mesh::MeshSpec& m = s.mesh;
  const double a = triangle_area(m.size.size_near);
  switch (m.kind) {
    case mesh::ModelKind::kTunnel:
      return estimate_tunnel(s);
    case mesh::ModelKind::kUcs: {
      const double t = m.specimen.width * m.specimen.height / a;
      return {t, t};
    }
    case mesh::ModelKind::kBrazilian: {
      const double t = M_PI * m.specimen.diameter * m.specimen.diameter / 4 / a;
      return {t, t};
    }
    case mesh::ModelKind::kMshFile:
      return read_msh_figures(s);
  }
  return {};
}

// Peak memory of a run without a probe: the libraries' baseline plus, per
// triangle, the implicit stage's peak, which sets the run's, and each
// implicit field held whole (stress, activity, displacements: 37 B per
// triangle measured, 1000 alphas all held on the default tunnel's 8,798
// triangles peaking at 582 MB). Measured on the one-shot seed tunnel at
// 3,337,814 triangles (one explicit step per stage, 2 threads): 2,911 MiB,
// 834 B per triangle above 256 MiB with one field held, the same mesh read
// as a .msh 2,898 MiB; the engine holds 443 B per triangle after its
// set-up (about 500 after 2,000 steps at 420k). 1000 B per triangle leaves
// room for the engine's growth over a long run; the bound shown adds
// kMemoryMargin.
constexpr double kBaseBytes = 256.0 * 1048576;
constexpr double kBytesPerTriangle = 1000;
constexpr double kBytesPerAlphaTriangle = 40;
constexpr double kMemoryMargin = 1.5;

// The implicit fields a run holds whole at once (run/field_sampler.hpp):
// under insitu.handoff = "last" the last alpha's alone (and, while the
// counterpart's tail is solved after it, that tail's field: not where the
// peak is); under
// "first_crack" the hand-off's candidate and the field just solved; with
// insitu.install_at_face_distance every alpha's and the one being solved
// (the open hole's, then the installation's).
double fields_held(const Scene& s) {
  const double n = double(s.insitu.alpha.size());
  if (s.insitu.install_at_face_distance) return n + 1;
  return s.insitu.handoff_first_crack ? std::min(n, 2.0) : std::min(n, 1.0);
}

// A Mohr-Coulomb or post-peak counterpart is factored by UMFPACK on the
// whole mesh before the engine is built: 1.75 GiB of peak RSS for the 440k
// factorisation (docs/benchmarks.md, "In-situ stage: bench_insitu and the
// tests"), about 4.2 kB per triangle, and more than linear in the
// mesh. The elastic counterpart is solved by AMG-CG like the implicit stage.
constexpr double kDirectCounterpartBytesPerTriangle = 4200;

double counterpart_bytes_per_triangle(const Scene& s) {
  const bool direct = s.insitu.continuum == "mohr_coulomb" || s.insitu.continuum_post_peak;
  return direct ? kDirectCounterpartBytesPerTriangle : 0.0;
}

double peak_bytes(const Scene& s, const Estimate& e) {
  return kBaseBytes + (kBytesPerTriangle + kBytesPerAlphaTriangle * fields_held(s) +
                       counterpart_bytes_per_triangle(s)) *
                          e.triangles;
}

double machine_bytes() { return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE)); }

// Serial engine throughput measured on the 2-core development machine
// (docs/benchmarks.md, "A vector kernel for the narrow phase"): 11 M
// triangle-steps/s for intact models (bench_ucs: 15 M), 8 M for a
// fracturing model with contact (the default tunnel: 10.4 M on one idle
// thread; a confined specimen after heavy fracture, every triangle
// fracturing: 5.3 M); 0.9 parallel efficiency at 2 threads; mesh and
// implicit stage about 90 us per triangle.
// Each alpha is one implicit solve and its output: 12 us per triangle
// (1000 alphas on the default tunnel's 8,798 triangles took 107 s). The
// bound shown is kTimeMargin times this sum: refined meshes ran up to 2.2
// times the plain figures (size_near 0.05).
constexpr double kAlphaSecondsPerTriangle = 12e-6;
constexpr double kTimeMargin = 2.5;

// What each stage costs beyond its steps: its change (damping, supports,
// the core), the energy ledger, the history row and the files rewritten
// at its end. Measured on the shared 2-core machine, 200 one-step
// equilibrium stages of the elastic circular tunnel: 25 ms per stage at
// 2,048 triangles, 20 ms at 4,688; 20,000 such stages of a scene were
// bounded at 70 s by steps alone and took 14 ms each. The bound
// takes 10 ms + 8 us per triangle per stage.
constexpr double kStageSeconds = 0.010;
constexpr double kStageSecondsPerTriangle = 8e-6;

double stage_changes(const Scene& s) {
  return s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile
             ? double(s.stages.size())
             : 0.0;
}

double stage_seconds(const Scene& s, double triangles) {
  return stage_changes(s) * (kStageSeconds + kStageSecondsPerTriangle * triangles);
}

// Explicit throughput per thread without a probe: 11 M triangle-steps/s
// for an unbroken model; 6 M where fracture and contact run (the one-shot
// seed tunnel on 2 threads: 6.3 M per thread at 420k triangles, 5.6 M at
// 3.3M; docs/benchmarks.md "The tunnel against the UCS bench per
// element", "The paper's large case").
double run_seconds(const Scene& s, const Estimate& e, int threads) {
  const double serial = e.fracture_triangles > 0 && s.engine.contact ? 6e6 : 11e6;
  const double rate = serial * std::max(1, threads) * (threads > 1 ? 0.9 : 1.0);
  const double implicit = kAlphaSecondsPerTriangle * double(s.insitu.alpha.size()) * e.triangles;
  return 90e-6 * e.triangles + implicit + explicit_steps(s) * e.triangles / rate +
         stage_seconds(s, e.triangles);
}

// Plane-strain P-wave speed of the rock.
double p_wave_speed(const MaterialSpec& r, bool plane_stress) {
  const double nu = r.poisson;
  const double modulus =
      plane_stress ? r.young / (1 - nu * nu) : r.young * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  return std::sqrt(modulus / r.density);
}

}  // namespace

void refuse_if_too_large(const Scene& scene) {
  const Estimate e = estimate(scene);
  const double need = peak_bytes(scene, e), have = machine_bytes();
  if (need <= have) return;
  char msg[600];
  if (e.exact)
    std::snprintf(msg, sizeof msg,
                  "%s: key 'msh.file' = \"%s\": the mesh has %.0f triangles and would need "
                  "about %.1f GiB, more than this machine's %.1f GiB; give a coarser mesh",
                  scene.source.c_str(), scene.mesh.msh.path.c_str(), e.triangles,
                  need / 1073741824.0, have / 1073741824.0);
  else
    std::snprintf(msg, sizeof msg,
                  "%s: key 'mesh.size_near' = %g: the model would have about %.3g triangles and "
                  "need about %.1f GiB, more than this machine's %.1f GiB; coarsen "
                  "mesh.size_near or shrink the domain",
                  scene.source.c_str(), scene.mesh.size.size_near, e.triangles, need / 1073741824.0,
                  have / 1073741824.0);
  throw InputError(msg);
}

namespace {

// The probe's figures into bounds: the explicit stages' cost per step
// measured here, raised for fracture (the probe's unloaded model does not
// fracture; run_time_estimate.hpp), plus meshing as measured and the
// implicit stage from its documented constants; memory as measured after
// meshing and building the engine, plus the implicit stage's share.
// Fixed and output costs the probe does not see: the process's start (MPI
// and library initialisation, scene reading: 0.9 s measured), and writing
constexpr double kStartSeconds = 2.0;
// each output step's frame and history row (10 us per triangle for the
// frame, and 5 ms for the files it rewrites: an output within a stage
// took 4-8 ms at 2,048 triangles), and the end's pictures, report and
// continuum counterpart with output.plots: 4 s + 0.03 ms per triangle
// (the runs' "output" timers less their frames: 2.4-6.7 s at 5,382-39,364
// triangles under a load of 5, docs/benchmarks.md, "check's bounds
// against runs").
constexpr double kOutputSecondsPerTriangle = 10e-6;
constexpr double kOutputSeconds = 0.005;
constexpr double kPicturesSeconds = 4.0;
constexpr double kPicturesSecondsPerTriangle = 0.03e-3;
constexpr double kProbeMemoryMargin = 1.25;
// What a tunnel run holds above the probe: the implicit solves (deal.II's
// grid and PETSc's matrix and hierarchy, freed before the engine is
// built), the fields the outputs keep and the frames. Peak RSS on
// tunnel-seed-oneshot.toml (2 threads, 300 explicit steps,
// docs/benchmarks.md "check's bound after the run's peak fell"): 169.6,
// 169.0 and 393.4 MiB at 16,284, 111,446 and 419,852 triangles over probes
// of 169.5, 169.4 and 391.6 MiB (the start-up's high-water mark is the
// floor of both); at 3,337,814 triangles the implicit stage peaked 78 MiB
// (24 B per triangle) above the engine's set-up. 100 B per triangle keeps
// every bound at least 26% above its run.
constexpr double kImplicitBytesPerTriangle = 100;

// Output steps at most: each stage's (and its last), or the specimen's.
double output_steps(const Scene& s) {
  if (!staged(s)) return double(s.engine.steps) / std::max(1, s.output.every_steps) + 1;
  double n = 1;  // the hand-off
  for (const StageSpec& st : s.stages) n += double(st.max_steps) / std::max(1, st.every_steps) + 1;
  return n;
}

RunTimeFigures probe_run_time(const Scene& s, const Probe& p, double expected) {
  const double tri = double(p.triangles);
  const double implicit =
      staged(s) ? 90e-6 * tri + kAlphaSecondsPerTriangle * tri * double(s.insitu.alpha.size())
                : 0.0;
  // Without output.vtk no frame is written, only the history row.
  const double frame = s.output.vtk ? kOutputSecondsPerTriangle * tri : 0;
  const double outputs =
      output_steps(s) * (kOutputSeconds + frame) +
      (s.output.plots ? kPicturesSeconds + kPicturesSecondsPerTriangle * tri : 0);
  RunTimeInputs in;
  in.fixed_seconds = kStartSeconds + p.mesh_seconds + implicit + outputs + stage_seconds(s, tri);
  in.seconds_per_step = p.seconds_per_step;
  in.steps = explicit_steps(s);
  in.expected_steps = expected;
  in.fracture_share = double(p.fracture_triangles) / double(std::max<std::size_t>(p.triangles, 1));
  in.joints = !s.mesh.joints.empty();
  in.fails_at_once = fails_at_once(s);
  return run_time(in);
}

double probe_bytes(const Scene& s, const Probe& p) {
  return p.rss_bytes + (kImplicitBytesPerTriangle + kBytesPerAlphaTriangle * fields_held(s) +
                        counterpart_bytes_per_triangle(s)) *
                           double(p.triangles);
}

// What the run's time grows with: implicit solves and explicit steps.
void print_step_counts(const Scene& scene) {
  std::printf("  implicit solves (alphas):   %zu\n", scene.insitu.alpha.size());
  std::printf("  explicit steps (at most):   %.0f\n", explicit_steps(scene));
}

// The expected steps and what they come from: the wave transit where
// check knows the mesh's grading (expected_steps.hpp), else half the caps.
void print_expected_steps(const Scene& scene, double transit, double expected) {
  if (transit > 0) {
    char failure[160] = "";
    if (rock_fails_at_opening(scene))
      std::snprintf(failure, sizeof failure,
                    ", and the rock's failure at the opening %g more, spent by the stages in "
                    "order%s",
                    kFailureTransits,
                    fails_at_once(scene) ? " (all at once: no soften stage)" : "");
    std::printf(
        "  explicit steps (expected):  %.0f (a P-wave crosses from the opening to the box's side "
        "in %.0f steps; a stage settles at a ratio of 1e-3 in %g transits%s; a grout trigger "
        "fires after %g)\n",
        expected, transit, kSettleTransits, failure, kGroutTransits);
  } else if (staged(scene))
    std::printf(
        "  explicit steps (expected):  %.0f (a stage that ends at its criterion, equilibrium "
        "or a grout trigger, at half its cap)\n",
        expected);
  else
    std::printf("  explicit steps (expected):  %.0f (%s)\n", expected,
                scene.engine.stop_after_peak > 0 ? "a specimen stops after its peak" : "as given");
}

void print_probe(const Scene& scene, const Probe& p, double cp) {
  std::printf("  triangles (meshed):         %zu\n", p.triangles);
  std::printf("  smallest altitude:          %.3g m\n", p.min_altitude);
  std::printf(
      "  peak memory (bound):        %.1f MiB at most, of %.1f MiB on this machine (bound: "
      "%.1f MiB measured after meshing and building the engine + %.0f B per triangle + %.0f "
      "B per triangle per implicit field held + %.0f B per triangle for a direct "
      "counterpart's factor, x %.2f margin)\n",
      kProbeMemoryMargin * probe_bytes(scene, p) / 1048576.0, machine_bytes() / 1048576.0,
      p.rss_bytes / 1048576.0, kImplicitBytesPerTriangle, kBytesPerAlphaTriangle,
      counterpart_bytes_per_triangle(scene), kProbeMemoryMargin);
  print_step_counts(scene);
  const double transit = transit_steps(scene, p.dt_stages, cp);
  const double expected = expected_steps(scene, transit);
  print_expected_steps(scene, transit, expected);
  const RunTimeFigures t = probe_run_time(scene, p, expected);
  const char* plural = p.threads == 1 ? "" : "s";
  std::printf(
      "  run time (estimate):        about %.0f s on %d thread%s, between %.0f s and the bound "
      "(%.3g ms per step measured here over %ld steps, x %.2f for the fracture%s expected, x "
      "%.0f steps expected, + %.1f s for meshing, the implicit stage, start-up, outputs, "
      "pictures and stage changes)\n",
      t.estimate, p.threads, plural, t.least, 1e3 * p.seconds_per_step, p.steps,
      t.expected_step_factor, scene.mesh.joints.empty() ? "" : " and joints", expected, t.least);
  std::printf(
      "  run time (bound):           %.0f s at most on %d thread%s (bound: %.3g ms per step "
      "measured here over %ld steps, x %.2f for fracture%s, x the steps, + meshing %.2f s + the "
      "implicit stage + start-up and outputs + %.0f stage changes at %.3g s each, x %.1f "
      "margin)\n",
      t.bound, p.threads, plural, 1e3 * p.seconds_per_step, p.steps, t.worst_step_factor,
      scene.mesh.joints.empty() ? "" : " and joints", p.mesh_seconds, stage_changes(scene),
      stage_seconds(scene, double(p.triangles)) / std::max(1.0, stage_changes(scene)),
      kRunTimeMargin);
  std::fputs(busy_machine_note(p).c_str(), stdout);
  std::printf("  stable time step:           %.4g s on true masses (this mesh, its penalties)\n",
              scene.engine.dt_safety * p.critical_true);
  std::printf("  time step at the start:     %.8g s%s%s\n", p.dt_start,
              scene.engine.mass_scaling ? " (mass-scaled, quasi-static pseudo-time)" : "",
              scene.insitu.handoff_first_crack
                  ? "; at the last alpha: the first-crack hand-off's alpha is known only "
                    "once the implicit stage has run, and its step differs by about 0.2%"
                  : "");
  if (staged(scene))
    std::printf(
        "  time step in the stages:    %.8g s at most (with their damping; a lining, bolts or "
        "grout may lower it)\n",
        p.dt_stages);
}

// Without a probe (a model above kProbeTriangleLimit): the figures from
// check's estimate and the documented constants above.
void print_constants(const Scene& scene, const Estimate& e, double cp, int threads) {
  const MaterialSpec& rock = scene.materials.at(mesh::kRock);
  // A gmsh Frontal-Delaunay mesh's smallest altitude is about 0.3 of the
  // near size (measured: 0.095 m at 0.35 m); crack penalties p = f E stiffen
  // it further (dt ~ h sqrt(rho / p)).
  const double h = e.min_altitude > 0 ? e.min_altitude : 0.3 * scene.mesh.size.size_near;
  double dt = h / cp;
  if (e.fracture_triangles > 0)
    dt = std::min(dt, h * std::sqrt(rock.density / (rock.penalty_factor * rock.young)));
  dt *= scene.engine.dt_safety;
  std::printf("  (no probe above %.0f triangles: documented constants)\n", kProbeTriangleLimit);
  if (e.exact) {
    std::printf("  triangles (in the file):    %.0f\n", e.triangles);
    std::printf("  smallest altitude:          %.3g m\n", e.min_altitude);
  } else {
    std::printf("  triangles (estimate):       %.0f\n", e.triangles);
  }
  std::printf(
      "  peak memory (bound):        %.1f MiB at most, of %.1f MiB on this machine (256 MiB "
      "+ %.0f B per triangle + %.0f B per triangle per implicit field held + %.0f B per "
      "triangle for a direct counterpart's factor, x %.1f margin)\n",
      kMemoryMargin * peak_bytes(scene, e) / 1048576.0, machine_bytes() / 1048576.0,
      kBytesPerTriangle, kBytesPerAlphaTriangle, counterpart_bytes_per_triangle(scene),
      kMemoryMargin);
  print_step_counts(scene);
  std::printf(
      "  run time (bound):           %.0f s at most on %d idle thread%s (measured throughput "
      "of the 2-core development machine: 6-11 M triangle-steps/s per thread, 12 us per "
      "triangle per alpha, 10 ms + 8 us per triangle per stage; x %.1f margin)\n",
      kTimeMargin * run_seconds(scene, e, threads), threads, threads == 1 ? "" : "s", kTimeMargin);
  std::printf("  stable time step (approx):  %.3g s on true masses (from the smallest altitude)\n",
              dt);
}

// A warning on stderr as it is found, kept for the verdict at the end.
void warn(std::vector<std::string>& said, const std::string& line) {
  std::fprintf(stderr, "warning: %s\n", line.c_str());
  said.push_back(line);
}

// The rock set against real rock's ranges (h / l_ch is warned of above).
void print_plausibility(const RockPlausibilityFigures& p, std::vector<std::string>& said) {
  if (!p.ucs_Pa) return;
  std::printf("  rock set:                   UCS %.3g MPa (Mohr-Coulomb of c, phi)",
              *p.ucs_Pa / 1e6);
  for (const PlausibilityFigure& f : p.figures)
    if (f.name != "h_over_l_ch") std::printf(", %s %.3g", f.name.c_str(), f.value);
  std::printf("\n");
  for (const std::string& line : plausibility_warnings(p, false)) warn(said, line);
}

// With materials.rock.gsi: the rock mass the run will use, derived from the
// laboratory set (rock_mass.hpp), so that the step is seen before a run.
void print_rock_mass(const Scene& scene) {
  if (!scene.rock_mass) return;
  const RockMassSpec& r = *scene.rock_mass;
  const RockMassFigures& m = r.mass;
  std::printf(
      "  rock mass (GSI %g, mi %g, D %g): E %.3g GPa, c %.3g MPa, phi %.3g deg, ft %.3g MPa, "
      "UCS %.3g MPa (Mohr-Coulomb), sigma_cm %.3g MPa; from the lab's E %.3g GPa, UCS %.3g MPa\n",
      r.gsi, r.mi, r.disturbance, m.young / 1e9, m.cohesion / 1e6, m.friction_angle,
      m.tensile_strength / 1e6, mohr_coulomb_ucs(m.cohesion, m.friction_angle) / 1e6,
      m.sigma_cm / 1e6, r.intact.young / 1e9, r.intact.ucs / 1e6);
  if (r.ft_over_ucs > 0)
    std::printf(
        "  rock mass's ft:             %g of its UCS (materials.rock.mass_ft_over_ucs; "
        "Hoek-Brown's s sigma_ci / mb: %.3g MPa)\n",
        r.ft_over_ucs, hoek_brown_tensile_strength(r.mass, r.intact.ucs) / 1e6);
}

// The last line: valid, or valid with what the warnings said.
void print_verdict(const std::vector<std::string>& said) {
  if (said.empty()) {
    std::printf("verdict: valid\n");
    return;
  }
  std::printf("verdict: valid, with %zu warning%s:\n", said.size(), said.size() == 1 ? "" : "s");
  for (const std::string& w : said) std::printf("  - %s\n", w.c_str());
}

}  // namespace

int command_check(const Scene& scene, const RunContext& ctx) {
  const Estimate e = estimate(scene);
  const double cp = p_wave_speed(scene.materials.at(mesh::kRock), scene.plane_stress);
  std::printf("scene %s: valid\n", scene.source.c_str());
  std::vector<std::string> said(scene.warnings);  // the input warnings, said on reading
  print_rock_mass(scene);
  if (e.exact) std::printf("  mesh from %s\n", scene.mesh.msh.path.c_str());
  // Crack elements: about 1.5 interior edges per triangle.
  std::printf("  crack elements (estimate):  %.0f\n", 1.5 * e.fracture_triangles);
  if (e.fracture_triangles > 0) {
    const Resolution r =
        e.fracture_h > 0 ? resolution_at(scene, e.fracture_h) : fracture_resolution(scene, nullptr);
    std::printf(
        "  fracture resolution:        h / l_ch = %.3g (h = %.3g m, l_ch = E GfI / "
        "ft^2 = %.3g m; limit %g)\n",
        r.ratio, r.h, r.l_ch, kResolutionLimit);
    if (r.ratio > kResolutionLimit) {
      char line[300];
      std::snprintf(line, sizeof line,
                    "the fracture zone's elements are %.2g times the rock's l_ch (limit %g): "
                    "crack pattern and displacements depend on the mesh; refine "
                    "mesh.size_near",
                    r.ratio, kResolutionLimit);
      warn(said, line);
    }
    print_plausibility(rock_plausibility(scene, r.ratio), said);
  }
  if (e.triangles <= kProbeTriangleLimit)
    print_probe(scene, probe_scene(scene, ctx), cp);
  else
    print_constants(scene, e, cp, ctx.threads);
  std::printf("  P-wave speed of rock:       %.1f m/s\n", cp);
  std::printf("  threads:                    %d\n", ctx.threads);
  print_verdict(said);
  return 0;
}

}  // namespace rockfdem::workflows
