// Window -> image -> PNG, through a temporary file beside the target.
#include "plot_png.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <stdexcept>

#include "rockfdem/coupling/atomic_file.hpp"
#include "rockfdem/error.hpp"
#include "rockfdem/plots/plot.hpp"

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

PngPixels read_png_pixels(const std::string& path) {
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
    throw std::runtime_error("cannot read '" + path + "' as PNG");
  reader->SetFileName(path.c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  auto* px = vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetPointData()->GetScalars());
  if (!px || px->GetNumberOfComponents() < 3)
    throw std::runtime_error("cannot read '" + path + "' as an RGB PNG");
  PngPixels out;
  out.width = dims[0];
  out.height = dims[1];
  const int nc = px->GetNumberOfComponents();
  out.rgb.resize(std::size_t(out.width) * std::size_t(out.height) * 3);
  for (vtkIdType i = 0; i < px->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      out.rgb[std::size_t(i) * 3 + std::size_t(c)] = px->GetValue(i * nc + c);
  return out;
}

int PngPixels::count(std::array<int, 3> colour, int tolerance) const {
  int n = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    bool match = true;
    for (std::size_t c = 0; c < 3; ++c)
      match = match && std::abs(rgb[i + c] - colour[c]) <= tolerance;
    n += match;
  }
  return n;
}

}  // namespace rockfdem::plots
