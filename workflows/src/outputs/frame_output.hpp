// The ParaView frames of a tunnel run: fdem_NNNN.vtu at each output step,
// listed in fdem.pvd, with the bolts' profiles as bolts_NNNN.vtp
// (docs/output-formats.md). Written only once the step passed the run's
// checks, so that the last frame is the last good state.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "outputs/bolt_results.hpp"
#include "outputs/output_step.hpp"
#include "record/summary.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"
#include "rockfdem/fdem/bolt_install.hpp"
#include "rockfdem/insitu/insitu.hpp"

namespace rockfdem::workflows {

class FrameOutput : public OutputStepObserver {
 public:
  /// Frames in `dir`, of the engine plus, with bolts, their axial stress
  /// and profiles (`bolts`, `bolt_results`: null without bolts); both
  /// outlive it.
  FrameOutput(std::string dir, const fdem::BoltPlan* bolts, BoltResults* bolt_results);
  /// The implicit part of the displacement the frames add (the hand-off
  /// field); it outlives the frames.
  void set_implicit(const insitu::InsituField& handoff) { implicit_ = &handoff; }
  /// fdem_NNNN.vtu (and bolts_NNNN.vtp), listed in the .pvd files.
  void at_output_step(const OutputStep& step, std::vector<double>& row) override;
  /// The frames written, for a checkpoint.
  nlohmann::json state() const;
  /// Puts state() back, copying the frames from `from_dir` when the restart
  /// writes to another directory (a missing one noted in `summary`).
  void restore(const nlohmann::json& state, const std::string& from_dir, RunRecord& summary);

 private:
  /// The engine grid plus, with bolts installed, "bolt_axial_stress" (steel
  /// stress along the axis per bolt triangle, NaN elsewhere).
  coupling::VtkGrid grid(const fdem::Engine& e, const mesh::Mesh& m) const;
  std::string dir_;
  const insitu::InsituField* implicit_ = nullptr;
  const fdem::BoltPlan* bolts_;
  BoltResults* bolt_results_;
  coupling::PvdCollection pvd_;
  int frame_ = 0;
};

}  // namespace rockfdem::workflows
