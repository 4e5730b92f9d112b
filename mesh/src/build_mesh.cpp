// build_mesh: one gmsh session per call. Build the OCC model for the spec's
// kind, set the sizes, mesh in 2D, extract the plain record, then mark the
// triangles where cracks may later open.
#include <gmsh.h>

#include <chrono>
#include <string>

#include "gmsh_model.hpp"
#include "gmsh_session.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/locality.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace rockfdem::mesh {
namespace {

void check_sizes(const MeshSpec& spec) {
  const MeshSizeSpec& s = spec.size;
  if (!(s.size_near > 0))
    throw InputError("mesh: size_near = " + std::to_string(s.size_near) + " must be > 0");
  if (spec.kind == ModelKind::kTunnel && !(s.size_far >= s.size_near))
    throw InputError("mesh: size_far = " + std::to_string(s.size_far) +
                     " must be >= size_near = " + std::to_string(s.size_near));
  if (s.grading_distance < 0)
    throw InputError("mesh: grading_distance must be >= 0 (0: automatic)");
  if (spec.tunnel.fracture_zone < 0) throw InputError("tunnel: fracture_zone must be >= 0");
}

detail::GmshModelMap add_model(const MeshSpec& spec, const std::vector<JointTrace>& joints) {
  switch (spec.kind) {
    case ModelKind::kTunnel: {
      detail::GmshModelMap model = detail::add_tunnel_model(spec, joints);
      detail::set_tunnel_size_field(spec, model);
      return model;
    }
    case ModelKind::kUcs: {
      detail::GmshModelMap model = detail::add_ucs_model(spec.specimen);
      detail::set_uniform_size(spec.size.size_near, spec.size.algorithm);
      return model;
    }
    case ModelKind::kBrazilian: {
      detail::GmshModelMap model = detail::add_disc_model(spec.specimen);
      detail::set_uniform_size(spec.size.size_near, spec.size.algorithm);
      return model;
    }
    case ModelKind::kMshFile:
      break;
  }
  throw std::logic_error("add_model: not a geometry kind");
}

// Rock triangles whose centroid lies within the fracture-zone distance of
// the opening's exact outline. A flag per triangle needs no extra gmsh
// surface, so the mesh stays as conformal as it is.
void flag_fracture_zone(const TunnelSpec& t, Mesh& m) {
  if (t.fracture_zone <= 0) return;
  const Outline opening = tunnel_outline(t);
  for (std::size_t k = 0; k < m.triangles.size(); ++k) {
    if (m.zone[k] != kRock) continue;
    const auto& [a, b, c] = m.triangles[k];
    const double cx = (m.x[a] + m.x[b] + m.x[c]) / 3, cy = (m.y[a] + m.y[b] + m.y[c]) / 3;
    if (distance_to_outline(opening, cx, cy) <= t.fracture_zone) m.fracture[k] = 1;
  }
}

Mesh mesh_geometry(const MeshSpec& spec, const std::vector<JointTrace>& joints, int& threads_used) {
  detail::GmshSession session(spec.size.threads);
  threads_used = session.threads();
  Mesh m = detail::gmsh_guarded("meshing", detail::GmshFailure::kRuntime, [&] {
    gmsh::model::add("rockfdem");
    const detail::GmshModelMap model = add_model(spec, joints);
    gmsh::model::mesh::generate(2);
    return detail::extract_mesh(model);
  });
  if (m.triangles.empty()) throw std::runtime_error("meshing: gmsh produced no triangles");
  if (spec.kind == ModelKind::kTunnel)
    flag_fracture_zone(spec.tunnel, m);
  else
    m.fracture.assign(m.triangles.size(), 1);
  // gmsh's numbering scatters neighbours through the arrays; every later
  // stage works in the locality order (locality.hpp). A user's .msh keeps
  // its own numbering, so its triangle ids stay the file's.
  return with_triangle_order(m, locality_order(m));
}

}  // namespace

Mesh build_mesh(const MeshSpec& spec, MeshReport* report) {
  const auto start = std::chrono::steady_clock::now();
  int threads_used = 0;
  Mesh m;
  JointTraceReport joints;
  std::vector<JointTrace> traces;
  if (spec.kind == ModelKind::kMshFile) {
    m = read_msh(spec.msh);
    traces = traces_of_joint_edges(m, &joints);
  } else {
    check_sizes(spec);
    if (spec.kind == ModelKind::kTunnel && !spec.joints.empty())
      traces = prepare_joint_traces(spec, spec.joints, &joints);
    m = mesh_geometry(spec, traces, threads_used);
  }
  if (report) {
    const MeshQuality q = measure_quality(m);
    report->n_triangles = m.n_triangles();
    report->n_vertices = m.n_vertices();
    report->min_altitude = q.min_altitude;
    report->min_angle_deg = q.min_angle_deg;
    report->gmsh_threads = threads_used;
    report->joints = joints;
    report->joint_traces = traces;
    report->seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return m;
}

}  // namespace rockfdem::mesh
