#include "study/register_study.hpp"

#include "commands/commands.hpp"
#include "study/study_commands.hpp"

namespace rockfdem::workflows::study {

void register_study_commands() {
  register_command("sweep", command_sweep);
  register_command("calibrate", command_calibrate);
}

}  // namespace rockfdem::workflows::study
