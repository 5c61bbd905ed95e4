#include "base/error.h"

#include <cstdio>

namespace candela {

std::string FileLoc::str() const {
  if (line <= 0) return file;
  return file + ":" + std::to_string(line);
}

std::string compactNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      // Control characters (ESC, CR, BEL, ...) written to a terminal could clear it or forge
      // text: shown as \xNN instead.
      static const char* kHex = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

InputError::InputError(FileLoc loc, const std::string& message)
    : std::runtime_error(printable(loc.str().empty() ? message : loc.str() + ": " + message)),
      loc_(std::move(loc)),
      message_(message) {}

}  // namespace candela
