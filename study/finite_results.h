// Results are checked before anything is written: NaN or infinity is never a result. Inputs
// that could overflow are refused at their line by the readers, so a non-finite value here is an
// internal failure (exit 1), reported with where it arose instead of written as "-nan" lux.
#pragma once

#include "engine/tracer.h"
#include "engine/irradiance_estimator.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {

// A result that is not finite (NaN or infinity). An internal failure in a run; a merge turns it
// into an InputError at its parts (a part whose data hold a NaN is damaged input).
class NonFiniteResult : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws NonFiniteResult naming `what` and the first point whose illuminance or error is not
// finite.
void checkFinite(const std::vector<IrradianceEstimate>& estimates, const std::string& what);
// The same for a block of n estimates whose first is point `firstIndex` of the run (the grid
// study's blocks, engine/sensors.h): the index named is the run's.
void checkFinite(const IrradianceEstimate* estimates, std::size_t n, const std::string& what, std::size_t firstIndex);

// Throws NonFiniteResult naming `what` and the first index whose value is not finite.
void checkFinite(const std::vector<float>& values, const std::string& what);
void checkFinite(const std::vector<double>& values, const std::string& what);
// The same for a block of a larger array, whose first value is the larger array's `firstIndex`
// (the annual study's blocks of sensors): the index named is the larger array's.
void checkFinite(const std::vector<float>& values, const std::string& what, std::size_t firstIndex);

}  // namespace candela
