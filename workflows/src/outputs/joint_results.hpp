// Joints at the end of a tunnel run: summary.json's "joints", joints.csv
// (the state of each meshed trace's crack elements) and joint_profile.csv
// (each element's slip and opening along its trace).
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

/// joint_profile.csv's text: one row per joint crack element, by trace and
/// along it (distance of the element's midpoint from the trace's start),
/// with its mean slip and opening since the start [mm], its aperture (the
/// faces apart beyond contact) and its state (docs/output-formats.md).
std::string joint_profile_csv(const fdem::Engine& e, const mesh::Mesh& m,
                              const std::vector<mesh::JointTrace>& traces);

}  // namespace rockfdem::workflows
