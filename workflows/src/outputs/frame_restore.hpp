// A checkpoint's ParaView frames: the list a run state keeps, and putting
// them back into a restarted run's series.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "record/summary.hpp"
#include "rockfdem/coupling/vtk_writer.hpp"

namespace rockfdem::workflows {

/// A run state's frame list: [time, file name] per ParaView frame.
nlohmann::json frames_state(const coupling::PvdCollection& pvd);

/// Adds the frames of `frames` (frames_state) to `pvd` and rewrites it;
/// where `to_dir` is not `from_dir` (a restart into another -o) copies each
/// frame from there so the series stays whole, noting in the summary any
/// that is missing. Returns the number of frames.
int restore_frames(const nlohmann::json& frames, const std::string& from_dir,
                   const std::string& to_dir, coupling::PvdCollection& pvd, RunRecord& summary);

}  // namespace rockfdem::workflows
