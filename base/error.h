// Input errors carry the place in the input that is wrong; only cli/ turns them into exit codes.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace candela {

// Place in an input file: 1-based line and column; 0 means "unknown".
struct FileLoc {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const;  // "file:line" (or "file" when the line is unknown)
};

// `text` with every control character (bytes 0x00–0x1f and 0x7f) written as \xNN, so that input
// echoed in a message cannot drive the terminal it is printed on.
std::string printable(std::string_view text);

// `v` in at most 9 significant digits ("%.9g": 1e+308, 0.1, 2.5): a number quoted in a message
// stays a few characters long whatever its size (std::to_string(1e308) has 309 digits).
std::string compactNumber(double v);

// Bad user input. what() reads "file:line: message", ready to print as the one error line, with
// control characters escaped (printable).
class InputError : public std::runtime_error {
 public:
  InputError(FileLoc loc, const std::string& message);
  const FileLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }

 private:
  FileLoc loc_;
  std::string message_;
};

}  // namespace candela
