// Private to the plot sources: grabbing a rendered window into a PNG file.
#pragma once

#include <string>

class vtkRenderWindow;

namespace rockfdem::plots {

/// Renders `window` and writes its back buffer as PNG to `path`, atomically.
/// @throws std::runtime_error naming `path` when it cannot be written.
void save_window_png(vtkRenderWindow* window, const std::string& path);

/// @throws std::invalid_argument unless both sizes are at least 16 pixels.
void check_image_size(int width, int height);

}  // namespace rockfdem::plots
