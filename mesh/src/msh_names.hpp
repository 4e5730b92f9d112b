// Private: the physical-group names write_msh gives zones and edge tags, and
// that read_msh looks for when the caller names no groups.
#pragma once

#include <map>
#include <string>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/msh_io.hpp"

namespace rockfdem::mesh::detail {

inline const char* const kFractureGroup = "fracture";
/// The 1D group of joint edges, one curve per trace.
inline const char* const kJointGroup = "joints";

/// "rock" -> kRock, "core" -> kCore, "lining" -> kLining.
std::map<std::string, int> default_zone_groups();

}  // namespace rockfdem::mesh::detail
