// Can VTK render here? Asked without VTK, because VTK's answer to "no display"
// is abort(). libX11 and libGL are opened with dlopen so that neither becomes
// a link dependency of the library (VTK links them itself when it renders).
#include "plot_display.hpp"

#include <dlfcn.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "rockfdem/plots/plot.hpp"

namespace rockfdem::plots {
namespace {

// The X and GLX entry points we need, declared with opaque pointers so no X
// header is required.
using XOpenDisplayFn = void* (*)(const char*);
using XCloseDisplayFn = int (*)(void*);
using GlxQueryExtensionFn = int (*)(void*, int*, int*);

// An Xvfb reset takes milliseconds; 20 tries 25 ms apart outlast it, and cost
// half a second only where DISPLAY names a server that is really not there.
constexpr int kConnectTries = 20;
constexpr auto kRetryPause = std::chrono::milliseconds(25);

// Looks up `name` in the shared library `lib`. The library stays loaded on
// purpose: VTK loads the same libX11/libGL when it renders, and unloading
// libGL after GLX was used on a connection is a known source of crashes.
template <typename Fn>
Fn symbol(const char* lib, const char* name) {
  void* handle = ::dlopen(lib, RTLD_NOW | RTLD_LOCAL);
  return handle ? reinterpret_cast<Fn>(::dlsym(handle, name)) : nullptr;
}

XCloseDisplayFn close_display() { return symbol<XCloseDisplayFn>("libX11.so.6", "XCloseDisplay"); }

void* connect_with_retries(XOpenDisplayFn open) {
  for (int attempt = 0; attempt < kConnectTries; ++attempt) {
    if (void* display = open(nullptr)) return display;
    std::this_thread::sleep_for(kRetryPause);
  }
  return nullptr;
}

std::string advice(const std::string& reason) {
  return reason + "; run under `xvfb-run -a` to render plots without a screen";
}

}  // namespace

DisplayConnection::DisplayConnection() {
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name) {
    reason_ = advice("no X display (DISPLAY is not set)");
    return;
  }
  const auto open = symbol<XOpenDisplayFn>("libX11.so.6", "XOpenDisplay");
  const auto close = close_display();
  const auto query = symbol<GlxQueryExtensionFn>("libGL.so.1", "glXQueryExtension");
  if (!open || !close) {
    reason_ = advice("libX11.so.6 cannot be loaded");
    return;
  }
  if (!query) {
    reason_ = advice("libGL.so.1 (GLX) cannot be loaded");
    return;
  }
  void* display = connect_with_retries(open);
  if (!display) {
    reason_ = advice(std::string("cannot open X display '") + name + "'");
    return;
  }
  int error_base = 0, event_base = 0;
  if (!query(display, &error_base, &event_base)) {
    close(display);
    reason_ = advice(std::string("X display '") + name + "' has no GLX");
    return;
  }
  display_ = display;
}

DisplayConnection::~DisplayConnection() {
  if (display_) close_display()(display_);
}

bool rendering_available(std::string* why) {
  const DisplayConnection connection;
  if (why) *why = connection.reason();
  return connection.ok();
}

}  // namespace rockfdem::plots
