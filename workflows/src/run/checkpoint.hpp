// Checkpoint files of a run (tunnel or specimen): `rockfdem run --checkpoint-every N`
// writes OUTDIR/checkpoints/checkpoint_<step>.rfck, keeping the newest two;
// `rockfdem run --restart FILE` continues from one.
//
// Layout (native byte order; a checkpoint is read back on the machine kind
// that wrote it):
//   "RFDMCKPT"  u32 format version  u64 scene key (FNV-1a of the scene
//   without output.checkpoint_every)  u64 n + n bytes: the run's state as
//   JSON (the stage cursor, history rows and frames; tunnels: bolt
//   installation; specimens: the platen's peak and stop state)
//   u64 n + n bytes: Engine::save_state()  u64 FNV-1a of everything before
// (fdem::fnv1a: FNV-1a 64 with the offset basis 1469598103934665603, not
// the standard 14695981039346656037; see docs/reliability.md)
//
// Written atomically (temp file, fsync, rename): a run killed while writing
// leaves the previous checkpoints intact.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "record/run_context.hpp"

namespace rockfdem::workflows {

struct Scene;

struct Checkpoint {
  nlohmann::json run;        ///< the workflow's state (stage_runner, run_outputs)
  std::string engine_state;  ///< Engine::save_state() bytes
};

/// 2: stage numbers (history.csv's stage column, the stage reports' "stage").
constexpr std::uint32_t kCheckpointVersion = 2;

/// FNV-1a 64 of the scene's canonical text (the key a checkpoint records).
std::uint64_t scene_key(const Scene& scene);

/// Writes OUTDIR/checkpoints/checkpoint_<step>.rfck and removes all but the
/// newest two (and temporary files of an interrupted write). Returns the path.
std::string write_checkpoint(const std::string& output_dir, long step, const Scene& scene,
                             const Checkpoint& checkpoint);

/// Reads and verifies a checkpoint written for `scene`. Throws InputError
/// naming the file for a missing file, anything but a regular file (FIFO,
/// device, directory: refused before it is opened for reading), a header
/// whose declared sizes do not add up to the file's size (refused before
/// the body is read), a bad checksum, another format version or another
/// scene, and a run state that validate_run_state() refuses.
Checkpoint read_checkpoint(const std::string& path, const Scene& scene);

/// Checks that `run` has every field the restart reads with its type: for
/// every run (StageRunner::restore and verdict()) a stage index within
/// `scene`'s stages; for a tunnel (run.cpp, RunOutputs::restore) its
/// outputs and bolts; for a specimen (SpecimenOutputs::restore,
/// PlatenLoad::restore) its history and peak; frame names
/// that are plain file names. Throws InputError naming the checkpoint
/// `path` and the field.
void validate_run_state(const std::string& path, const nlohmann::json& run, const Scene& scene);

/// Checks the run state's steps and times against the engine state saved
/// with it (its step count `step` and simulated time `time`, after
/// Engine::load_state): the checkpoint's step, the current stage's first
/// step and start time, history rows in step order up to `step`, a
/// specimen's peak step. Throws InputError naming the checkpoint `path`
/// and the field.
void check_run_state_against_engine(const std::string& path, const nlohmann::json& run,
                                    const Scene& scene, long step, double time);

}  // namespace rockfdem::workflows
