#include "engine/radiance/picture.h"

#include "base/input_file.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace candela {
namespace {

constexpr int kMaxSide = 1 << 15;  // no picture side beyond 32768 pixels

[[noreturn]] void bad(const std::string& file, int line, const std::string& what) {
  throw InputError(FileLoc{file, line}, "picture: " + what);
}

// One RGBE pixel as Radiance decodes it (color.c, colr_color): (m + 0.5)·2^(e − 136), 0 for e = 0.
double channel(uint8_t m, uint8_t e) { return e == 0 ? 0.0 : std::ldexp(m + 0.5, static_cast<int>(e) - 136); }

// Reads one scanline of `width` RGBE pixels at bytes[pos] (flat, old run-length or new
// run-length encoding: color.c's freadcolrs), advancing pos; false when the data end or are
// damaged.
bool readScanline(std::string_view bytes, size_t& pos, int width, std::vector<uint8_t>& out) {
  out.assign(static_cast<size_t>(width) * 4, 0);
  auto byte = [&](uint8_t& b) {
    if (pos >= bytes.size()) return false;
    b = static_cast<uint8_t>(bytes[pos++]);
    return true;
  };
  if (width >= 8 && width < 0x8000 && pos + 4 <= bytes.size() && static_cast<uint8_t>(bytes[pos]) == 2 &&
      static_cast<uint8_t>(bytes[pos + 1]) == 2 && !(static_cast<uint8_t>(bytes[pos + 2]) & 0x80)) {
    const int len = (static_cast<uint8_t>(bytes[pos + 2]) << 8) | static_cast<uint8_t>(bytes[pos + 3]);
    if (len != width) return false;
    pos += 4;
    for (int c = 0; c < 4; ++c) {  // each component's run-length coded row
      for (int x = 0; x < width;) {
        uint8_t code, v;
        if (!byte(code)) return false;
        if (code > 128) {
          const int run = code & 127;
          if (!byte(v) || x + run > width) return false;
          for (int k = 0; k < run; ++k) out[static_cast<size_t>(x++) * 4 + c] = v;
        } else {
          if (code == 0 || x + code > width) return false;
          for (int k = 0; k < code; ++k) {
            if (!byte(v)) return false;
            out[static_cast<size_t>(x++) * 4 + c] = v;
          }
        }
      }
    }
    return true;
  }
  // Flat pixels, with the old run-length code: (1, 1, 1, n) repeats the previous pixel n << shift.
  int shift = 0;
  for (int x = 0; x < width;) {
    uint8_t p[4];
    for (uint8_t& b : p)
      if (!byte(b)) return false;
    if (p[0] == 1 && p[1] == 1 && p[2] == 1) {
      if (x == 0 || shift > 24) return false;
      const long run = static_cast<long>(p[3]) << shift;
      if (x + run > width) return false;
      for (long k = 0; k < run; ++k, ++x)
        for (int c = 0; c < 4; ++c) out[static_cast<size_t>(x) * 4 + c] = out[static_cast<size_t>(x - 1) * 4 + c];
      shift += 8;
    } else {
      for (int c = 0; c < 4; ++c) out[static_cast<size_t>(x) * 4 + c] = p[c];
      ++x;
      shift = 0;
    }
  }
  return true;
}

}  // namespace

