// Text from outside (a scene's key or title, a .msh physical name, a
// checkpoint's field) shown safely: in an error message on a terminal, in
// report.md or a CSV cell. Beside error.hpp (in common/, below every
// library) because every stage's messages go through it.
#pragma once

#include <string>

namespace rockfdem {

/// `text` with its control characters shown as escapes: C0 controls (\n,
/// \t, \r by name, the rest as \x1b), DEL (\x7f) and the C1 controls
/// (U+0080 to U+009F, two bytes 0xC2 0x80-0x9F in UTF-8, shown as \u009b:
/// U+009B is a CSI on some terminals). Such text cannot move the cursor,
/// clear or retitle the terminal, or cut a message short (NUL). With
/// `keep_line_breaks`, '\n' stays as it is (for messages of several lines).
inline std::string printable(const std::string& text, bool keep_line_breaks = false) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == 0xC2 && i + 1 < text.size() &&
        (static_cast<unsigned char>(text[i + 1]) & 0xE0) == 0x80) {
      const auto d = static_cast<unsigned char>(text[++i]);
      out += "\\u00";
      out += kHex[d >> 4];
      out += kHex[d & 15];
    } else if (c == '\n') {
      out += keep_line_breaks ? "\n" : "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += char(c);
    }
  }
  return out;
}

}  // namespace rockfdem
