#include "record/output_dir.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

#include "record/run_context.hpp"
#include "record/small_file.hpp"
#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/printable.hpp"
#include "rockfdem/workflows/scene.hpp"
#include "rockfdem/workflows/version.hpp"
#include "scene/scene_reader.hpp"

namespace fs = std::filesystem;

namespace rockfdem::workflows {
namespace {

constexpr const char* kOwnerFile = ".rockfdem-scene";
constexpr const char* kLockFile = ".rockfdem-lock";
constexpr std::size_t kMaxOwnerBytes = 64 * 1024;  // a written record: the scene's path and key

// An exclusive flock on DIR/.rockfdem-lock, held while the returned
// descriptor is open (the kernel releases it on any death, kill -9
// included), with the holder's PID in the file for the message.
int take_lock(const std::string& dir) {
  const std::string path = (fs::path(dir) / kLockFile).string();
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError("output directory " + dir + ": cannot create " + kLockFile);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {0};
    const ssize_t n = ::pread(fd, pid, sizeof pid - 1, 0);
    ::close(fd);
    std::string holder(pid, n > 0 ? std::size_t(n) : 0);
    holder.erase(
        std::remove_if(holder.begin(), holder.end(),
                       [](char c) { return !std::isdigit(static_cast<unsigned char>(c)); }),
        holder.end());
    throw InputError("output directory " + dir + ": in use by another rockfdem run (PID " +
                     (holder.empty() ? std::string("unknown") : holder) +
                     "); wait for it to end or choose another -o");
  }
  const std::string me = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, me.data(), me.size(), 0) < 0) {
    // The lock holds without the PID; the message then says "unknown".
  }
  return fd;
}

void refuse_if_not_directory(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError("output directory " + dir + ": exists and is not a directory");
}

// One run per folder, locked until the process ends. A second claim of
// the same folder by this process keeps the lock it has; a claim of
// another folder (the next run of a sweep) releases it.
void lock_output_dir(const std::string& dir) {
  static std::string held;
  static int held_fd = -1;
  std::error_code ec;
  if (!held.empty() && fs::equivalent(held, dir, ec)) return;
  const int fd = take_lock(dir);
  if (held_fd >= 0) ::close(held_fd);
  held = dir;  // fd stays open: the lock lasts until the process ends or claims another
  held_fd = fd;
}

// Folders that creating OUTDIR made only on the way: "-o 'a/../x'" makes
// `a` (as mkdir -p does) though nothing is written there. Removed when the
// process ends, if still empty (rmdir refuses otherwise).
std::vector<fs::path>& stray_folders() {
  static std::vector<fs::path> folders;
  static const bool registered = [] {
    std::atexit([] {
      std::error_code ec;
      for (auto it = folders.rbegin(); it != folders.rend(); ++it) fs::remove(*it, ec);
    });
    return true;
  }();
  (void)registered;
  return folders;
}

// Creates `dir` and its missing parents, noting the created folders that
// are not `dir` or one of its real ancestors.
void create_output_dir(const std::string& dir, std::error_code& ec) {
  std::vector<fs::path> missing;
  fs::path prefix;
  for (const fs::path& part : fs::path(dir)) {
    prefix /= part;
    std::error_code exists_ec;
    if (!fs::exists(prefix, exists_ec)) missing.push_back(prefix);
  }
  fs::create_directories(dir, ec);
  if (ec) return;
  std::error_code canon_ec;
  const fs::path target = fs::canonical(dir, canon_ec);
  for (const fs::path& made : missing) {
    const fs::path real = fs::canonical(made, canon_ec);
    if (canon_ec) continue;
    const auto mismatch = std::mismatch(real.begin(), real.end(), target.begin(), target.end());
    if (mismatch.first != real.end()) stray_folders().push_back(made);  // not on the way to dir
  }
}

void create_dir(const std::string& dir) {
  std::error_code ec;
  create_output_dir(dir, ec);
  if (ec) throw InputError("output directory " + dir + ": cannot create: " + ec.message());
}

