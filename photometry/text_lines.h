// Line splitting shared by the photometric file readers (IES LM-63, EULUMDAT).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace candela {

// Splits text into lines (LF or CRLF); trailing blank lines and DOS end-of-file marks (0x1A) are
// dropped, so that "truncated data" errors name the last real line.
std::vector<std::string> splitLines(std::string_view text);

}  // namespace candela
