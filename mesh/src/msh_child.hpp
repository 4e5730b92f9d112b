// Private: a user's .msh read by gmsh in a child process (msh_child.cpp).
// gmsh's reader is a third-party parser that malformed files can crash
// (memory errors no check of ours can catch once they happen); in a child,
// such a crash ends the child only, and the parent turns it into an
// InputError naming the file. The child sends the finished Mesh record
// back through a pipe in the binary form below; the parent trusts none of
// it until every count is within the file's limits and every index points
// at a vertex.
//
// The record (native byte order: both ends are one program on one machine):
//   u32 magic "RFMC", u32 version, u32 kind
//   kind 0 (a mesh): u64 vertices, u64 triangles, u64 edges, then
//     f64 x[vertices], f64 y[vertices], i32 triangles[3 * triangles],
//     i32 zone[triangles], u8 fracture[triangles], i32 edges[3 * edges]
//     (a, b, tag): the tagged edges, then the joint edges with tag
//     -1 - trace (edge tags are never negative)
//   other kinds (an error: 1 InputError, 2 runtime_error, 3 logic_error,
//     4 bad_alloc, 5 any other exception): u64 length, then the message
//   and nothing after the last field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>

#include "rockfdem/mesh/mesh.hpp"

namespace rockfdem::mesh::detail {

/// What a record from the child may hold: counts within what a file of
/// `file_bytes` bytes can describe and zones among those the reader maps.
struct RecordLimits {
  std::uint64_t file_bytes = 0;  ///< sets the child's time limit
  std::uint64_t vertices = 0;    ///< one per byte of the file
  std::uint64_t triangles = 0;   ///< one per byte of the file
  std::uint64_t edges = 0;       ///< 16 per byte (a line may be in several edge groups)
  std::uint64_t message_bytes = 65536;
  std::set<int> zones;  ///< empty: any
};

RecordLimits record_limits(std::uint64_t file_bytes, std::set<int> zones);

/// Encodes what the child's read gave (a Mesh, or the exception it threw).
std::string encode_mesh(const Mesh& m);
std::string encode_error(std::uint32_t kind, const std::string& message);

/// The parent's side: bytes in as they arrive, then the answer.
class RecordReceiver {
 public:
  explicit RecordReceiver(RecordLimits limits) : limits_(std::move(limits)) {}

  /// Takes the next bytes. Returns why the record cannot be valid (a count
  /// beyond the limits, more bytes than it declared) as soon as it is known.
  std::optional<std::string> take(const char* data, std::size_t n);

  /// After the last byte: the mesh (kind 0), or the child's error (kind and
  /// message), or why the record is incomplete or implausible (`problem`).
  struct Answer {
    std::uint32_t kind = 0;
    Mesh mesh;
    std::string message;
    std::string problem;  ///< non-empty: no usable answer
  };
  Answer finish();

  std::size_t received() const { return buffer_.size(); }

 private:
  std::optional<std::string> check_header();
  RecordLimits limits_;
  std::string buffer_;
  std::uint64_t expected_ = 0;  ///< whole record's bytes, once the header is in
};

/// The time a child may take for a file of `file_bytes` bytes:
/// 60 s + 4 s per MiB (reads and their checks ran at 7-12 MB/s on a
/// shared 2-core VM: 2.8 s for 21 MB, whose limit is 140 s).
double child_time_limit_s(std::uint64_t file_bytes);

/// The memory a child may take beyond what it maps at the fork: 1 GiB +
/// 32 bytes per byte of the file (its address space is limited to that
/// sum, RLIMIT_AS). gmsh's model of a valid file takes a few bytes per
/// byte of it; a count forged in a file asks for far more.
std::uint64_t child_memory_budget(std::uint64_t file_bytes);

/// Runs read() in a forked child and returns its Mesh. Errors read() throws
/// come back as the same type and message, but running out of memory (the
/// child's budget) is an InputError naming `path`. A child that dies by a signal,
/// exits without a whole record, sends an implausible one or runs past
/// child_time_limit_s (then killed) is an InputError naming `path`.
/// Failing to start the child (fork, pipe) is a std::runtime_error.
Mesh read_in_child(const std::string& path, const RecordLimits& limits,
                   const std::function<Mesh()>& read);

}  // namespace rockfdem::mesh::detail
