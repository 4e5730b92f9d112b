#include "outputs/frame_restore.hpp"

#include <filesystem>
#include <system_error>

#include "record/output_dir.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows {

nlohmann::json frames_state(const coupling::PvdCollection& pvd) {
  nlohmann::json frames = nlohmann::json::array();
  for (const coupling::PvdEntry& f : pvd.entries()) frames.push_back({f.time, f.file});
  return frames;
}

int restore_frames(const nlohmann::json& frames, const std::string& from_dir,
                   const std::string& to_dir, coupling::PvdCollection& pvd, RunRecord& summary) {
  std::error_code same_ec;
  const bool same_dir = fs::equivalent(from_dir, to_dir, same_ec);
  int n = 0;
  for (const auto& f : frames) {
    const std::string name = f.at(1).get<std::string>();
    if (!same_dir) {
      // The earlier frames live beside the checkpoint's run; the series
      // stays whole only if they come along.
      std::error_code ec;
      fs::copy_file(output_path(from_dir, name), output_path(to_dir, name),
                    fs::copy_options::overwrite_existing, ec);
      if (ec)
        summary.skipped.push_back("frame " + name + " of the restarted run: not found in " +
                                  from_dir);
    }
    pvd.add(f.at(0).get<double>(), name);
    ++n;
  }
  if (n > 0) pvd.write();
  return n;
}

}  // namespace rockfdem::workflows
