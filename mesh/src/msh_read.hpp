// Private: the two halves of read_msh (msh_read.cpp). The checks before
// gmsh run in the calling process; the read with gmsh and the checks of
// what it read run where they are called: in a child process for
// read_msh (msh_child.hpp), here for the fuzzer and the tests that compare
// the two.
#pragma once

#include <cstdint>

#include "rockfdem/mesh/mesh.hpp"
#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh::detail {

/// The bounded checks before gmsh reads a byte (a regular file, its start
/// and end, its size against its declared counts, counts beyond the file,
/// tags beyond int). Returns the file's size; throws InputError.
std::uint64_t check_before_gmsh(const MshFileSpec& spec);

/// gmsh::open in a session of its own, then every check of what it read,
/// in this process. Call check_before_gmsh first.
Mesh read_with_gmsh(const MshFileSpec& spec);

/// Both in this process: read_msh without the child (a crash in gmsh's
/// reader ends this process).
Mesh read_msh_in_process(const MshFileSpec& spec);

}  // namespace rockfdem::mesh::detail
