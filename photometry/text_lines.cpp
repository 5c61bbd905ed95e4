#include "photometry/text_lines.h"

namespace candela {

std::vector<std::string> splitLines(std::string_view text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(start, end - start));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    if (end == text.size()) break;
    start = end + 1;
  }
  while (!lines.empty() && lines.back().find_first_not_of(" \t\x1a") == std::string::npos) lines.pop_back();
  return lines;
}

}  // namespace candela
