// `rockfdem insitu SCENE -o DIR`: mesh, then the implicit deal.II stage for
// every softening factor alpha. Writes insitu.vtu (the last alpha, the state
// handed to the explicit engine) and insitu.pvd + insitu_NN.vtu (every
// alpha) unless output.vtk = false, and, for a circular opening, the
// comparison with Kirsch: insitu_vs_analytic.csv and summary.json's
// insitu.kirsch_rel_l2.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands/commands.hpp"
#include "outputs/continuum_comparison.hpp"
#include "record/output_dir.hpp"
#include "record/phase_timer.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/coupling/insitu_grid.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/mesh/build.hpp"
#include "rockfdem/mesh/msh_io.hpp"
#include "run/engine_setup.hpp"
#include "run/implicit_check.hpp"

namespace rockfdem::workflows {
namespace {

std::string kirsch_csv(const insitu::KirschComparison& c) {
  std::ostringstream out;
  out.precision(10);
  out << "triangle,x,y,r,theta,srr,stt,srt,srr_exact,stt_exact,srt_exact\n";
  for (const insitu::KirschRow& r : c.rows)
    out << r.triangle << ',' << r.x << ',' << r.y << ',' << r.r << ',' << r.theta << ',' << r.srr
        << ',' << r.stt << ',' << r.srt << ',' << r.srr_exact << ',' << r.stt_exact << ','
        << r.srt_exact << '\n';
  return out.str();
}

void write_fields(const mesh::Mesh& m, const std::vector<insitu::InsituField>& fields,
                  const std::string& dir) {
  coupling::PvdCollection pvd(output_path(dir, "insitu.pvd"));
  for (std::size_t i = 0; i < fields.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "insitu_%02zu.vtu", i);
    coupling::write_vtu(coupling::insitu_grid(m, fields[i]), output_path(dir, name));
    // ParaView plays a series in increasing time: the deconfinement 1 - alpha
    // grows as the core softens (alpha itself is in each file's field data).
    pvd.add(1.0 - fields[i].alpha, name);
  }
  pvd.write();
  coupling::write_vtu(coupling::insitu_grid(m, fields.back()), output_path(dir, "insitu.vtu"));
}

// Each implicit stage's alpha, solver, size and timings.
std::vector<InsituSolveFigures> solves(const std::vector<insitu::InsituField>& fields) {
  std::vector<InsituSolveFigures> out;
  for (const insitu::InsituField& f : fields)
    out.push_back({f.alpha, f.solver, long(f.n_dofs), f.assembly_seconds, f.solve_seconds,
                   f.total_seconds, f.preconditioner_seconds, f.unbalanced_ratio});
  return out;
}

// The Kirsch comparison where the scene is a Kirsch case fully excavated,
// else a note of why it was skipped.
void compare_with_kirsch(const Scene& scene, const RunContext& ctx, const mesh::Mesh& m,
                         const insitu::InsituField& last, RunRecord& summary) {
  insitu::KirschCase k;
  if (!kirsch_case(scene, &k) || last.alpha != 0.0) {
    summary.skipped.push_back(
        "Kirsch comparison: needs a circular opening without lining, uniform stress "
        "and a last alpha of 0");
    return;
  }
  const insitu::KirschComparison c = insitu::compare_kirsch(m, last, k);
  summary.insitu.kirsch_rel_l2 = c.stress_rel_l2;
  summary.insitu.kirsch_wall_ur_rel_l2 = c.wall_ur_rel_l2;
  summary.insitu.kirsch_triangles = long(c.n_triangles);
  coupling::atomic_write_text(output_path(ctx.output_dir, "insitu_vs_analytic.csv"), kirsch_csv(c));
  if (!ctx.quiet)
    std::cout << "Kirsch: relative L2 stress error over a <= r <= 5a: " << c.stress_rel_l2 << " ("
              << c.n_triangles << " triangles); wall u_r error " << c.wall_ur_rel_l2 << '\n';
}

}  // namespace

int command_insitu(const Scene& scene, const RunContext& ctx) {
  PhaseTimer timer;
  if (scene.mesh.kind != mesh::ModelKind::kTunnel && scene.mesh.kind != mesh::ModelKind::kMshFile)
    throw InputError(scene.source +
                     ": key 'model.kind': `rockfdem insitu` needs a tunnel or a "
                     ".msh model; specimens have no in-situ stage");
  const insitu::InsituSpec spec = insitu_spec(scene);
  prepare_output_dir(ctx.output_dir, scene, ctx.force);
  RunRecord summary(scene, ctx.threads);

  mesh::MeshReport report;
  const mesh::Mesh m = keeping_threads(ctx, [&] { return mesh::build_mesh(scene.mesh, &report); });
  timer.stamp("mesh");
  const std::vector<insitu::InsituField> fields =
      keeping_threads(ctx, [&] { return insitu::solve_insitu(m, spec); });
  for (const insitu::InsituField& f : fields)
    check_implicit_field(scene, m, f.alpha, inverted_triangles(m, f));
  timer.stamp("insitu");

  mesh::write_msh(m, output_path(ctx.output_dir, "mesh.msh"));
  if (scene.output.vtk) write_fields(m, fields, ctx.output_dir);
  summary.note_turned_off(scene.output, "insitu.vtu, insitu.pvd, insitu_NN.vtu", false);
  summary.record_mesh(m, report);
  summary.record_insitu(fields);
  summary.insitu.stages = solves(fields);
  compare_with_kirsch(scene, ctx, m, fields.back(), summary);
  summary.skipped.push_back("fdem: `rockfdem insitu` runs the implicit stage only");
  summary.status = "completed";
  timer.stamp("output");
  summary.set_timings(timer);
  summary.write(output_path(ctx.output_dir, "summary.json"));
  if (!ctx.quiet) std::cout << insitu::timing_table(fields) << timer.table();
  return 0;
}

}  // namespace rockfdem::workflows
