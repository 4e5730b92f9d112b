// The output directory: created only after the scene is valid, never
// reused for another scene's results without --force.
#pragma once

#include <string>

namespace rockfdem::workflows {

struct Scene;
struct RunContext;

/// Creates `dir` (and parents) or checks that an existing one holds nothing
/// of another scene; records which scene owns it. With `force` it may hold
/// another scene's results, and the outputs an earlier run wrote there
/// (known by name, remove_previous_outputs) are removed first, unless
/// `keep_previous` (a restart continuing the run in its own directory).
/// In a directory an earlier run claimed, the temporary files of its
/// outputs' writes (".fdem_0009.tmp-<pid>-<n>.vtu", a checkpoint's
/// "checkpoints/.checkpoint_...") are removed once the folder is locked,
/// always: whichever run wrote them was killed mid-write.
/// Only a directory an earlier run claimed (its owner record present) is
/// ever cleaned: a user's folder keeps every file, whatever its name.
/// Returns whether it was such a directory. Throws InputError.
bool prepare_output_dir(const std::string& dir, const Scene& scene, bool force,
                        bool keep_previous = false);

/// Makes (or claims) OUTDIR once the scene is accepted (prepare_output_dir):
/// --force clears an earlier run's outputs first, except where a restart
/// continues that run. With `first_outputs`, a fresh run (no restart) also
/// removes the checkpoints of the earlier run that had claimed the folder,
/// so that they do not mix with its own (a folder no run claimed keeps
/// whatever it holds). Throws InputError.
void claim_output_dir(const Scene& scene, const RunContext& ctx, bool first_outputs);

/// Creates a study's folder (sweep, calibrate) and locks it, as
/// prepare_output_dir locks a run's, until the process ends: a second study
/// into the same folder is refused (InputError naming the holder's PID).
/// The study's runs, in their own subfolders, take their own locks.
void lock_study_dir(const std::string& dir);

/// Whether `name` is a file rockfdem writes into an output directory
/// (summary.json, fdem_0003.vtu, bolt_02.csv, ..., or a temporary file of an
/// interrupted atomic write of one); nothing else is ever removed.
bool is_rockfdem_output(const std::string& name);

/// Removes every rockfdem output in `dir` (is_rockfdem_output) and the
/// checkpoints in `dir`/checkpoints; other files stay.
void remove_previous_outputs(const std::string& dir);

/// Removes `dir`/checkpoints/checkpoint_*.rfck (and interrupted writes of
/// them), then the folder if nothing else is in it.
void remove_checkpoints(const std::string& dir);

/// Removes the temporary files of interrupted writes of rockfdem outputs in
/// `dir` (is_rockfdem_output's temporary names) and of checkpoints in
/// `dir`/checkpoints. Only for a folder this process has locked.
void remove_stale_temporaries(const std::string& dir);

/// Whether two paths name the same existing directory.
bool same_directory(const std::string& a, const std::string& b);

/// The run directory a checkpoint belongs to: OUTDIR/checkpoints/FILE -> OUTDIR.
std::string run_dir_of(const std::string& checkpoint);

/// `dir` + "/" + `name`.
std::string output_path(const std::string& dir, const std::string& name);

}  // namespace rockfdem::workflows
