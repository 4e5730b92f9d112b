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

#include "broken_zone.hpp"
#include "commands.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/outline.hpp"
#include "stage_inputs.hpp"

namespace rockfdem::workflows {
namespace {

struct Estimate {
  double triangles = 0;
  double fracture_triangles = 0;
  double min_altitude = 0;  ///< [m]; 0: not known before meshing
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
  const double grading = m.size.grading_distance > 0
                             ? m.size.grading_distance
                             : 0.5 * std::min(m.domain.width, m.domain.height);
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
      const double beyond = std::max(0.0, d - m.tunnel.fracture_zone);
      const double h =
          m.size.size_near + (m.size.size_far - m.size.size_near) * std::min(1.0, beyond / grading);
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
  const std::pair<int, const char*> sides[] = {{mesh::kBottom, "bottom"},
                                               {mesh::kRight, "right"},
                                               {mesh::kTop, "top"},
                                               {mesh::kLeft, "left"}};
  for (const auto& [tag, name] : sides)
    if (std::none_of(m.edges.begin(), m.edges.end(),
                     [tag = tag](const mesh::TaggedEdge& e) { return e.tag == tag; }))
      throw InputError(s.source + ": key 'msh.edges': no edge of " + s.mesh.msh.path +
                       " is tagged \"" + name +
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

// Peak memory of a run: the libraries' baseline plus, per triangle, the
// mesh and the implicit stage (measured 0.65 kB per triangle of peak RSS
// growth between 107k and 390k triangles, `rockfdem insitu`) and the engine
// (1100 B per triangle, below), with the implicit fields the outputs keep.
constexpr double kBaseBytes = 256.0 * 1048576;
constexpr double kBytesPerTriangle = 650 + 1100 + 250;

double peak_bytes(const Estimate& e) { return kBaseBytes + kBytesPerTriangle * e.triangles; }

double machine_bytes() { return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE)); }

// Explicit steps at most: the step caps of the stages (tunnels) or the
// specimen's step count.
double explicit_steps(const Scene& s) {
  const bool staged =
      s.mesh.kind == mesh::ModelKind::kTunnel || s.mesh.kind == mesh::ModelKind::kMshFile;
  if (!staged) return double(s.engine.steps);
  double n = s.stages.empty() ? 0 : 1;  // the hand-off step
  for (const StageSpec& st : s.stages) n += double(st.max_steps);
  return n;
}

// Serial engine throughput measured on the 2-core development machine
// (docs/benchmarks.md, "A vector kernel for the narrow phase"): 11 M
// triangle-steps/s for intact models (bench_ucs: 15 M), 8 M for a
// fracturing model with contact (the default tunnel: 10.4 M on one idle
// thread; a confined specimen after heavy fracture, every triangle
// fracturing: 5.3 M); 0.9 parallel efficiency at 2 threads; mesh and
// implicit stage about 90 us per triangle.
double run_seconds(const Scene& s, const Estimate& e, int threads) {
  const double serial = e.fracture_triangles > 0 && s.engine.contact ? 8e6 : 11e6;
  const double rate = serial * std::max(1, threads) * (threads > 1 ? 0.9 : 1.0);
  return 90e-6 * e.triangles + explicit_steps(s) * e.triangles / rate;
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
  const double need = peak_bytes(e), have = machine_bytes();
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

int command_check(const Scene& scene, const CommandLine& /*cli*/) {
  const Estimate e = estimate(scene);
  const MaterialSpec& rock = scene.materials.at("rock");
  const double cp = p_wave_speed(rock, scene.plane_stress);
  // A gmsh Frontal-Delaunay mesh's smallest altitude is about 0.3 of the
  // near size (measured: 0.095 m at 0.35 m); crack penalties p = f E stiffen
  // it further (dt ~ h sqrt(rho / p)). The engine computes the exact limit.
  const double h = e.min_altitude > 0 ? e.min_altitude : 0.3 * scene.mesh.size.size_near;
  double dt = h / cp;
  if (e.fracture_triangles > 0)
    dt = std::min(dt, h * std::sqrt(rock.density / (rock.penalty_factor * rock.young)));
  dt *= scene.engine.dt_safety;
  // Crack elements: about 1.5 interior edges per triangle. Memory: the
  // engine measured 640 B per triangle on the fracturing UCS and 830-1070 B
  // on the default tunnel (contact structures included): 1100 B bounds both.
  const double cracks = 1.5 * e.fracture_triangles;
  const double bytes = e.triangles * 1100;
  std::printf("scene %s: valid\n", scene.source.c_str());
  if (e.exact) {
    std::printf("  mesh from %s\n", scene.mesh.msh.path.c_str());
    std::printf("  triangles (in the file):    %.0f\n", e.triangles);
    std::printf("  smallest altitude:          %.3g m\n", e.min_altitude);
  } else {
    std::printf("  triangles (estimate):       %.0f\n", e.triangles);
  }
  std::printf("  crack elements (estimate):  %.0f\n", cracks);
  if (e.fracture_triangles > 0) {
    const Resolution r = fracture_resolution(scene, nullptr);
    std::printf(
        "  fracture resolution:        h / l_ch = %.3g (h = %.3g m, l_ch = E GfI / "
        "ft^2 = %.3g m; limit %g)\n",
        r.ratio, r.h, r.l_ch, kResolutionLimit);
    if (r.ratio > kResolutionLimit)
      std::fprintf(stderr,
                   "warning: the fracture zone's elements are %.2g times the rock's l_ch "
                   "(limit %g): crack pattern and displacements depend on the mesh; refine "
                   "mesh.size_near\n",
                   r.ratio, kResolutionLimit);
  }
  std::printf("  engine memory (estimate):   %.1f MiB\n", bytes / 1048576.0);
  std::printf("  peak memory (estimate):     %.1f MiB of %.1f MiB on this machine\n",
              peak_bytes(e) / 1048576.0, machine_bytes() / 1048576.0);
  std::printf("  explicit steps (at most):   %.0f\n", explicit_steps(scene));
  std::printf("  run time (estimate):        %.0f s at most on %d idle thread%s\n",
              run_seconds(scene, e, active_threads()), active_threads(),
              active_threads() == 1 ? "" : "s");
  std::printf("  P-wave speed of rock:       %.1f m/s\n", cp);
  std::printf("  stable time step (approx):  %.3g s%s\n", dt,
              scene.engine.mass_scaling ? " on true masses" : "");
  if (scene.engine.mass_scaling) {
    // Scaled to the least constrained node, among the coarsest triangles far
    // out, less the tunnel's local damping (0.8 unless set: 1 / sqrt(1.8))
    // and contact, which adds its frequency on top (1 / sqrt(2)).
    const double local = stage_damping(scene).local;
    const double contact = scene.engine.contact ? std::sqrt(0.5) : 1.0;
    const double target = scene.engine.mass_scaling_dt > 0 ? scene.engine.mass_scaling_dt
                                                           : 0.3 * scene.mesh.size.size_far / cp;
    const double scaled = scene.engine.dt_safety * target * contact / std::sqrt(1 + local);
    std::printf("  time step, mass-scaled:     %.3g s (quasi-static pseudo-time)\n",
                std::max(dt, scaled));
  }
  std::printf("  threads:                    %d\n", active_threads());
  return 0;
}

}  // namespace rockfdem::workflows
