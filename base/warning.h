// A warning: the input is valid but its result is probably not what the user meant (a scene with
// no light, a sensor on a wall, ...). Studies collect them (study/warnings.h), reports show them
// and the command line prints them; `--strict` makes the first one an InputError. The codes are a
// contract (docs/warnings.md): short, stable snake_case.
#pragma once

#include "base/error.h"

#include <string>
#include <vector>

namespace candela {

struct Warning {
  std::string code;     // e.g. "no_light_source"
  std::string message;  // one sentence, what is wrong and why it matters
  FileLoc loc;          // where in the input; line 0 when only the file is known
};

// The line the command line prints: "warning: file:line: message [code]", control characters
// escaped (printable).
std::string warningLine(const Warning& w);

// Throws InputError(loc, "message [code]") for the first of `warnings` when `strict`.
void throwIfStrict(const std::vector<Warning>& warnings, bool strict);

}  // namespace candela
