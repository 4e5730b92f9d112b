#pragma once
#include <string>
namespace rockfdem::workflows {
/// "0.1.0" (from the CMake project version).
std::string version_string();
}  // namespace rockfdem::workflows