// Every name a command writes into OUTDIR (workflow.md, "Monitors and
// results"); numbered files are matched by prefix, digits and suffix.
const char* const kFixedNames[] = {"summary.json",
                                   "scene.toml",
                                   "preview.png",
                                   "history.csv",
                                   "mesh.msh",
                                   "mesh.vtu",
                                   "insitu.vtu",
                                   "insitu.pvd",
                                   "insitu_vs_analytic.csv",
                                   "fdem.pvd",
                                   "fdem_vs_continuum.csv",
                                   "continuum_profiles.csv",
                                   "continuum.vtu",
                                   "continuum_profiles.png",
                                   "grouted_cracks.csv",
                                   "joints.csv",
                                   "joint_profile.csv",
                                   "bolts.csv",
                                   "bolts.pvd",
                                   "bolt_forces.png",
                                   "bolt_forces_history.png",
                                   "extensometers.png",
                                   "convergence.png",
                                   "chord_convergence.png",
                                   "broken.png",
                                   "ground_reaction.png",
                                   "final_mesh.png",
                                   "broken_zone.png",
                                   "stress_strain.png",
                                   "lining.csv",
                                   "lining_forces.png",
                                   "lining_capacity.png",
                                   "lining_history.png",
                                   "support_forces.png",
                                   "continuum_yield.png",
                                   "displacement.png",
                                   "sigma_max_compressive.png",
                                   "sigma_min_compressive.png",
                                   "sigma_max_tensile.png",
                                   "report.md"};

struct Numbered {
  const char *prefix, *suffix;
};
const Numbered kNumberedNames[] = {{"fdem_", ".vtu"},
                                   {"insitu_", ".vtu"},
                                   {"bolt_", ".csv"},
                                   {"bolts_", ".vtp"},
                                   {"lining_", ".csv"}};

bool all_digits(const std::string& s) {
  return !s.empty() &&
         std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
}

bool numbered(const std::string& name, const std::string& prefix, const std::string& suffix) {
  return name.size() > prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
         all_digits(name.substr(prefix.size(), name.size() - prefix.size() - suffix.size()));
}

bool is_final_output(const std::string& name) {
  for (const char* fixed : kFixedNames)
    if (name == fixed) return true;
  for (const Numbered& n : kNumberedNames)
    if (numbered(name, n.prefix, n.suffix)) return true;
  return false;
}

// ".history.tmp-<pid>-<n>.csv" (atomic_write) or ".mesh.msh.tmp<pid>.msh"
// (write_msh): what an interrupted write of an output leaves.
bool is_temporary_output(const std::string& name) {
  const auto tmp = name.find(".tmp", 1);
  const auto dot = name.find_last_of('.');
  if (name[0] != '.' || tmp == std::string::npos || dot <= tmp) return false;
  const std::string marks = name.substr(tmp + 4, dot - tmp - 4);
  if (!std::all_of(marks.begin(), marks.end(),
                   [](unsigned char c) { return c == '-' || std::isdigit(c) != 0; }))
    return false;
  const std::string stem = name.substr(1, tmp - 1);
  return is_final_output(stem) || is_final_output(stem + name.substr(dot));
}

bool is_checkpoint_file(const std::string& name) {
  return numbered(name, "checkpoint_", ".rfck") || name.rfind(".checkpoint_", 0) == 0;
}

// The scene file as one path however it was spelled (./x.toml, x.toml,
// /abs/x.toml), so that a restart or rerun of the same scene is not taken
// for another's; "default" stays as it is.
std::string scene_identity(const Scene& scene) {
  if (scene.source == "default" || scene.source == "<stdin>") return scene.source;
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(scene.source, ec), ec);
  return ec ? scene.source : p.string();
}

std::string owner_record(const Scene& scene) {
  std::ostringstream out;
  out << scene_identity(scene) << '\n'
      << std::hex << std::hash<std::string>{}(scene.canonical) << '\n';
  return out.str();
}

