// rockfdem: from a tunnel scene to stresses, cracks, convergence and support
// loads. Errors are caught here once and mapped to the exit codes of
// the README: 2 bad input, 3 numerical failure, 1 anything else; 130/143
// after SIGINT/SIGTERM (interrupt.hpp). A message may quote text from a
// file (a .msh group name, a scene's value): its control characters are
// shown as escapes, never sent to the terminal.
#include <iostream>

#include "rockfdem/coupling/vtk_messages.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/insitu/insitu.hpp"
#include "rockfdem/printable.hpp"
#include "rockfdem/workflows/cli.hpp"
#include "run/interrupt.hpp"
#include "run/loader_pages.hpp"
#include "run/process_memory.hpp"
#include "study/register_study.hpp"

int main(int argc, char** argv) {
  using namespace rockfdem;
  workflows::install_early_handlers();
  // A failing VTK writer is reported by its caller in one line.
  coupling::quiet_vtk_messages();
  // MPI (for PETSc's AMG in the implicit stage) lives as long as main().
  insitu::ScopedParallelInit parallel(argc, argv);
  workflows::study::register_study_commands();
  workflows::install_early_handlers();  // again: MPI may have set its own
  // What linking the libraries left resident (their symbol tables: 0.1 GB)
  // is not needed again: it would add to every run's peak.
  workflows::release_loader_pages();
  workflows::restore_malloc_policy();
  try {
    const workflows::CommandLine cli = workflows::parse_command_line(argc, argv);
    const int code = workflows::run_command(cli);
    // A signal after the command's last check (a study's or run's end,
    // MPI's finalisation) still ends the process with 128 + signal.
    workflows::install_closing_handlers();
    workflows::signal_point("command-end");
    workflows::throw_if_interrupted("as the command ended; its outputs are written");
    return code;
  } catch (const workflows::Interrupted& e) {
    std::cerr << "rockfdem: " << printable(e.what(), true) << '\n';  // it says what was written
    return e.exit_code();
  } catch (const InputError& e) {
    std::cerr << "rockfdem: error: " << printable(e.what(), true) << '\n';
    return 2;
  } catch (const NumericalError& e) {
    std::cerr << "rockfdem: numerical failure: " << printable(e.what(), true) << '\n';
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "rockfdem: " << printable(e.what(), true) << '\n';
    return 1;
  }
}
