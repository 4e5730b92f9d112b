#include "rockfdem/coupling/vtk_messages.hpp"

#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

#include <mutex>

#include "rockfdem/printable.hpp"

namespace rockfdem::coupling {
namespace {

std::mutex last_mutex;
std::string last_text;

// Keeps the last message instead of printing it.
class QuietOutputWindow : public vtkOutputWindow {
 public:
  static QuietOutputWindow* New();
  vtkTypeMacro(QuietOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override {
    const std::lock_guard<std::mutex> lock(last_mutex);
    last_text = text ? printable(text, true) : "";
  }
};
vtkStandardNewMacro(QuietOutputWindow);

}  // namespace

void quiet_vtk_messages() {
  static const bool installed = [] {
    // vtkOutputWindowDisplayErrorText logs through vtkLogger (to stderr,
    // with colour codes) before it calls the output window.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkNew<QuietOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
    return true;
  }();
  (void)installed;
}

std::string last_vtk_message() {
  const std::lock_guard<std::mutex> lock(last_mutex);
  return last_text;
}

}  // namespace rockfdem::coupling
