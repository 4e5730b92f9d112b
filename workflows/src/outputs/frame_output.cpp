#include "outputs/frame_output.hpp"

#include <cmath>
#include <cstdio>

#include "outputs/frame_restore.hpp"
#include "record/output_dir.hpp"
#include "rockfdem/coupling/fdem_model.hpp"
#include "rockfdem/fdem/bolt_output.hpp"

namespace rockfdem::workflows {

FrameOutput::FrameOutput(std::string dir, const fdem::BoltPlan* bolts, BoltResults* bolt_results)
    : dir_(std::move(dir)),
      bolts_(bolts),
      bolt_results_(bolt_results),
      pvd_(output_path(dir_, "fdem.pvd")) {}

void FrameOutput::at_output_step(const OutputStep& s, std::vector<double>&) {
  char name[32];
  std::snprintf(name, sizeof name, "fdem_%04d.vtu", frame_++);
  coupling::VtkGrid g = grid(s.engine, s.mesh);
  coupling::add_frame_info(g.field, s.stage, s.engine.step_count(), s.engine.time());
  coupling::write_vtu(g, output_path(dir_, name));
  pvd_.add(s.engine.time(), name);
  pvd_.write();
  std::snprintf(name, sizeof name, "bolts_%04d.vtp", frame_ - 1);
  if (bolt_results_) bolt_results_->write_frame(name, g.field);
}

coupling::VtkGrid FrameOutput::grid(const fdem::Engine& e, const mesh::Mesh& m) const {
  coupling::VtkGrid g = coupling::fdem_grid(e, m, implicit_);
  if (!bolts_ || bolts_->specs.empty()) return g;
  std::vector<double> stress(e.n_triangles(), std::nan(""));
  for (std::size_t b = 0; b < bolts_->specs.size(); ++b) {
    if (!bolts_->installed[b]) continue;
    for (const fdem::BoltSample& p : fdem::bolt_axial_profile(e, *bolts_, int(b)))
      stress[p.triangle] = p.steel_stress;
  }
  g.cell_arrays.push_back(coupling::triangle_cell_array(
      g, coupling::scalar_array("bolt_axial_stress", std::move(stress))));
  return g;
}

nlohmann::json FrameOutput::state() const { return frames_state(pvd_); }

void FrameOutput::restore(const nlohmann::json& state, const std::string& from_dir,
                          RunRecord& summary) {
  frame_ += restore_frames(state, from_dir, dir_, pvd_, summary);
}

}  // namespace rockfdem::workflows
