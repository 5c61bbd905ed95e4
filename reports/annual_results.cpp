#include "reports/annual_results.h"

#include <bit>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include "base/atomic_file.h"
#include "base/error.h"

namespace candela {

namespace {

constexpr char kLayout[] = "sensor-major";
constexpr char kUnits[] = "lux";
constexpr std::size_t kLayoutBytes = 16, kUnitsBytes = 8;

// Explicit little-endian bytes, so the file is the same on any host.
void putU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFFu);
}

void putPadded(std::string& out, const char* text, std::size_t width) {
  std::string field(width, '\0');
  std::memcpy(field.data(), text, std::strlen(text));
  out += field;
}

uint32_t getU32(const std::string& in, std::size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}

std::string getPadded(const std::string& in, std::size_t at, std::size_t width) {
  std::string s = in.substr(at, width);
  const std::size_t nul = s.find('\0');
  return nul == std::string::npos ? s : s.substr(0, nul);
}

std::string header(int sensors, const std::vector<HourStamp>& hours) {
  if (sensors < 0) throw std::invalid_argument("annual results: negative sensor count");
  std::string out;
  out.append(kAnnualResultsMagic, sizeof kAnnualResultsMagic);
  putU32(out, kAnnualResultsVersion);
  putU32(out, static_cast<uint32_t>(kAnnualResultsFixedHeaderBytes + 4 * hours.size()));
  putU32(out, static_cast<uint32_t>(sensors));
  putU32(out, static_cast<uint32_t>(hours.size()));
  putPadded(out, kLayout, kLayoutBytes);
  putPadded(out, kUnits, kUnitsBytes);
  for (const HourStamp& h : hours) {
    out += static_cast<char>(h.month);
    out += static_cast<char>(h.day);
    out += static_cast<char>(h.hourEnding);
    out += '\0';
  }
  return out;
}

void putF32(std::string& out, float v) { putU32(out, std::bit_cast<uint32_t>(v)); }

}  // namespace

std::vector<double> AnnualResults::sensorSeries(int sensor) const {
  const std::size_t n = hours.size(), begin = static_cast<std::size_t>(sensor) * n;
  return std::vector<double>(lux.begin() + static_cast<std::ptrdiff_t>(begin),
                             lux.begin() + static_cast<std::ptrdiff_t>(begin + n));
}

std::string encodeAnnualResults(const AnnualResults& r) {
  if (r.sensors < 0 || r.lux.size() != static_cast<std::size_t>(r.sensors) * r.hours.size())
    throw std::invalid_argument("annual results: " + std::to_string(r.lux.size()) + " values for " +
                                std::to_string(r.sensors) + " sensors × " + std::to_string(r.hours.size()) + " hours");
  std::string out = header(r.sensors, r.hours);
  out.reserve(out.size() + 4 * r.lux.size());
  for (float v : r.lux) putF32(out, v);
  return out;
}

void writeAnnualResults(const std::filesystem::path& path, const AnnualResults& results) {
  const std::string bytes = encodeAnnualResults(results);
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  writeFileAtomic(path, bytes);
}

void writeAnnualResults(const std::filesystem::path& path, int sensors, const std::vector<HourStamp>& hours,
                        const std::function<float(int, int)>& luxAt) {
  std::string out = header(sensors, hours);
  const int n = static_cast<int>(hours.size());
  out.reserve(out.size() + 4 * static_cast<std::size_t>(sensors) * hours.size());
  for (int s = 0; s < sensors; ++s)
    for (int h = 0; h < n; ++h) putF32(out, luxAt(s, h));
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  writeFileAtomic(path, out);
}

AnnualResultsStream::AnnualResultsStream(const std::filesystem::path& path, int sensors,
                                         const std::vector<HourStamp>& hours)
    : path_(path), file_(std::make_unique<AtomicFile>(path)), sensors_(sensors), hours_(static_cast<int>(hours.size())) {
  const std::string head = header(sensors, hours);
  dataOffset_ = head.size();
  file_->write(head);
}

AnnualResultsStream::~AnnualResultsStream() = default;

