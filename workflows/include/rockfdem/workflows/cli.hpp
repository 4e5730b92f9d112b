// The `rockfdem` command line (contract: README.md, "Command line"). Parsing is separate
// from running so tests can check both without spawning processes.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rockfdem::workflows {

/// `rockfdem sweep` and `rockfdem calibrate` (docs/studies.md); checked by
/// the commands, which name the flag in every refusal.
struct StudyOptions {
  std::vector<std::string> vary;     ///< sweep: KEY=V1,V2,... or KEY=LO:HI (with samples)
  long samples = 0;                  ///< sweep: Latin hypercube samples; 0: the product
  std::vector<std::string> targets;  ///< calibrate: NAME=VALUE (mm, MPa)
  std::vector<std::string> weights;  ///< calibrate: NAME=W
  std::vector<std::string> free;     ///< calibrate: KEY=LO:HI
  long max_evals = 60;               ///< calibrate: runs the optimiser may ask for
  std::string method = "bobyqa";     ///< calibrate: bobyqa or cobyla
  /// sweep and calibrate: runs per variant, over heterogeneity seeds 1..N
  std::optional<long> realisations;
};

struct CommandLine {
  std::string command;  ///< run, check, mesh, insitu, sweep, calibrate ("" with --help/--version)
  std::string scene;    ///< scene file, "-" for stdin; empty: the built-in default (run only)
  std::string output_dir = "rockfdem-out";
  int threads = 0;                     ///< 0: all cores; without -j: OMP_NUM_THREADS, else 0
  std::vector<std::string> overrides;  ///< --set section.key=value
  bool quiet = false;
  bool force = false;  ///< overwrite another scene's results in the output directory
  long checkpoint_every =
      -1;                 ///< steps between checkpoints; -1: the scene's output.checkpoint_every
  std::string restart;    ///< checkpoint to continue from; empty: start afresh
  bool force_dt = false;  ///< accept an engine.dt above the stability limit
  bool help = false;
  bool version = false;
  bool scene_reference = false;
  std::string help_text;
  StudyOptions study;
};

/// Parses argv; throws rockfdem::InputError on a bad option.
CommandLine parse_command_line(int argc, const char* const argv[]);

/// Runs a parsed command and returns the process exit code (0, 1, 2 or 3).
int run_command(const CommandLine& cli);

}  // namespace rockfdem::workflows
