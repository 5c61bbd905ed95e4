#include "study/finite_results.h"
#include "engine/irradiance_estimator.h"

#include <cmath>
#include <stdexcept>

namespace candela {

namespace {

[[noreturn]] void nonFinite(const std::string& what, std::size_t i) {
  throw NonFiniteResult("a non-finite result in " + what + " at index " + std::to_string(i) +
                           "; nothing was written");
}

template <class T>
void checkAll(const std::vector<T>& values, const std::string& what, std::size_t firstIndex = 0) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i])) nonFinite(what, firstIndex + i);
}

}  // namespace

void checkFinite(const std::vector<IrradianceEstimate>& estimates, const std::string& what) {
  checkFinite(estimates.data(), estimates.size(), what, 0);
}

void checkFinite(const IrradianceEstimate* estimates, std::size_t n, const std::string& what, std::size_t firstIndex) {
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(estimates[i].illuminanceLux()) || !std::isfinite(estimates[i].standardErrorLux()))
      nonFinite(what, firstIndex + i);
}

void checkFinite(const std::vector<float>& values, const std::string& what) { checkAll(values, what); }
void checkFinite(const std::vector<double>& values, const std::string& what) { checkAll(values, what); }
void checkFinite(const std::vector<float>& values, const std::string& what, std::size_t firstIndex) {
  checkAll(values, what, firstIndex);
}

}  // namespace candela
