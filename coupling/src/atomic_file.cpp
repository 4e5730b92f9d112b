// Temp file + fsync + rename. See atomic_file.hpp for why.
#include "rockfdem/coupling/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "rockfdem/error.hpp"

namespace rockfdem::coupling {
namespace {

// What to do about the system's error `err`.
std::string remedy(int err) {
  if (err == ENOSPC || err == EDQUOT) return "free disk space there or choose another folder";
  return "check that the directory exists and is writable";
}

OutputError write_error(const std::string& path, const std::string& what, int err) {
  return OutputError("cannot write '" + path + "': " + what + ": " + std::strerror(err) + "; " +
                     remedy(err));
}

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// "dir/name.ext" -> "dir/.name.tmp-<pid>-<n>.ext": hidden, unique per process
// and call, same directory, same extension.
std::string temp_name(const std::string& path, unsigned n) {
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string file = path.substr(dir.size());
  const auto dot = file.find_last_of('.');
  const std::string stem = dot == std::string::npos || dot == 0 ? file : file.substr(0, dot);
  const std::string ext = stem.size() == file.size() ? "" : file.substr(dot);
  return dir + "." + stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n) + ext;
}

// Creates a fresh temporary file beside `path` (O_EXCL, so two writers never
// share one) with mode 0666 minus the umask, like an ordinary new file.
std::pair<int, std::string> create_temp(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = temp_name(path, counter++);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return {fd, std::move(name)};
    if (errno != EEXIST) throw write_error(path, "cannot create a temporary file", errno);
  }
  throw write_error(path, "no free temporary file name", EEXIST);
}

void write_all(int fd, const std::string& content, const std::string& path) {
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw write_error(path, "write failed", errno);
    data += n;
    left -= static_cast<std::size_t>(n);
  }
}

// The rename is only durable once the directory entry is on disk too.
// Best effort: some file systems refuse fsync on directories.
void sync_directory(const std::string& path) {
  const int dir = ::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;
  ::fsync(dir);
  ::close(dir);
}

// fsync then rename `temp` onto `path`; removes `temp` on failure.
void sync_and_rename(int fd, const std::string& temp, const std::string& path) {
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    std::remove(temp.c_str());
    throw write_error(path, "fsync failed", err);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    std::remove(temp.c_str());
    throw write_error(path, "close failed", err);
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    std::remove(temp.c_str());
    throw write_error(path, "rename failed", err);
  }
  sync_directory(path);
}

}  // namespace

void atomic_write_text(const std::string& path, const std::string& content) {
  auto [fd, temp] = create_temp(path);
  try {
    write_all(fd, content, path);
  } catch (...) {
    ::close(fd);
    std::remove(temp.c_str());
    throw;
  }
  sync_and_rename(fd, temp, path);
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  auto [fd, temp] = create_temp(path_);
  ::close(fd);  // the external writer opens the name itself
  temp_path_ = std::move(temp);
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::commit() {
  const int fd = ::open(temp_path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw write_error(path_, "temporary file vanished", errno);
  committed_ = true;  // sync_and_rename removes the temporary file itself on failure
  sync_and_rename(fd, temp_path_, path_);
}

}  // namespace rockfdem::coupling
