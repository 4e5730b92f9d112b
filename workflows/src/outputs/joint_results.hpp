// Joints at the end of a tunnel run: summary.json's "joints" and joints.csv,
// the state of each meshed trace's crack elements.
#pragma once

#include <string>
#include <vector>

#include "record/support_figures.hpp"
#include "rockfdem/fdem/engine.hpp"
#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::workflows {

/// The joint elements' counts in all, and joints.csv at `csv_path`: one row
/// per meshed trace (`traces`, the mesh report's), 1-based as the VTK
/// files' `joint` array numbers them.
JointRecord joint_results(const fdem::Engine& e, const mesh::Mesh& m,
                          const std::vector<mesh::JointTrace>& traces, const std::string& csv_path);

}  // namespace rockfdem::workflows
