// VTK's own error and warning messages, kept off the terminal.
//
// A VTK writer that fails (a full disk) prints a dozen lines of its
// pipeline's state to stderr through its logger, with colour codes,
// before the writer returns; the caller's exception then names the file
// and the reason in one line. rockfdem's messages are its own: VTK's go
// to a window that keeps only the last one, for a caller that wants it.
#pragma once

#include <string>

namespace rockfdem::coupling {

/// Routes VTK's messages (errors, warnings, its logger's output to
/// stderr) away from the terminal for the rest of the process. Call once,
/// early in main(); calling again does nothing more.
void quiet_vtk_messages();

/// The last message VTK sent since quiet_vtk_messages(), with control
/// characters escaped ("" when none).
std::string last_vtk_message();

}  // namespace rockfdem::coupling
