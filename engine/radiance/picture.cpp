#include "engine/radiance/picture.h"

#include "base/input_file.h"

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
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

// What the header says that candela reads (header.c's lines up to an empty one).
struct PictureHeader {
  std::string format;            // FORMAT= (empty: none)
  int formatLine = 0;
  double aspect = 1.0;           // PIXASPECT= (multiplied, as Radiance's headaspect)
  int components = 0;            // NCOMP= (0: none)
  std::array<double, 4> splits{};  // WAVELENGTH_SPLITS= (nm, the longest first)
  bool hasSplits = false;
  int line = 0;                  // the header's last line (the empty one)
};

PictureHeader readHeader(std::string_view bytes, const std::string& fileName, size_t& pos) {
  PictureHeader h;
  bool first = true;
  for (;;) {
    const size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos || ++h.line > 10000)
      bad(fileName, h.line, "no end of header (not a Radiance picture)");
    const std::string_view text = bytes.substr(pos, end - pos);
    pos = end + 1;
    if (first && text.rfind("#?", 0) != 0 && !text.empty() && text.find('=') == std::string_view::npos)
      bad(fileName, h.line, "not a Radiance picture (no '#?RADIANCE' line)");
    first = false;
    if (text.empty()) return h;
    const std::string value(text.substr(text.find('=') + 1, 200));
    if (text.rfind("FORMAT=", 0) == 0) {
      h.format = std::string(text.substr(7, 40));
      h.formatLine = h.line;
    } else if (text.rfind("PIXASPECT=", 0) == 0) {
      const double a = std::atof(value.c_str());
      if (!(a > 0.0 && a < 1e6)) bad(fileName, h.line, "PIXASPECT is not a positive number");
      h.aspect *= a;
    } else if (text.rfind("NCOMP=", 0) == 0) {
      h.components = std::atoi(value.c_str());
    } else if (text.rfind("WAVELENGTH_SPLITS=", 0) == 0) {
      std::istringstream in(value);
      for (double& w : h.splits) in >> w;
      h.hasSplits = static_cast<bool>(in);
      if (!h.hasSplits) bad(fileName, h.line, "WAVELENGTH_SPLITS needs four wavelengths (nm)");
    }
  }
}

// The resolution line's layout: the picture's size, how its scanlines run, and getpict's extent
// (y then x, the shorter side from 0 to 1).
struct PictureLayout {
  long width = 0, height = 0;
  bool yMajor = true, yDown = true, xLeft = true;
  double ySize = 1.0, xSize = 1.0;
  long scanLength() const { return yMajor ? width : height; }
  long scans() const { return yMajor ? height : width; }
  // The pixel at position `along` of scanline `across`: its row from the bottom times the width
  // plus its column from the left.
  size_t pixel(long across, long along) const {
    long x = yMajor ? along : across, y = yMajor ? across : along;
    if (yDown) y = height - 1 - y;
    if (!xLeft) x = width - 1 - x;
    return static_cast<size_t>(y * width + x);
  }
};

// The resolution line ("-Y h +X w" or another of Radiance's eight orientations) at pos, for
// pixels of `valuesPerPixel` values each (bounded by kMaxDataValues in all).
PictureLayout readResolution(std::string_view bytes, const std::string& fileName, size_t& pos, int line,
                             double aspect, size_t valuesPerPixel) {
  const size_t end = bytes.find('\n', pos);
  if (end == std::string_view::npos) bad(fileName, line, "no resolution line");
  std::istringstream res{std::string(bytes.substr(pos, std::min<size_t>(end - pos, 100)))};
  std::string a1, a2;
  long n1 = 0, n2 = 0;
  res >> a1 >> n1 >> a2 >> n2;
  const bool ok1 = a1.size() == 2 && (a1[0] == '-' || a1[0] == '+'), ok2 = a2.size() == 2 && (a2[0] == '-' || a2[0] == '+');
  if (!res || !ok1 || !ok2 || a1[1] == a2[1] || (a1[1] != 'X' && a1[1] != 'Y') || (a2[1] != 'X' && a2[1] != 'Y'))
    bad(fileName, line, "the resolution line is not '-Y height +X width' or another of Radiance's orientations");
  if (n1 < 1 || n2 < 1 || n1 > kMaxSide || n2 > kMaxSide ||
      static_cast<size_t>(n1 * n2) > kMaxDataValues / valuesPerPixel)
    bad(fileName, line, "a picture of " + std::to_string(n1) + " × " + std::to_string(n2) + " pixels of " +
                            std::to_string(valuesPerPixel) + " values is beyond what candela reads (32768 a side, " +
                            "2^24 values)");
  pos = end + 1;
  PictureLayout l;
  l.yMajor = a1[1] == 'Y';  // scanlines run along x
  l.width = l.yMajor ? n2 : n1;
  l.height = l.yMajor ? n1 : n2;
  l.yDown = (l.yMajor ? a1 : a2)[0] == '-';
  l.xLeft = (l.yMajor ? a2 : a1)[0] == '+';
  const bool tall = static_cast<double>(l.width) <= static_cast<double>(l.height) * aspect;
  l.ySize = tall ? aspect * static_cast<double>(l.height) / static_cast<double>(l.width) : 1.0;
  l.xSize = tall ? 1.0 : static_cast<double>(l.width) / static_cast<double>(l.height) / aspect;
  return l;
}