std::array<RadDataArray, 3> parseRadiancePicture(std::string_view bytes, const std::string& fileName) {
  // The header: lines up to an empty one (header.c); the format must be RGBE.
  size_t pos = 0;
  int line = 0;
  double aspect = 1.0;
  bool first = true;
  for (;;) {
    const size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos || ++line > 10000) bad(fileName, line, "no end of header (not a Radiance picture)");
    const std::string_view text = bytes.substr(pos, end - pos);
    pos = end + 1;
    if (first && text.rfind("#?", 0) != 0 && !text.empty() && text.find('=') == std::string_view::npos)
      bad(fileName, line, "not a Radiance picture (no '#?RADIANCE' line)");
    first = false;
    if (text.empty()) break;
    if (text.rfind("FORMAT=", 0) == 0 && text.substr(7) != "32-bit_rle_rgbe")
      bad(fileName, line, "format '" + std::string(text.substr(7, 40)) + "' is not 32-bit_rle_rgbe (RGB)");
    if (text.rfind("PIXASPECT=", 0) == 0) {
      const double a = std::atof(std::string(text.substr(10, 40)).c_str());
      if (!(a > 0.0 && a < 1e6)) bad(fileName, line, "PIXASPECT is not a positive number");
      aspect *= a;
    }
  }
  // The resolution line: "-Y h +X w" (standard) or any of Radiance's eight orientations.
  const size_t end = bytes.find('\n', pos);
  ++line;
  if (end == std::string_view::npos) bad(fileName, line, "no resolution line");
  std::istringstream res{std::string(bytes.substr(pos, std::min<size_t>(end - pos, 100)))};
  std::string a1, a2;
  long n1 = 0, n2 = 0;
  res >> a1 >> n1 >> a2 >> n2;
  const bool ok1 = a1.size() == 2 && (a1[0] == '-' || a1[0] == '+'), ok2 = a2.size() == 2 && (a2[0] == '-' || a2[0] == '+');
  if (!res || !ok1 || !ok2 || a1[1] == a2[1] || (a1[1] != 'X' && a1[1] != 'Y') || (a2[1] != 'X' && a2[1] != 'Y'))
    bad(fileName, line, "the resolution line is not '-Y height +X width' or another of Radiance's orientations");
  if (n1 < 1 || n2 < 1 || n1 > kMaxSide || n2 > kMaxSide || static_cast<size_t>(n1 * n2) > kMaxPicturePixels)
    bad(fileName, line, "a picture of " + std::to_string(n1) + " × " + std::to_string(n2) +
                            " pixels is beyond what candela reads (32768 a side, 2^24 pixels)");
  pos = end + 1;
  const bool yMajor = a1[1] == 'Y';  // scanlines run along x
  const long width = yMajor ? n2 : n1, height = yMajor ? n1 : n2;
  const bool yDown = (yMajor ? a1 : a2)[0] == '-', xLeft = (yMajor ? a2 : a1)[0] == '+';
  std::array<RadDataArray, 3> out;
  // getpict's dimensions: y then x, the shorter side from 0 to 1.
  const bool tall = static_cast<double>(width) <= static_cast<double>(height) * aspect;
  const double ySize = tall ? aspect * static_cast<double>(height) / static_cast<double>(width) : 1.0;
  const double xSize = tall ? 1.0 : static_cast<double>(width) / static_cast<double>(height) / aspect;
  for (RadDataArray& a : out) {
    a.file = fileName;
    a.axes = {RadDataArray::Axis{0.0, ySize, static_cast<int>(height), {}},
              RadDataArray::Axis{0.0, xSize, static_cast<int>(width), {}}};
    a.values.assign(static_cast<size_t>(width * height), 0.0);
  }
  const long scanLength = yMajor ? width : height, scans = yMajor ? height : width;
  std::vector<uint8_t> scan;
  for (long s = 0; s < scans; ++s) {
    if (!readScanline(bytes, pos, static_cast<int>(scanLength), scan))
      bad(fileName, line, "scanline " + std::to_string(s + 1) + " of " + std::to_string(scans) +
                              " is damaged or missing");
    for (long k = 0; k < scanLength; ++k) {
      // The pixel's place: row y from the bottom, column x from the left.
      const long along = k, across = s;
      long x = yMajor ? along : across, y = yMajor ? across : along;
      if (yDown) y = height - 1 - y;
      if (!xLeft) x = width - 1 - x;
      const size_t at = static_cast<size_t>(y * width + x);
      const uint8_t* p = &scan[static_cast<size_t>(k) * 4];
      for (int c = 0; c < 3; ++c) out[static_cast<size_t>(c)].values[at] = channel(p[c], p[3]);
    }
  }
  return out;
}

std::array<RadDataArray, 3> readRadiancePicture(const std::filesystem::path& path) {
  checkInputFile(path, "picture");
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxPicturePixels * 4 + (1 << 20))
    throw InputError(FileLoc{path.string(), 0}, "picture: larger than a picture candela reads (2^24 pixels)");
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw InputError(FileLoc{path.string(), 0}, "picture: cannot be read");
  InputFileLog::record(path, bytes);
  return parseRadiancePicture(bytes, path.string());
}

}  // namespace candela
