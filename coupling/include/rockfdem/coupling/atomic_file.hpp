// Atomic file output: a reader (ParaView, a script, a CI check) either sees
// the previous complete file or the new complete file, never a half-written
// one, even when a run is killed mid-write.
//
// The recipe: write a temporary file in the *same* directory (rename is only
// atomic within one file system), flush and fsync it, then rename it over
// the target. On any failure the temporary file is removed.
#pragma once

#include <string>

namespace rockfdem::coupling {

/// Writes `content` to `path` atomically.
/// @throws std::runtime_error naming `path` when it cannot be written
///         (missing directory, no permission, disk full).
void atomic_write_text(const std::string& path, const std::string& content);

/// For writers that insist on opening a file name themselves (VTK writers):
/// hands out a temporary name beside the target, and on commit() fsyncs it
/// and renames it over the target. If commit() is never reached (an
/// exception, an early return) the destructor removes the temporary file.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// The temporary file to write: "<dir>/.<name>.tmp-<pid>-<n><ext>". It keeps the
  /// target's extension because some writers choose the format from it.
  const std::string& temp_path() const { return temp_path_; }
  const std::string& path() const { return path_; }

  /// fsync the temporary file and rename it onto path().
  /// @throws std::runtime_error naming path() on failure (temp file removed).
  void commit();

 private:
  std::string path_;
  std::string temp_path_;
  bool committed_ = false;
};

}  // namespace rockfdem::coupling
