// `rockfdem mesh SCENE -o DIR`: gmsh meshing alone; writes mesh.msh (for
// gmsh and reuse), mesh.vtu (zones and quality, for ParaView; unless
// output.vtk = false), preview.png (unless output.plots = false) and
// summary.json.
#include <iostream>

#include "commands/commands.hpp"
#include "commands/mesh_preview.hpp"
#include "record/output_dir.hpp"
#include "record/phase_timer.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/mesh_grid.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace rockfdem::workflows {

int command_mesh(const Scene& scene, const RunContext& ctx) {
  PhaseTimer timer;
  prepare_output_dir(ctx.output_dir, scene, ctx.force);
  RunRecord summary(scene, ctx.threads);
  mesh::MeshReport report;
  const mesh::Mesh m = keeping_threads(ctx, [&] { return mesh::build_mesh(scene.mesh, &report); });
  timer.stamp("mesh");

  mesh::write_msh(m, output_path(ctx.output_dir, "mesh.msh"));
  if (scene.output.vtk)
    coupling::write_vtu(coupling::mesh_grid(m), output_path(ctx.output_dir, "mesh.vtu"));
  if (scene.output.plots) write_mesh_preview(scene, m, ctx.output_dir, summary, ctx.quiet);
  timer.stamp("output");

  summary.record_mesh(m, report);
  summary.note_turned_off(scene.output, "mesh.vtu", true);
  summary.skipped.push_back("insitu, fdem: `rockfdem mesh` meshes only");
  summary.status = "completed";
  summary.set_timings(timer);
  summary.write(output_path(ctx.output_dir, "summary.json"));
  if (!ctx.quiet) {
    std::cout << "mesh: " << report.n_triangles << " triangles, " << report.n_vertices
              << " vertices, min altitude " << report.min_altitude << " m, min angle "
              << report.min_angle_deg << " deg, " << report.seconds << " s\n"
              << timer.table();
  }
  return 0;
}

}  // namespace rockfdem::workflows
