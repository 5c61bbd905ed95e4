#include "base/warning.h"

namespace candela {

std::string warningLine(const Warning& w) {
  return "warning: " + printable(w.loc.str() + ": " + w.message + " [" + w.code + "]");
}

void throwIfStrict(const std::vector<Warning>& warnings, bool strict) {
  if (strict && !warnings.empty())
    throw InputError(warnings.front().loc, warnings.front().message + " [" + warnings.front().code + "]");
}

}  // namespace candela
