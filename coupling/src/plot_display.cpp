// Can VTK render here? Asked without VTK, because VTK's answer to "no display"
// is abort(). libX11 and libGL are opened with dlopen so that neither becomes
// a link dependency of the library (VTK links them itself when it renders).
#include <dlfcn.h>

#include <cstdlib>
#include <string>

#include "rockfdem/coupling/plot.hpp"

namespace rockfdem::coupling {
namespace {

// The X and GLX entry points we need, declared with opaque pointers so no X
// header is required.
using XOpenDisplayFn = void* (*)(const char*);
using XCloseDisplayFn = int (*)(void*);
using GlxQueryExtensionFn = int (*)(void*, int*, int*);

// Looks up `name` in the shared library `lib`. The library stays loaded on
// purpose: VTK loads the same libX11/libGL when it renders, and unloading
// libGL after GLX was used on a connection is a known source of crashes.
template <typename Fn>
Fn symbol(const char* lib, const char* name) {
  void* handle = ::dlopen(lib, RTLD_NOW | RTLD_LOCAL);
  return handle ? reinterpret_cast<Fn>(::dlsym(handle, name)) : nullptr;
}

bool fail(std::string* why, const std::string& reason) {
  if (why) *why = reason + "; run under `xvfb-run -a` to render plots without a screen";
  return false;
}

}  // namespace

bool rendering_available(std::string* why) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) return fail(why, "no X display (DISPLAY is not set)");
  const auto open = symbol<XOpenDisplayFn>("libX11.so.6", "XOpenDisplay");
  const auto close = symbol<XCloseDisplayFn>("libX11.so.6", "XCloseDisplay");
  if (!open || !close) return fail(why, "libX11.so.6 cannot be loaded");
  const auto query = symbol<GlxQueryExtensionFn>("libGL.so.1", "glXQueryExtension");
  if (!query) return fail(why, "libGL.so.1 (GLX) cannot be loaded");
  void* connection = open(nullptr);
  if (!connection) return fail(why, std::string("cannot open X display '") + display + "'");
  int error_base = 0, event_base = 0;
  const bool has_glx = query(connection, &error_base, &event_base) != 0;
  close(connection);
  if (!has_glx) return fail(why, std::string("X display '") + display + "' has no GLX");
  if (why) why->clear();
  return true;
}

}  // namespace rockfdem::coupling
