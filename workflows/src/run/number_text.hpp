// Numbers as the run's text outputs print them (report.md, the support
// verdict): one helper, so a figure reads the same wherever it appears.
#pragma once

#include <cstdio>
#include <string>

namespace rockfdem::workflows {

/// `v` with `decimals` digits after the point.
inline std::string fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

}  // namespace rockfdem::workflows