void AnnualResultsStream::append(const float* lux, int count) {
  if (finished_) throw std::invalid_argument("annual results stream: " + path_.string() + " is finished");
  if (count < 0 || count > sensors_ - written_)
    throw std::invalid_argument("annual results stream: " + std::to_string(count) + " rows after " +
                                std::to_string(written_) + " of " + std::to_string(sensors_));
  // Little-endian whatever the host, as encodeAnnualResults writes them: the floats themselves on
  // a little-endian host, else converted in pieces of 4 MB (a copy small beside the block).
  constexpr std::size_t kPieceValues = std::size_t{1} << 20;
  const std::size_t values = static_cast<std::size_t>(count) * hours_;
  std::string bytes;
  for (std::size_t at = 0; at < values; at += kPieceValues) {
    const std::size_t n = std::min(kPieceValues, values - at);
    if constexpr (std::endian::native == std::endian::little) {
      file_->write(std::string_view(reinterpret_cast<const char*>(lux + at), 4 * n));
    } else {
      bytes.clear();
      bytes.reserve(4 * n);
      for (std::size_t i = 0; i < n; ++i) putF32(bytes, lux[at + i]);
      file_->write(bytes);
    }
  }
  written_ += count;
}

void AnnualResultsStream::read(int first, int count, float* lux) const {
  if (first < 0 || count < 0 || first > written_ - count)
    throw std::invalid_argument("annual results stream: rows " + std::to_string(first) + " + " +
                                std::to_string(count) + " not written yet (" + std::to_string(written_) + ")");
  const std::size_t values = static_cast<std::size_t>(count) * hours_;
  // Straight into `lux` on a little-endian host; else through bytes converted after.
  constexpr bool kLittle = std::endian::native == std::endian::little;
  std::string bytes(kLittle ? 0 : 4 * values, '\0');
  char* into = kLittle ? reinterpret_cast<char*>(lux) : bytes.data();
  const off_t start = static_cast<off_t>(dataOffset_ + 4 * static_cast<std::size_t>(first) * hours_);
  std::size_t done = 0;
  while (done < 4 * values) {
    const ssize_t n = ::pread(file_->descriptor(), into + done, 4 * values - done, start + static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw std::runtime_error("cannot read back " + path_.string() + (n < 0 ? ": " + std::string(std::strerror(errno)) : ""));
    done += static_cast<std::size_t>(n);
  }
  if constexpr (!kLittle)
    for (std::size_t i = 0; i < values; ++i) lux[i] = std::bit_cast<float>(getU32(bytes, 4 * i));
}

void AnnualResultsStream::finish() {
  if (written_ != sensors_)
    throw std::invalid_argument("annual results stream: " + path_.string() + " has " + std::to_string(written_) +
                                " of " + std::to_string(sensors_) + " rows");
  finished_ = true;
}

void AnnualResultsStream::commitAs(const std::filesystem::path& target) {
  finish();
  file_->commitAs(target);
}

namespace {

InputError failAt(const std::string& fileName, std::size_t byte, const std::string& message) {
  return InputError(FileLoc{fileName, 0, 0}, "byte " + std::to_string(byte) + ": " + message);
}

// The header of a file of `fileSize` bytes whose first bytes are `in` (at least the fixed
// header and the hour stamps, when the file has them): stamps into r, every check of
// decodeAnnualResults. Returns the data offset.
std::size_t parseHeader(const std::string& in, uint64_t fileSize, const std::string& fileName, AnnualResults& r) {
  auto fail = [&](std::size_t byte, const std::string& message) { return failAt(fileName, byte, message); };
  if (fileSize < kAnnualResultsFixedHeaderBytes)
    throw fail(fileSize, "truncated header: " + std::to_string(fileSize) + " bytes, the fixed header has " +
                             std::to_string(kAnnualResultsFixedHeaderBytes));
  if (std::memcmp(in.data(), kAnnualResultsMagic, sizeof kAnnualResultsMagic) != 0)
    throw fail(0, "not a candela hourly results file (magic is not \"CNDLHRLY\")");
  const uint32_t version = getU32(in, 8);
  if (version != kAnnualResultsVersion)
    throw fail(8, "unsupported version " + std::to_string(version) + " (this build reads version " +
                      std::to_string(kAnnualResultsVersion) + ")");
  const uint32_t dataOffset = getU32(in, 12), sensors = getU32(in, 16), hourCount = getU32(in, 20);
  const std::string layout = getPadded(in, 24, kLayoutBytes), units = getPadded(in, 40, kUnitsBytes);
  if (layout != kLayout) throw fail(24, "unknown layout \"" + layout + "\", expected \"" + kLayout + "\"");
  if (units != kUnits) throw fail(40, "unknown units \"" + units + "\", expected \"" + kUnits + "\"");
  const uint64_t expectedOffset = kAnnualResultsFixedHeaderBytes + 4ull * hourCount;
  if (dataOffset != expectedOffset)
    throw fail(12, "data offset " + std::to_string(dataOffset) + " does not match " + std::to_string(hourCount) +
                       " hours (expected " + std::to_string(expectedOffset) + ")");
  const uint64_t expectedSize = expectedOffset + 4ull * sensors * hourCount;
  if (fileSize != expectedSize)
    throw fail(std::min<uint64_t>(fileSize, expectedSize),
               (fileSize < expectedSize ? "truncated file: " : "file too long: ") + std::to_string(fileSize) +
                   " bytes, the header (" + std::to_string(sensors) + " sensors × " + std::to_string(hourCount) +
                   " hours) needs " + std::to_string(expectedSize));
  r.sensors = static_cast<int>(sensors);
  r.hours.resize(hourCount);
  for (uint32_t h = 0; h < hourCount; ++h) {
    const std::size_t at = kAnnualResultsFixedHeaderBytes + 4 * h;
    HourStamp& s = r.hours[h];
    s.month = static_cast<uint8_t>(in[at]);
    s.day = static_cast<uint8_t>(in[at + 1]);
    s.hourEnding = static_cast<uint8_t>(in[at + 2]);
    if (s.month < 1 || s.month > 12 || s.day < 1 || s.day > 31 || s.hourEnding < 1 || s.hourEnding > 24)
      throw fail(at, "hour " + std::to_string(h) + " has an invalid stamp (month " + std::to_string(s.month) +
                         ", day " + std::to_string(s.day) + ", hour ending " + std::to_string(s.hourEnding) + ")");
  }
  return dataOffset;
}

}  // namespace

AnnualResults decodeAnnualResults(const std::string& in, const std::string& fileName) {
  AnnualResults r;
  const std::size_t dataOffset = parseHeader(in, in.size(), fileName, r);
  r.lux.resize(static_cast<std::size_t>(r.sensors) * r.hours.size());
  for (std::size_t i = 0; i < r.lux.size(); ++i) r.lux[i] = std::bit_cast<float>(getU32(in, dataOffset + 4 * i));
  return r;
}

AnnualResults readAnnualResultsRows(const std::filesystem::path& path, int first, int count) {
  std::ifstream f(path, std::ios::binary);
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(path, ec);
  if (!f || ec) throw InputError(FileLoc{path.string(), 0, 0}, "cannot open hourly results file");
  // The fixed header tells how many stamps follow; read those, then the rows asked for alone.
  std::string head(std::min<uint64_t>(size, kAnnualResultsFixedHeaderBytes), '\0');
  f.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (head.size() == kAnnualResultsFixedHeaderBytes) {
    const uint64_t stamps = std::min<uint64_t>(4ull * getU32(head, 20), size - kAnnualResultsFixedHeaderBytes);
    head.resize(kAnnualResultsFixedHeaderBytes + stamps);
    f.read(head.data() + kAnnualResultsFixedHeaderBytes, static_cast<std::streamsize>(stamps));
  }
  AnnualResults r;
  const std::size_t dataOffset = parseHeader(head, size, path.string(), r);
  if (first < 0 || count < 0 || first > r.sensors - count)
    throw InputError(FileLoc{path.string(), 0, 0}, "sensors " + std::to_string(first) + " to " +
                                                       std::to_string(first + count - 1) + " are not in the file (" +
                                                       std::to_string(r.sensors) + " sensors)");
  const std::size_t n = r.hours.size();
  std::string bytes(4 * n * static_cast<std::size_t>(count), '\0');
  f.seekg(static_cast<std::streamoff>(dataOffset + 4 * n * static_cast<std::size_t>(first)));
  f.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!f) throw InputError(FileLoc{path.string(), 0, 0}, "cannot read hourly results file");
  r.sensors = count;
  r.lux.resize(n * static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < r.lux.size(); ++i) r.lux[i] = std::bit_cast<float>(getU32(bytes, 4 * i));
  return r;
}

AnnualResults readAnnualResults(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(FileLoc{path.string(), 0, 0}, "cannot open hourly results file");
  std::ostringstream s;
  s << f.rdbuf();
  return decodeAnnualResults(s.str(), path.string());
}

std::string annualResultsFileName(const std::string& gridName) { return safeFileName(gridName) + "_hourly.f32"; }

}  // namespace candela
