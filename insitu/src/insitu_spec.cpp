// Checks of an InsituSpec against the mesh it is to be solved on, and the
// timing table. Every message names the key, the value, and what to change:
// workflows/ turns an InputError into exit code 2 with this text.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "rockfdem/error.hpp"
#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::insitu {

namespace {

[[noreturn]] void fail(const std::string& what) { throw InputError("insitu: " + what); }

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void check_material(const std::optional<ElasticMaterial>& m, const char* key, const char* why) {
  if (!m) fail(std::string("no material for ") + why + ": set materials." + key + " (E, nu)");
  if (!(m->E > 0) || !std::isfinite(m->E))
    fail(std::string("materials.") + key + ".E = " + num(m->E) + " Pa: must be > 0");
  if (!(m->nu > -1 && m->nu < 0.5))
    fail(std::string("materials.") + key + ".nu = " + num(m->nu) +
         ": must lie in (-1, 0.5) for plane strain");
}

}  // namespace

void validate(const mesh::Mesh& mesh, const InsituSpec& spec) {
  // 1. The mesh record itself: sizes, indices, zones, orientation.
  const std::size_t n_v = mesh.n_vertices(), n_t = mesh.n_triangles();
  if (n_t == 0) fail("the mesh has no triangles");
  if (mesh.y.size() != n_v) fail("mesh.x and mesh.y differ in length");
  if (mesh.zone.size() != n_t)
    fail("mesh.zone has " + std::to_string(mesh.zone.size()) + " entries for " +
         std::to_string(n_t) + " triangles");
  bool has_zone[4] = {false, false, false, false};
  for (std::size_t t = 0; t < n_t; ++t) {
    const auto& tri = mesh.triangles[t];
    for (const int v : tri)
      if (v < 0 || static_cast<std::size_t>(v) >= n_v)
        fail("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
             " (the mesh has " + std::to_string(n_v) + ")");
    const int z = mesh.zone[t];
    if (z < mesh::kRock || z > mesh::kLining)
      fail("triangle " + std::to_string(t) + " has zone " + std::to_string(z) +
           ": expected 1 (rock), 2 (core) or 3 (lining)");
    has_zone[z] = true;
    const double area2 = (mesh.x[tri[1]] - mesh.x[tri[0]]) * (mesh.y[tri[2]] - mesh.y[tri[0]]) -
                         (mesh.x[tri[2]] - mesh.x[tri[0]]) * (mesh.y[tri[1]] - mesh.y[tri[0]]);
    if (!(area2 > 0))
      fail("triangle " + std::to_string(t) + " is not counter-clockwise (signed area " +
           num(0.5 * area2) + "): fix the mesh generator");
  }

  // 2. Far field: compression is required everywhere in the model.
  const FarField& ff = spec.far_field;
  if (!(ff.sH > 0) || !std::isfinite(ff.sH))
    fail("far_field.sH = " + num(ff.sH) + " Pa: must be a compression > 0");
  if (!(ff.sV > 0) || !std::isfinite(ff.sV))
    fail("far_field.sV = " + num(ff.sV) + " Pa: must be a compression > 0");
  if (ff.sZ && (!(*ff.sZ > 0) || !std::isfinite(*ff.sZ)))
    fail("far_field.sZ = " + num(*ff.sZ) + " Pa: must be a compression > 0 (or left unset)");
  if (!std::isfinite(ff.angle_deg)) fail("far_field.angle_deg is not a number");

  const Gravity& g = spec.gravity;
  if (!(g.unit_weight >= 0) || !std::isfinite(g.unit_weight))
    fail("gravity.unit_weight = " + num(g.unit_weight) + " N/m^3: must be >= 0");
  if (g.unit_weight > 0) {
    if (ff.angle_deg != 0)
      fail(
          "gravity needs vertical principal stresses: set far_field.angle_deg = 0 or "
          "gravity.unit_weight = 0");
    if (spec.loading == BoundaryLoading::kKirschExact)
      fail(
          "gravity cannot be combined with exact Kirsch tractions (uniform far field "
          "only): set gravity.unit_weight = 0");
    double y_top = mesh.y[0];
    for (const double y : mesh.y) y_top = std::max(y_top, y);
    const double dz = g.reference_y - y_top;  // negative above the reference
    const double sv_top = ff.sV + g.unit_weight * dz;
    const double sh_top = ff.sH + ff.sH / ff.sV * g.unit_weight * dz;
    if (!(sv_top > 0) || !(sh_top > 0))
      fail("with gravity the stress at the top of the model (y = " + num(y_top) +
           ") is sV = " + num(sv_top) + ", sH = " + num(sh_top) +
           " Pa: compression is required everywhere; raise far_field.sV or lower "
           "gravity.reference_y");
  }
  if (spec.loading == BoundaryLoading::kKirschExact && !(spec.kirsch_radius > 0))
    fail("kirsch_radius = " + num(spec.kirsch_radius) +
         " m: exact Kirsch tractions need the hole radius > 0");

  // 3. The softening sequence.
  if (spec.alphas.empty()) fail("alphas is empty: give at least one softening factor, e.g. [1]");
  for (std::size_t i = 0; i < spec.alphas.size(); ++i) {
    const double a = spec.alphas[i];
    if (!(a >= 0 && a <= 1))
      fail("alphas[" + std::to_string(i) + "] = " + num(a) + ": must lie in [0, 1]");
    if (i > 0 && !(a < spec.alphas[i - 1]))
      fail("alphas must be strictly decreasing: alphas[" + std::to_string(i - 1) +
           "] = " + num(spec.alphas[i - 1]) + ", alphas[" + std::to_string(i) + "] = " + num(a));
  }
  if (spec.lining.active && !(spec.lining.install_alpha >= 0 && spec.lining.install_alpha <= 1))
    fail("lining.install_alpha = " + num(spec.lining.install_alpha) + ": must lie in [0, 1]");

  // 4. Materials for every zone that takes part in some stage.
  const bool lining_installed_at_first =
      spec.lining.active && spec.alphas.front() <= spec.lining.install_alpha;
  if (has_zone[mesh::kRock]) check_material(spec.materials.rock, "rock", "the rock zone");
  if (has_zone[mesh::kCore]) check_material(spec.materials.core, "core", "the core zone");
  if (has_zone[mesh::kLining] && !lining_installed_at_first)
    check_material(spec.materials.core, "core",
                   "the lining ring before installation (it is ground to excavate)");
  if (spec.lining.active) {
    if (!has_zone[mesh::kLining])
      fail(
          "lining.active = true but the mesh has no lining ring: set "
          "tunnel.lining_thickness > 0 or lining.active = false");
    check_material(spec.materials.lining, "lining", "the installed lining");
  }
  if (!has_zone[mesh::kRock] && spec.alphas.back() == 0 && !spec.lining.active)
    fail(
        "everything would be removed at alpha = 0 (the mesh has no rock zone): "
        "the system is singular");

  // 5. The solver.
  if (!(spec.solver.tolerance > 0 && spec.solver.tolerance < 1))
    fail("solver.tolerance = " + num(spec.solver.tolerance) + ": must lie in (0, 1)");
  if (spec.solver.max_iterations < 1)
    fail("solver.max_iterations = " + std::to_string(spec.solver.max_iterations) +
         ": must be >= 1");
}

std::string timing_table(const std::vector<InsituField>& fields) {
  std::ostringstream os;
  char line[256];
  std::snprintf(line, sizeof line, "%8s %9s %9s %-26s %5s %9s %9s %9s %9s %9s %10s\n", "alpha",
                "cells", "dofs", "solver", "iter", "setup s", "assem s", "solve s", "of it amg",
                "total s", "unbalance");
  os << line;
  for (const auto& f : fields) {
    std::snprintf(line, sizeof line,
                  "%8.4g %9zu %9zu %-26s %5d %9.3f %9.3f %9.3f %9.3f %9.3f %10.2e\n", f.alpha,
                  f.n_cells, f.n_dofs,
                  (f.solver + (f.preconditioner_reused ? " (kept)" : "")).substr(0, 26).c_str(),
                  f.iterations, f.setup_seconds, f.assembly_seconds, f.solve_seconds,
                  f.preconditioner_seconds, f.total_seconds, f.unbalanced_ratio);
    os << line;
  }
  return os.str();
}

}  // namespace rockfdem::insitu
