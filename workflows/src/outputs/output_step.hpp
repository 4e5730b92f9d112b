// The outputs that act at each output step (bolts.csv, the instruments'
// readings, the lining's forces, the ParaView frames) and the one interface
// through which the run's outputs call them. The time loop
// (run/stage_runner.cpp) drives an output step: history.csv's row with the
// files of the outputs that add to it, then its checks, then the frames
// (outputs/run_outputs.hpp).
#pragma once

#include <string>
#include <vector>

#include "outputs/material_point.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

/// The run at one output step, as the outputs read it.
struct OutputStep {
  const fdem::Engine& engine;
  const mesh::Mesh& mesh;
  const std::string& stage;   ///< the stage's kind; "handoff" for the hand-off step
  int stage_index;            ///< history.csv's stage column (summary history_stages)
  const NodeDisplacement& u;  ///< node displacement from the in-situ state [m]
};

class OutputStepObserver {
 public:
  virtual ~OutputStepObserver() = default;
  /// history.csv's columns this output adds after the run's own; none by default.
  virtual std::vector<std::string> history_columns() const { return {}; }
  /// Writes what this output writes at the step and appends the values of
  /// its history_columns() to `row`.
  virtual void at_output_step(const OutputStep& step, std::vector<double>& row) = 0;
};

}  // namespace rockfdem::workflows
