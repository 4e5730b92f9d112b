// Private to the plot sources: an X connection held open while VTK renders.
//
// Why hold one: Xvfb (as xvfb-run starts it) resets itself whenever its last
// client disconnects, and a connection attempted during that reset fails;
// VTK answers that with abort() or a crash. Our own connection, opened (with
// retries) before VTK connects and closed after it is done, keeps the server
// from resetting under VTK, and the retries ride out a reset left by an
// earlier picture.
#pragma once

#include <string>

namespace rockfdem::plots {

class DisplayConnection {
 public:
  /// Connects to $DISPLAY and checks for GLX; see ok() and reason().
  DisplayConnection();
  ~DisplayConnection();
  DisplayConnection(const DisplayConnection&) = delete;
  DisplayConnection& operator=(const DisplayConnection&) = delete;

  bool ok() const { return display_ != nullptr; }
  /// Why rendering is not possible (empty when ok()).
  const std::string& reason() const { return reason_; }

 private:
  void* display_ = nullptr;  // Display*, opaque so no X header is needed
  std::string reason_;
};

}  // namespace rockfdem::plots
