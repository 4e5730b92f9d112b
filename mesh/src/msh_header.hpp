// Private: a look at an ASCII .msh file's own header (see msh_header.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace rockfdem::mesh::detail {

/// The node count the $Nodes section of an ASCII .msh declares; nullopt for
/// binary files or when the file has no readable $Nodes header.
std::optional<std::size_t> declared_node_count(const std::string& path);

/// Bytes read to tell a mesh file's start, and its end.
inline constexpr std::size_t kHeadBytes = 64;
inline constexpr std::size_t kTailBytes = 4096;
/// Bytes of a line kept by the header scans (the rest is skipped).
inline constexpr std::size_t kLineBytes = 4096;
/// An ASCII .msh holds at most kFixedBytes + kBytesPerItem x (the nodes and
/// elements its headers declare): a node line takes 30-80 bytes as gmsh
/// writes it, an element 20-60; sections beyond those (physical names,
/// entities, node data of a few components) fit the margin.
inline constexpr std::uint64_t kFixedBytes = 1 << 20;
inline constexpr std::uint64_t kBytesPerItem = 1024;

/// Whether the file starts as a gmsh mesh file does ("$MeshFormat", or
/// "$NOD" for MSH 1). gmsh::open reads any other text as a .geo script,
/// which can run shell commands (SystemCall): such files must never reach
/// it (found by tests/fuzz/fuzz_msh).
bool starts_as_msh(const std::string& path);

/// What follows the file's last section, from its last kTailBytes bytes:
/// nullopt when the last line but white space starts with "$End" (every
/// section of a .msh, text or binary, ends with such a line), else what
/// follows (text after a mesh: gmsh skips it, however long).
std::optional<std::string> text_after_last_section(const std::string& path, std::uint64_t size);

/// The nodes and elements the $Nodes and $Elements headers of an ASCII .msh
/// declare, together; nullopt for binary files or without both headers.
/// Reads lines up to the $Elements header, each kept to kLineBytes.
std::optional<std::uint64_t> declared_items(const std::string& path);

/// In an ASCII .msh, the first number in an $Elements or $Periodic section
/// that is negative or above 2147483647, as "line N: 'TEXT'"; nullopt when
/// there is none (or the file is binary). gmsh 4.8 looks node tags up as
/// int, so such a number crashes its reader (found by tests/fuzz/fuzz_msh).
std::optional<std::string> tag_out_of_int_range(const std::string& path);

/// In an ASCII .msh, the first count that the file cannot hold, as
/// "the $Nodes section declares 999999999999 nodes, but ...": a total in a
/// $Nodes, $Elements or $Entities header, or an MSH 4 block's count, above
/// what the bytes after it can hold (every node, element or entity takes at
/// least 2), or an MSH 4 total that is not the sum of its blocks' counts.
/// gmsh 4.8 allocates by the declared total before it reads a node (a huge
/// one ends in std::bad_alloc) and fills that allocation with whatever the
/// blocks hold (past its end when they hold more). nullopt when every count
/// fits. Binary files are scanned by binary_count_beyond_file.
std::optional<std::string> count_beyond_file(const std::string& path);

/// The same for a binary .msh (msh_binary_counts.cpp): MSH 2's text count
/// lines, MSH 4.1's binary totals and block counts, each against the bytes
/// after it at the size of the smallest record (a node: tag and three
/// coordinates). nullopt for text files and byte orders other than this
/// machine's (gmsh's reader answers those).
std::optional<std::string> binary_count_beyond_file(const std::string& path);

/// "WHERE declares N WHAT, but the BYTES bytes after it can hold at most
/// ..." when n items of at least per_item bytes do not fit in `bytes`.
std::optional<std::string> count_beyond(const std::string& where, std::uint64_t n,
                                        const std::string& what, std::uint64_t bytes,
                                        std::uint64_t per_item);

}  // namespace rockfdem::mesh::detail
