// Hourly illuminances of an annual run, stored compactly: one binary file per grid, float32
// little-endian, sensor-major, behind a small self-describing header. The byte layout is
// documented in docs/annual-outputs.md (with a numpy reader).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <functional>
#include <string>
#include <vector>

#include "base/atomic_file.h"
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

// The same file written a block of sensors at a time, so that a study never holds a grid's year
// (docs/annual-outputs.md, "Streaming"): the header on construction, then the sensors' rows in
// sensor order, each nHours floats. The file is a temporary in `path`'s folder, unnamed where the
// file system allows (base/atomic_file.h AtomicFile), so that a run killed midway leaves nothing;
// commitAs(target) checks that every sensor's row came and puts it in place, in the result folder
// made at the end of the run (study/run_outputs.h). A stream destroyed uncommitted removes its
// temporary, so it never passes for a whole file. Errors are std::runtime_error (a full disk) or
// std::invalid_argument (a row count that does not fit).
class AnnualResultsStream {
 public:
  AnnualResultsStream(const std::filesystem::path& path, int sensors, const std::vector<HourStamp>& hours);
  ~AnnualResultsStream();
  AnnualResultsStream(const AnnualResultsStream&) = delete;
  AnnualResultsStream& operator=(const AnnualResultsStream&) = delete;

  // Appends `count` sensors' rows, sensor-major: lux[k * nHours + h], lux.
  void append(const float* lux, int count);
  // Reads back `count` rows already appended, from sensor `first` on, into lux[k * nHours + h].
  void read(int first, int count, float* lux) const;
  // Checks that every sensor's row came; appending after it is an error.
  void finish();
  // finish(), then the file goes to `target`, a path in the same file system as `path`'s folder.
  void commitAs(const std::filesystem::path& target);
  int written() const { return written_; }

 private:
  std::filesystem::path path_;
  std::unique_ptr<AtomicFile> file_;
  bool finished_ = false;
  int sensors_ = 0, hours_ = 0, written_ = 0;
  std::size_t dataOffset_ = 0;
};

// Parses the bytes of a file; `fileName` names it in errors. Throws InputError whose what() reads
// "name: byte N: message" (a binary file has no lines: the place is the byte offset) on a bad magic,
// an unknown version, an unknown layout or unit, an hour stamp out of range, or a size that does not
// match the header (truncated or overlong file).
AnnualResults decodeAnnualResults(const std::string& bytes, const std::string& fileName);

// Reads and parses a file. Also throws InputError when the file cannot be opened.
AnnualResults readAnnualResults(const std::filesystem::path& path);

// The rows of sensors first .. first + count - 1 alone, as results of `count` sensors (sensor k
// of the result is sensor first + k of the file), read at their offsets without the rest: rows
// have a fixed size, so sensor s starts at byte dataOffset + 4·nHours·s (that arithmetic is the
// file's index, docs/annual-outputs.md). Throws InputError as readAnnualResults (the whole
// header is checked, the file's size included), and when the range lies beyond the file.
AnnualResults readAnnualResultsRows(const std::filesystem::path& path, int first, int count);

// File name of a grid's hourly results: "<safeFileName(gridName)>_hourly.f32".
std::string annualResultsFileName(const std::string& gridName);

}  // namespace candela
