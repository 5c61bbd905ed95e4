// Input errors carry the place in the input that is wrong; only cli/ turns them into exit codes.
#pragma once

#include <stdexcept>
#include <string>

namespace candela {

// Place in an input file: 1-based line and column; 0 means "unknown".
struct FileLoc {
  std::string file;
  int line = 0;
  int column = 0;
  std::string str() const;  // "file:line" (or "file" when the line is unknown)
};

// Bad user input. what() reads "file:line: message", ready to print as the one error line.
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
