// Reading a small record the program wrote itself (an output folder's owner
// record, a study variant's record) from a folder anyone may have changed
// since: a FIFO must not block the read, a device (/dev/zero) must not grow
// memory without bound, and a deeply nested JSON value must not reach code
// that recurses on it.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

namespace rockfdem::workflows {

/// What read_small_file found at a path.
struct SmallFile {
  enum class Kind { kMissing, kText, kRefused } kind = Kind::kMissing;
  std::string text;  ///< the whole file (kText)
  std::string why;   ///< kRefused: what the path is, "a FIFO, not a regular file", ...
};

/// The whole of `path` when it is a regular file of at most `max_bytes`
/// (the path stat()ed before it is opened; the open O_NONBLOCK and fstat()ed
/// after it; at most max_bytes + 1 bytes read). Time and memory O(max_bytes).
SmallFile read_small_file(const std::string& path, std::size_t max_bytes);

/// `text` parsed as JSON, or null (discarded) when it is not JSON or nests
/// deeper than `max_depth` levels (the parse stops at the first level
/// beyond it).
nlohmann::json parse_shallow_json(const std::string& text, int max_depth);

}  // namespace rockfdem::workflows
