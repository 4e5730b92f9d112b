// Subcommands whose stages are being wired in (insitu, run).
#include <stdexcept>

#include "commands.hpp"

namespace rockfdem::workflows {

int command_insitu(const Scene&, const CommandLine&) {
  throw std::runtime_error("`rockfdem insitu` is not wired to the implicit stage yet");
}

int command_run(const Scene&, const CommandLine&) {
  throw std::runtime_error("`rockfdem run` is not wired to the explicit stage yet");
}

}  // namespace rockfdem::workflows
