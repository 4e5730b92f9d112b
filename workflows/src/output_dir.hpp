// The output directory: created only after the scene is valid, never
// reused for another scene's results without --force.
#pragma once

#include <string>

namespace rockfdem::workflows {

struct Scene;

/// Creates `dir` (and parents) or checks that an existing one holds nothing
/// of another scene; records which scene owns it. Throws InputError.
void prepare_output_dir(const std::string& dir, const Scene& scene, bool force);

/// `dir` + "/" + `name`.
std::string output_path(const std::string& dir, const std::string& name);

}  // namespace rockfdem::workflows
