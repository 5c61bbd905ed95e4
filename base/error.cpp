#include "base/error.h"

namespace candela {

std::string FileLoc::str() const {
  if (line <= 0) return file;
  return file + ":" + std::to_string(line);
}

InputError::InputError(FileLoc loc, const std::string& message)
    : std::runtime_error(loc.str().empty() ? message : loc.str() + ": " + message),
      loc_(std::move(loc)),
      message_(message) {}

}  // namespace candela
