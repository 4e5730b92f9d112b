// One variant of a study run as `rockfdem run` runs it, in its own folder
// <out>/variants/<name>/, or taken from that folder when an earlier study
// finished it for the same scene and settings (resume).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "rockfdem/workflows/cli.hpp"
#include "study/study_variants.hpp"

namespace rockfdem::workflows::study {

struct VariantResult {
  std::string name;
  std::string status;   ///< the run's summary status; "failed" or "refused" when it stopped
  std::string message;  ///< why it failed or was refused
  double wall_s = 0;    ///< the run's wall time [s] (when it ran, also for a reused result)
  bool reused = false;  ///< taken from an earlier study's folder, not run now
  nlohmann::json figures = nlohmann::json::object();  ///< key_figures() of its summary

  nlohmann::json to_json() const;
  static VariantResult from_json(const nlohmann::json& j);
};

/// <out>/variants/<name>.
std::string variant_dir(const CommandLine& study, const Variant& v);

/// What makes two runs the same: the scene file's absolute path, a hash of
/// the validated scene text with every override applied (`scene`, loaded
/// with the study's and the variant's settings), and the settings.
nlohmann::json variant_identity(const Scene& scene, const Variant& v);

/// The finished result of identity `id` recorded in the variant's folder,
/// if there is one (marked reused).
std::optional<VariantResult> recorded_result(const CommandLine& study, const Variant& v,
                                             const nlohmann::json& id);

/// A study installs the interrupt handlers at its start and calls this
/// between its steps: a SIGINT or SIGTERM at any moment of a study ends it
/// (Interrupted: exit 130/143) at the next of these checks or inside the
/// variant's run, never later. A signal between two variants, or one that
/// came after a run's last check, would otherwise be lost. `when` says
/// where (e.g. "before variant NAME").
void stop_study_if_interrupted(const CommandLine& study, const std::string& when);

/// Runs the variant (-j threads of `study`, quietly, its folder claimed
/// with --force) unless its folder's variant.json records a finished run of
/// the same scene and settings (a finished status: completed,
/// not_at_equilibrium, unstable, failed or refused). Checks for a signal
/// first. A numerical failure or a refusal of the
/// variant's scene (an engine.dt this material cannot hold) is a result;
/// an interrupt and other errors propagate.
VariantResult run_variant(const CommandLine& study, const Variant& v);

}  // namespace rockfdem::workflows::study
