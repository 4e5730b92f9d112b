#include "checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "output_dir.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/fdem/bits_hash.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows {
namespace {

constexpr char kMagic[8] = {'R', 'F', 'D', 'M', 'C', 'K', 'P', 'T'};
constexpr const char* kPrefix = "checkpoint_";
constexpr const char* kSuffix = ".rfck";

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void put_block(std::string& out, const std::string& block) {
  put<std::uint64_t>(out, block.size());
  out += block;
}

// Reads from a byte buffer, naming the file and offset when it runs out.
class Reader {
 public:
  Reader(const std::string& path, const std::string& bytes, std::size_t end)
      : path_(path), bytes_(bytes), end_(end) {}
  template <class T>
  T get() {
    T value;
    need(sizeof value);
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string block() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string b = bytes_.substr(at_, n);
    at_ += n;
    return b;
  }

 private:
  void need(std::uint64_t n) const {
    if (n > end_ - at_)
      throw InputError("checkpoint " + path_ + ": truncated or corrupt at byte " +
                       std::to_string(at_) + "; use the previous checkpoint");
  }
  const std::string& path_;
  const std::string& bytes_;
  std::size_t end_;
  std::size_t at_ = 0;
};

// Checkpoints in `dir` (and temporary files of interrupted writes), oldest first.
void prune(const fs::path& dir, std::size_t keep) {
  std::vector<fs::path> done, temps;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(kPrefix, 0) == 0 && name.size() > std::strlen(kSuffix) &&
        name.compare(name.size() - std::strlen(kSuffix), std::string::npos, kSuffix) == 0)
      done.push_back(entry.path());
    else if (name.rfind(std::string(".") + kPrefix, 0) == 0)
      temps.push_back(entry.path());
  }
  std::sort(done.begin(), done.end());  // zero-padded step numbers sort in time
  for (std::size_t i = 0; i + keep < done.size(); ++i) fs::remove(done[i], ec);
  for (const fs::path& t : temps) fs::remove(t, ec);
}

}  // namespace

std::uint64_t scene_key(const Scene& scene) {
  return fdem::fnv1a(scene.restart_key.data(), scene.restart_key.size());
}

std::string write_checkpoint(const std::string& output_dir, long step, const Scene& scene,
                             const Checkpoint& checkpoint) {
  const fs::path dir = fs::path(output_dir) / "checkpoints";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());
  std::string bytes(kMagic, sizeof kMagic);
  put<std::uint32_t>(bytes, kCheckpointVersion);
  put<std::uint64_t>(bytes, scene_key(scene));
  put_block(bytes, checkpoint.run.dump());
  put_block(bytes, checkpoint.engine_state);
  put<std::uint64_t>(bytes, fdem::fnv1a(bytes.data(), bytes.size()));
  char name[64];
  std::snprintf(name, sizeof name, "%s%012ld%s", kPrefix, step, kSuffix);
  const std::string path = (dir / name).string();
  coupling::atomic_write_text(path, bytes);
  prune(dir, 2);
  return path;
}

Checkpoint read_checkpoint(const std::string& path, const Scene& scene) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("checkpoint " + path + ": cannot open the file");
  std::ostringstream all;
  all << in.rdbuf();
  const std::string bytes = all.str();
  const std::size_t header = sizeof kMagic + sizeof(std::uint32_t) + sizeof(std::uint64_t);
  if (bytes.size() < header + sizeof(std::uint64_t) ||
      std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError("checkpoint " + path + ": not a rockfdem checkpoint (no RFDMCKPT header)");
  std::uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof kMagic, sizeof version);
  if (version != kCheckpointVersion)
    throw InputError("checkpoint " + path + ": format version " + std::to_string(version) +
                     "; this build reads version " + std::to_string(kCheckpointVersion));
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof stored);
  if (stored != fdem::fnv1a(bytes.data(), body))
    throw InputError("checkpoint " + path + ": checksum mismatch (" +
                     std::to_string(bytes.size()) +
                     " bytes, truncated or corrupt); use the previous checkpoint");
  Reader r(path, bytes, body);
  r.get<std::uint64_t>();  // magic
  r.get<std::uint32_t>();  // version, checked above
  if (r.get<std::uint64_t>() != scene_key(scene))
    throw InputError("checkpoint " + path + ": written for another scene (or other --set "
                     "values); restart with the scene and overrides of the original run");
  Checkpoint c;
  try {
    c.run = nlohmann::json::parse(r.block());
  } catch (const nlohmann::json::exception& e) {
    throw InputError("checkpoint " + path + ": corrupt run state: " + e.what());
  }
  c.engine_state = r.block();
  return c;
}

}  // namespace rockfdem::workflows
