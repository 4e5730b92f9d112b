// `rockfdem sweep` and `rockfdem calibrate` (docs/studies.md), signed up
// with the command line by register_study_commands().
#pragma once

#include "rockfdem/workflows/cli.hpp"
#include "rockfdem/workflows/scene.hpp"

namespace rockfdem::workflows::study {

int command_sweep(const Scene& scene, const CommandLine& cli);
int command_calibrate(const Scene& scene, const CommandLine& cli);

}  // namespace rockfdem::workflows::study
