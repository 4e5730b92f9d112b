// Window -> image -> PNG, through a temporary file beside the target.
#include "plot_png.hpp"

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <stdexcept>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"

namespace rockfdem::plots {

void save_window_png(vtkRenderWindow* window, const std::string& path) {
  coupling::AtomicFile file(path);  // fails early, before rendering, on a bad directory
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();  // offscreen windows have only a back buffer worth reading
  grab->Update();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetFileName(file.temp_path().c_str());
  png->Write();
  if (png->GetErrorCode() != 0) {
    throw OutputError("cannot write '" + path + "': PNG writer failed (error code " +
                      std::to_string(png->GetErrorCode()) +
                      "); check free disk space and permissions");
  }
  file.commit();
}

void check_image_size(int width, int height) {
  if (width < 16 || height < 16) {
    throw std::invalid_argument("image size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is below 16x16 pixels");
  }
}

}  // namespace rockfdem::plots
