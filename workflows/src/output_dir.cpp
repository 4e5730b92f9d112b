#include "output_dir.hpp"

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows {
namespace {

constexpr const char* kOwnerFile = ".rockfdem-scene";

std::string owner_record(const Scene& scene) {
  std::ostringstream out;
  out << scene.source << '\n' << std::hex << std::hash<std::string>{}(scene.canonical) << '\n';
  return out.str();
}

}  // namespace

std::string output_path(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

void prepare_output_dir(const std::string& dir, const Scene& scene, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError("output directory " + dir + ": exists and is not a directory");
  const std::string owner = output_path(dir, kOwnerFile);
  if (fs::exists(owner, ec) && !force) {
    std::ifstream in(owner);
    std::stringstream held;
    held << in.rdbuf();
    if (held.str() != owner_record(scene))
      throw InputError("output directory " + dir + ": holds results of another scene (" +
                       held.str().substr(0, held.str().find('\n')) +
                       "); choose another -o or pass --force to overwrite");
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError("output directory " + dir + ": cannot create: " + ec.message());
  coupling::atomic_write_text(owner, owner_record(scene));
}

}  // namespace rockfdem::workflows