// A picture file's bytes, read whole (a regular file: base/input_file.h) up to maxBytes.
std::string pictureBytes(const std::filesystem::path& path, std::uintmax_t maxBytes, const std::string& what) {
  checkInputFile(path, what);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > maxBytes)
    throw InputError(FileLoc{path.string(), 0}, what + ": larger than a picture candela reads (2^24 values)");
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw InputError(FileLoc{path.string(), 0}, what + ": cannot be read");
  InputFileLog::record(path, bytes);
  return bytes;
}

}  // namespace

std::array<RadDataArray, 3> parseRadiancePicture(std::string_view bytes, const std::string& fileName) {
  size_t pos = 0;
  const PictureHeader h = readHeader(bytes, fileName, pos);
  if (!h.format.empty() && h.format != "32-bit_rle_rgbe")
    bad(fileName, h.formatLine, "format '" + h.format + "' is not 32-bit_rle_rgbe (RGB)");
  const int line = h.line + 1;
  const PictureLayout l = readResolution(bytes, fileName, pos, line, h.aspect, 3);
  std::array<RadDataArray, 3> out;
  for (RadDataArray& a : out) {
    a.file = fileName;
    a.axes = {RadDataArray::Axis{0.0, l.ySize, static_cast<int>(l.height), {}},
              RadDataArray::Axis{0.0, l.xSize, static_cast<int>(l.width), {}}};
    a.values.assign(static_cast<size_t>(l.width * l.height), 0.0);
  }
  std::vector<uint8_t> scan;
  for (long s = 0; s < l.scans(); ++s) {
    if (!readScanline(bytes, pos, static_cast<int>(l.scanLength()), scan))
      bad(fileName, line, "scanline " + std::to_string(s + 1) + " of " + std::to_string(l.scans()) +
                              " is damaged or missing");
    for (long k = 0; k < l.scanLength(); ++k) {
      const size_t at = l.pixel(s, k);
      const uint8_t* p = &scan[static_cast<size_t>(k) * 4];
      for (int c = 0; c < 3; ++c) out[static_cast<size_t>(c)].values[at] = channel(p[c], p[3]);
    }
  }
  return out;
}

RadDataArray parseHyperspectralPicture(std::string_view bytes, const std::string& fileName) {
  size_t pos = 0;
  const PictureHeader h = readHeader(bytes, fileName, pos);
  // getspec (src/rt/data.c): a FORMAT other than the spectral one, NCOMP of 3 or fewer (or beyond
  // MAXCSAMP, 24) or no wavelength splits is not a hyperspectral picture.
  if (!h.format.empty() && h.format.find("spectra") == std::string::npos)
    bad(fileName, h.formatLine, "format '" + h.format + "' is not a Radiance hyperspectral picture (Radiance_spectra)");
  if (h.components <= 3 || h.components > kMaxSpectralComponents)
    bad(fileName, h.line, "a hyperspectral picture needs NCOMP= between 4 and " +
                              std::to_string(kMaxSpectralComponents) + " in its header" +
                              (h.components != 0 ? ", got " + std::to_string(h.components) : ""));
  if (!h.hasSplits || !(h.splits[3] >= 1.0) || h.splits[0] == h.splits[3])
    bad(fileName, h.line, "a hyperspectral picture needs WAVELENGTH_SPLITS= with its range of wavelengths (nm)");
  const int line = h.line + 1;
  const int nc = h.components;
  const PictureLayout l = readResolution(bytes, fileName, pos, line, h.aspect, static_cast<size_t>(nc));
  RadDataArray out;
  out.file = fileName;
  // The components are nc equal bands from splits[0] to splits[3], each at its centre (getspec).
  const double range = h.splits[3] - h.splits[0];
  const double first = h.splits[0] + 0.5 * range / nc;
  out.axes = {RadDataArray::Axis{0.0, l.ySize, static_cast<int>(l.height), {}},
              RadDataArray::Axis{0.0, l.xSize, static_cast<int>(l.width), {}},
              RadDataArray::Axis{first, first + range * (nc - 1.0) / nc, nc, {}}};
  out.values.assign(static_cast<size_t>(l.width * l.height) * static_cast<size_t>(nc), 0.0);
  // Each scanline flat: nc mantissas and one common exponent a pixel (color.c freadscolrs).
  const size_t pixelBytes = static_cast<size_t>(nc) + 1;
  for (long s = 0; s < l.scans(); ++s) {
    const size_t need = static_cast<size_t>(l.scanLength()) * pixelBytes;
    if (bytes.size() - pos < need)
      bad(fileName, line, "scanline " + std::to_string(s + 1) + " of " + std::to_string(l.scans()) + " is missing");
    for (long k = 0; k < l.scanLength(); ++k) {
      const auto* p = reinterpret_cast<const uint8_t*>(bytes.data() + pos + static_cast<size_t>(k) * pixelBytes);
      double* v = &out.values[l.pixel(s, k) * static_cast<size_t>(nc)];
      for (int c = 0; c < nc; ++c) v[c] = channel(p[c], p[nc]);
    }
    pos += need;
  }
  return out;
}

std::array<RadDataArray, 3> readRadiancePicture(const std::filesystem::path& path) {
  return parseRadiancePicture(pictureBytes(path, kMaxPicturePixels * 4 + (1 << 20), "picture"), path.string());
}

RadDataArray readHyperspectralPicture(const std::filesystem::path& path) {
  // nc + 1 bytes a pixel for nc values: at most twice the values (nc ≥ 4), and the header.
  return parseHyperspectralPicture(pictureBytes(path, 2 * kMaxDataValues + (1 << 20), "hyperspectral picture"),
                                   path.string());
}

}  // namespace candela
