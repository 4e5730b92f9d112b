// A discrete fracture network from a CSV file of trace end points
// (joints.dfn_file): one trace per line, x0,y0,x1,y1 in m.
#pragma once

#include <string>
#include <vector>

#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::workflows {

/// Most traces a file may hold (each is a mesh line).
inline constexpr std::size_t kMaxDfnTraces = 100000;

/// Reads `path`. Lines starting with '#', blank lines and a first line of
/// names (before any trace) are skipped. Throws InputError naming the file, the line, the
/// value and what is allowed (`key` is the scene key that named the file).
std::vector<mesh::JointTrace> read_dfn_csv(const std::string& path, const std::string& key);

}  // namespace rockfdem::workflows
