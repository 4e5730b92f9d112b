// Private: a look at an ASCII .msh file's own header (see msh_header.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace rockfdem::mesh::detail {

/// The node count the $Nodes section of an ASCII .msh declares; nullopt for
/// binary files or when the file has no readable $Nodes header.
std::optional<std::size_t> declared_node_count(const std::string& path);

}  // namespace rockfdem::mesh::detail
