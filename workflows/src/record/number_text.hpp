// Numbers as the run's text outputs print them (report.md, the support
// verdict): one helper, so a figure reads the same wherever it appears.
#pragma once

#include <cstdio>
#include <string>

namespace rockfdem::workflows {

/// `v` with `decimals` digits after the point; a value that rounds to zero
/// reads "0.00", never "-0.00".
inline std::string fixed(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  const std::string s = text;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) return s.substr(1);
  return s;
}

}  // namespace rockfdem::workflows
