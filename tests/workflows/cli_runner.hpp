// Runs the rockfdem binary as a user does, for the command-line tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "rockfdem/error.hpp"

namespace rockfdem::test {

/// The InputError message `f` throws; empty when it throws none.
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

inline bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

struct Result {
  int code = -1;
  std::string output;
};

/// `rockfdem ARGS` with stderr merged into the output; `prefix` runs it
/// through another command (`env -u DISPLAY`, `xvfb-run -a`).
inline Result run(const std::string& args, const std::string& prefix = "") {
  Result r;
  const std::string cmd = prefix + " " + std::string(ROCKFDEM_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// The scratch paths this process handed out, removed when it exits: a
/// test that fails before its own remove_all leaves nothing behind in the
/// temp directory. ROCKFDEM_KEEP_SCRATCH=1 keeps them to look at.
struct ScratchPaths {
  pid_t owner = getpid();  // a forked child leaves through _exit, but never removes
  std::vector<std::filesystem::path> paths;
  ~ScratchPaths() {
    if (getpid() != owner || std::getenv("ROCKFDEM_KEEP_SCRATCH") != nullptr) return;
    std::error_code ignored;
    for (const auto& p : paths) std::filesystem::remove_all(p, ignored);
  }
};

inline ScratchPaths& scratch_paths() {
  static ScratchPaths paths;
  return paths;
}

/// A fresh (absent) scratch path under the temp directory, unique per
/// process, removed at the latest when the process exits.
inline std::filesystem::path scratch(const std::string& name) {
  std::filesystem::path p = std::filesystem::temp_directory_path() /
                            ("rockfdem-cli-" + name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(p);
  scratch_paths().paths.push_back(p);
  return p;
}

inline nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The rows of a CSV file's text of numbers, its header line left out.
inline std::vector<std::vector<double>> numeric_rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
    rows.push_back(std::move(v));
  }
  return rows;
}

const std::string kTestDir = ROCKFDEM_TEST_DIR;
/// The seed tunnel, the shipped scene most tests vary with --set.
const std::string kSeedScene = std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/tunnel-seed.toml";
/// The seed tunnel handed over in one shot at alpha 0.01 (the former
/// default): its grout fires within the first steps, so short runs reach
/// every stage.
const std::string kOneShotScene =
    std::string(ROCKFDEM_SOURCE_DIR) + "/scenes/tunnel-seed-oneshot.toml";

/// A user's .msh scene: `dir`/mesh/mesh.msh meshed from restart_support.toml
/// (a circular tunnel with a lining ring and a fracture zone, 1.7k
/// triangles) and `dir`/scene.toml mapping its groups, with no [[stages]];
/// `extra` is appended to the scene. Returns the scene's path.
inline std::filesystem::path msh_scene(const std::filesystem::path& dir,
                                       const std::string& extra = "") {
  std::filesystem::create_directories(dir);
  const Result meshed =
      run("mesh " + kTestDir + "/restart_support.toml -q -o " + (dir / "mesh").string());
  if (meshed.code != 0) throw std::runtime_error("meshing failed: " + meshed.output);
  const std::filesystem::path scene = dir / "scene.toml";
  std::ofstream(scene) << R"([model]
kind = "msh"
[msh]
file = "mesh/mesh.msh"
zones = { rock = "rock", core = "core", lining = "lining" }
edges = { bottom = "bottom", right = "right", top = "top", left = "left", excavation = "excavation", lining_inner = "lining_inner" }
fracture_group = "fracture"
[materials.rock]
young = 3.0e9
poisson = 0.25
tensile_strength = 1.0e6
cohesion = 3.0e6
fracture_energy_I = 30.0
fracture_energy_II = 150.0
[materials.lining]
young = 5.0e8
poisson = 0.3
[insitu]
sigma_h = 18.2e6
sigma_v = 11.4e6
alpha = [1.0, 0.01]
[engine]
steps = 200
[output]
every_steps = 100
plots = false
)" << extra;
  return scene;
}

// Starts `rockfdem ARGS` without waiting; its output goes to `log`.
inline pid_t spawn(const std::string& args, const std::filesystem::path& log) {
  const std::string cmd =
      "exec " + std::string(ROCKFDEM_BINARY) + " " + args + " > " + log.string() + " 2>&1";
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

/// The exit code of a spawned run (128 + signal when a signal ended it).
inline int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// OUTDIR/checkpoints/checkpoint_*.rfck, oldest first.
inline std::vector<std::filesystem::path> checkpoints(const std::filesystem::path& run_dir) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(run_dir / "checkpoints", ec))
    if (e.path().extension() == ".rfck") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// The step a checkpoint's name holds: checkpoint_000000001200.rfck -> 1200.
inline long checkpoint_step(const std::filesystem::path& p) {
  const std::string name = p.stem().string();
  return std::stol(name.substr(name.find('_') + 1));
}

}  // namespace rockfdem::test