// DIR/scene.toml: the scene with its --set values applied, so that
// `rockfdem run DIR/scene.toml` repeats the run.
void write_scene_as_run(const std::string& dir, const Scene& scene) {
  // printable(): a file name or --set value holding a newline stays in its comment.
  const std::string source = scene.source == "default"
                                 ? "the built-in default (scenes/tunnel-seed.toml)"
                                 : detail::printable(scene.source);
  std::string head = "# The scene as rockfdem " + version_string() + " ran it: " + source;
  for (const std::string& set : scene.overrides) head += "\n#   --set " + detail::printable(set);
  coupling::atomic_write_text(output_path(dir, "scene.toml"), head + "\n\n" + scene.as_run);
}

}  // namespace

std::string output_path(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

bool is_rockfdem_output(const std::string& name) {
  return !name.empty() && (is_final_output(name) || is_temporary_output(name));
}

void remove_checkpoints(const std::string& dir) {
  const fs::path folder = fs::path(dir) / "checkpoints";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && is_checkpoint_file(entry.path().filename().string()))
      fs::remove(entry.path(), ec);
  if (fs::is_empty(folder, ec)) fs::remove(folder, ec);
}

void remove_stale_temporaries(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && is_temporary_output(entry.path().filename().string()))
      fs::remove(entry.path(), ec);
  for (const auto& entry : fs::directory_iterator(fs::path(dir) / "checkpoints", ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(ec) && name.rfind(".checkpoint_", 0) == 0)
      fs::remove(entry.path(), ec);
  }
}

void remove_previous_outputs(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && is_rockfdem_output(entry.path().filename().string()))
      fs::remove(entry.path(), ec);
  remove_checkpoints(dir);
}

std::string run_dir_of(const std::string& checkpoint) {
  const fs::path p = fs::absolute(checkpoint);
  return p.parent_path().parent_path().string();
}

bool same_directory(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

void lock_study_dir(const std::string& dir) {
  refuse_if_not_directory(dir);
  create_dir(dir);
  take_lock(dir);  // never closed: held until the process ends
}

bool prepare_output_dir(const std::string& dir, const Scene& scene, bool force,
                        bool keep_previous) {
  std::error_code ec;
  refuse_if_not_directory(dir);
  const std::string owner = output_path(dir, kOwnerFile);
  const bool claimed = fs::exists(fs::symlink_status(owner, ec));
  if (claimed && !force) {
    // The record this program writes is a line or two; anything else in
    // its place (a FIFO, a link to a device, a huge file) is refused
    // unread, never waited on or read whole.
    const SmallFile held = read_small_file(owner, kMaxOwnerBytes);
    if (held.kind == SmallFile::Kind::kRefused)
      throw InputError("output directory " + dir + ": its record of the scene " + owner + " " +
                       held.why + "; allowed: the file rockfdem wrote there (at most " +
                       std::to_string(kMaxOwnerBytes) +
                       " bytes); remove it, choose another -o or pass --force to overwrite");
    if (held.text != owner_record(scene))
      throw InputError(
          "output directory " + dir + ": holds results of another scene (" +
          printable(held.text.substr(0, std::min<std::size_t>(held.text.find('\n'), 200))) +
          "); choose another -o or pass --force to overwrite");
  }
  create_dir(dir);
  lock_output_dir(dir);
  // Held by this process now: a temporary file of an output is what a
  // killed run's write left (a restart into this folder keeps the outputs).
  if (claimed) remove_stale_temporaries(dir);
  // Frames or plots of a longer earlier run must not sit beside the new ones.
  if (force && claimed && !keep_previous) remove_previous_outputs(dir);
  coupling::atomic_write_text(owner, owner_record(scene));
  write_scene_as_run(dir, scene);
  return claimed;
}

void claim_output_dir(const Scene& scene, const RunContext& ctx, bool first_outputs) {
  const bool restart = !ctx.restart.empty();
  const bool continues_here = restart && same_directory(ctx.output_dir, run_dir_of(ctx.restart));
  const bool claimed = prepare_output_dir(ctx.output_dir, scene, ctx.force, continues_here);
  if (first_outputs && !restart && claimed) remove_checkpoints(ctx.output_dir);
}

}  // namespace rockfdem::workflows
