#include "record/small_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rockfdem::workflows {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

SmallFile refused(std::string why) {
  SmallFile f;
  f.kind = SmallFile::Kind::kRefused;
  f.why = std::move(why);
  return f;
}

// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

SmallFile read_small_file(const std::string& path, std::size_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return errno == ENOENT ? SmallFile{}
                           : refused(std::string("cannot be read (") + std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode)) return refused("is " + kind_of(st.st_mode) + ", not a regular file");
  const Fd file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) return refused(std::string("cannot be opened (") + std::strerror(errno) + ")");
  if (::fstat(file.fd, &st) != 0 || !S_ISREG(st.st_mode))
    return refused("is not a regular file (it changed while being opened)");
  if (std::uintmax_t(st.st_size) > max_bytes)
    return refused("has " + std::to_string(st.st_size) + " bytes, more than the " +
                   std::to_string(max_bytes) + " such a record can hold");
  SmallFile f;
  f.kind = SmallFile::Kind::kText;
  f.text.resize(max_bytes + 1);
  std::size_t have = 0;
  while (have < f.text.size()) {
    const ssize_t got = ::read(file.fd, &f.text[have], f.text.size() - have);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    have += std::size_t(got);
  }
  if (have > max_bytes)
    return refused("grew beyond the " + std::to_string(max_bytes) +
                   " bytes such a record can hold while being read");
  f.text.resize(have);
  return f;
}

nlohmann::json parse_shallow_json(const std::string& text, int max_depth) {
  struct TooDeep {};
  try {
    return nlohmann::json::parse(
        text,
        [max_depth](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
          if (depth > max_depth) throw TooDeep{};
          return true;
        },
        false);
  } catch (const TooDeep&) {
    return nlohmann::json();
  }
}

}  // namespace rockfdem::workflows
