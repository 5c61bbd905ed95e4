// Hourly illuminances of an annual run, stored compactly: one binary file per grid, float32
// little-endian, sensor-major, behind a small self-describing header. The byte layout is
// documented in docs/annual-outputs.md (with a numpy reader).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "reports/report_data.h"

namespace candela {

// Header layout, version 1 (all integers little-endian):
//   0   char[8]   magic "CNDLHRLY"
//   8   uint32    version (1)
//   12  uint32    data offset in bytes (= 48 + 4·nHours)
//   16  uint32    nSensors
//   20  uint32    nHours
//   24  char[16]  layout, NUL-padded: "sensor-major"
//   40  char[8]   units, NUL-padded: "lux"
//   48  nHours × {uint8 month, uint8 day, uint8 hourEnding, uint8 0}
//   48 + 4·nHours: float32[nSensors·nHours], value(s, h) at index s·nHours + h
inline constexpr char kAnnualResultsMagic[8] = {'C', 'N', 'D', 'L', 'H', 'R', 'L', 'Y'};
inline constexpr uint32_t kAnnualResultsVersion = 1;
inline constexpr std::size_t kAnnualResultsFixedHeaderBytes = 48;

// Hourly illuminance of every sensor of a grid for one year.
struct AnnualResults {
  int sensors = 0;
  std::vector<HourStamp> hours;  // one per time step (8760 or 8784 for a year)
  std::vector<float> lux;        // sensor-major: lux[s * hours.size() + h], in lux

  int hourCount() const { return static_cast<int>(hours.size()); }
  float at(int sensor, int hour) const { return lux[static_cast<std::size_t>(sensor) * hours.size() + hour]; }
  // One sensor's year, as doubles (for AnnualGridReport::chosenSensorLux).
  std::vector<double> sensorSeries(int sensor) const;
};

// The file's bytes. Throws std::invalid_argument when lux.size() != sensors · hours.size().
std::string encodeAnnualResults(const AnnualResults& results);

// Writes the file atomically (temporary file + rename); creates the parent folder if needed.
void writeAnnualResults(const std::filesystem::path& path, const AnnualResults& results);

// Same, for callers that keep the values in another order: `luxAt(s, h)` gives the illuminance of
// sensor s at time step h in lux; it is called sensor by sensor, hour by hour.
void writeAnnualResults(const std::filesystem::path& path, int sensors, const std::vector<HourStamp>& hours,
                        const std::function<float(int sensor, int hour)>& luxAt);

// Parses the bytes of a file; `fileName` names it in errors. Throws InputError whose what() reads
// "name: byte N: message" (a binary file has no lines: the place is the byte offset) on a bad magic,
// an unknown version, an unknown layout or unit, an hour stamp out of range, or a size that does not
// match the header (truncated or overlong file).
AnnualResults decodeAnnualResults(const std::string& bytes, const std::string& fileName);

// Reads and parses a file. Also throws InputError when the file cannot be opened.
AnnualResults readAnnualResults(const std::filesystem::path& path);

// File name of a grid's hourly results: "<safeFileName(gridName)>_hourly.f32".
std::string annualResultsFileName(const std::string& gridName);

}  // namespace candela
