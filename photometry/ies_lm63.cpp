// IES LM-63 reader. File layout (ANSI/IES LM-63-02 and LM-63-19, section "file format"):
//   [IESNA:LM-63-xxxx | IESNA91 | IES:LM-63-2019]   (absent in LM-63-1986)
//   [KEYWORD] text lines ...                        (free text in LM-63-1986)
//   TILT=NONE | TILT=INCLUDE | TILT=<file>
//   [lamp-to-luminaire geometry, pair count, angles, multipliers]   (TILT=INCLUDE)
//   lamps, lumens/lamp, candela multiplier, #vertical, #horizontal, type, units, W, L, H
//   ballast factor, ballast-lamp factor | future use | file generation type, input watts
//   vertical angles, horizontal angles, candela values (for each horizontal angle, all
//   vertical angles). After the TILT line numbers may wrap freely across lines and be
//   separated by blanks or commas.
#include "photometry/ies_lm63.h"

#include "base/input_file.h"
#include "photometry/text_lines.h"

#include "base/error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace candela {

namespace {

constexpr double kFeetToMetres = 0.3048;  // international foot

char upperChar(char c) { return char(std::toupper(static_cast<unsigned char>(c))); }



std::string trim(std::string_view s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  const size_t b = s.find_last_not_of(" \t\r");
  return std::string(s.substr(a, b - a + 1));
}

bool parseNumber(std::string_view tok, double& out) {
  if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
  if (tok.empty()) return false;
  const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return ec == std::errc() && p == tok.data() + tok.size() && std::isfinite(out);
}

// The numbers after the TILT line, each with its 1-based line number.
class Tokens {
 public:
  Tokens(std::string file, const std::vector<std::string>& lines, size_t firstLine)
      : file_(std::move(file)), lastLine_(int(lines.size())) {
    for (size_t i = firstLine; i < lines.size(); ++i) {
      std::string s = lines[i];
      std::replace(s.begin(), s.end(), ',', ' ');
      std::replace(s.begin(), s.end(), '\t', ' ');
      std::istringstream in(s);
      std::string tok;
      while (in >> tok)
        if (tok != "\x1a") toks_.push_back({tok, int(i) + 1});
    }
  }

  double number(const std::string& what) {
    const auto& [tok, line] = next(what);
    double v = 0.0;
    if (!parseNumber(tok, v))
      throw InputError(FileLoc{file_, line, 0}, "bad number '" + tok + "' for " + what);
    return v;
  }
  int integer(const std::string& what) {
    const double v = number(what);
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      throw InputError(loc(), what + " must be a whole number, got " + toks_[pos_ - 1].first);
    return int(v);
  }
  // Strictly increasing angles, all read.
  std::vector<double> angles(int n, const std::string& what) {
    std::vector<double> a;
    for (int k = 0; k < n; ++k) {
      a.push_back(number(what));
      if (k > 0 && !(a[size_t(k)] > a[size_t(k) - 1]))
        throw InputError(loc(), what + " must increase: " + fmt(a[size_t(k)]) + " follows " +
                                    fmt(a[size_t(k) - 1]));
    }
    return a;
  }
  FileLoc loc() const { return FileLoc{file_, toks_[pos_ - 1].second, 0}; }
  // Where a file that ends too early is reported: its last line.
  FileLoc endLoc() const { return FileLoc{file_, lastLine_, 0}; }
  bool done() const { return pos_ >= toks_.size(); }
  size_t remaining() const { return toks_.size() - pos_; }
  FileLoc peekLoc() const { return FileLoc{file_, toks_[pos_].second, 0}; }
  const std::string& peek() const { return toks_[pos_].first; }
  static std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

 private:
  const std::pair<std::string, int>& next(const std::string& what) {
    if (pos_ >= toks_.size())
      throw InputError(FileLoc{file_, lastLine_, 0}, "file ends before " + what + " (truncated data)");
    return toks_[pos_++];
  }

  std::string file_;
  int lastLine_;
  std::vector<std::pair<std::string, int>> toks_;
  size_t pos_ = 0;
};

void readTiltBlock(Tokens& t, TiltData& tilt) {
  tilt.lampGeometry = t.integer("TILT lamp-to-luminaire geometry");
  if (tilt.lampGeometry < 1 || tilt.lampGeometry > 3)
    throw InputError(t.loc(), "TILT lamp-to-luminaire geometry must be 1, 2 or 3, got " +
                                  std::to_string(tilt.lampGeometry));
  const int n = t.integer("number of TILT angle/multiplier pairs");
  if (n < 1) throw InputError(t.loc(), "number of TILT pairs must be at least 1, got " + std::to_string(n));
  tilt.anglesDeg = t.angles(n, "TILT angles");
  for (int k = 0; k < n; ++k) {
    const double m = t.number("TILT multipliers");
    if (m < 0.0) throw InputError(t.loc(), "TILT multiplier must not be negative, got " + Tokens::fmt(m));
    tilt.multipliers.push_back(m);
  }
}

// A TILT file names a file beside the IES file (LM-63-2019 5.5: a file name). Confined to the IES
// file's folder (no absolute path, no "..") and to a regular file of at most 1 MiB, and a file
// the user did not name is never quoted in an error: its problems are reported at the TILT line
// of the IES file with the TILT file's line number only.
constexpr std::uintmax_t kMaxTiltFileBytes = 1 << 20;

void readTiltFile(const std::string& name, const std::filesystem::path& folder, const FileLoc& at, TiltData& tilt) {
  const std::filesystem::path rel(name);
  bool escapes = rel.is_absolute() || rel.has_root_name();
  for (const auto& part : rel) escapes = escapes || part == "..";
  if (escapes) throw InputError(at, "TILT file '" + name + "' must lie in the IES file's folder");
  const std::filesystem::path tiltPath = folder / rel;
  std::string text;
  try {
    text = readInputFile(tiltPath, "TILT file", kMaxTiltFileBytes);
  } catch (const InputError& e) {
    throw InputError(at, "cannot open TILT file '" + name + "': " + e.message());
  }
  const std::vector<std::string> tiltLines = splitLines(text);
  Tokens tt(tiltPath.string(), tiltLines, 0);
  try {
    readTiltBlock(tt, tilt);
  } catch (const InputError& e) {
    throw InputError(at, "TILT file '" + name + "' is not a valid TILT block (its line " +
                             std::to_string(e.loc().line) + ")");
  }
}

// Linear interpolation in the TILT table, held constant beyond its ends.
double tiltMultiplier(const TiltData& tilt, double angleDeg) {
  const auto& a = tilt.anglesDeg;
  const auto& m = tilt.multipliers;
  if (a.empty()) return 1.0;
  if (angleDeg <= a.front()) return m.front();
  if (angleDeg >= a.back()) return m.back();
  const size_t i = size_t(std::upper_bound(a.begin(), a.end(), angleDeg) - a.begin()) - 1;
  const double t = (angleDeg - a[i]) / (a[i + 1] - a[i]);
  return m[i] * (1.0 - t) + m[i + 1] * t;
}

}  // namespace

OpeningShape iesOpeningShape(double w, double l, double h) {
  const auto same = [](double a, double b) {
    return std::fabs(a - b) <= 1e-9 + 1e-6 * std::max(std::fabs(a), std::fabs(b));
  };
  if (w == 0 && l == 0 && h == 0) return OpeningShape::kPoint;
  if (w > 0 && l > 0) return h == 0 ? OpeningShape::kRectangular
                            : h > 0 ? OpeningShape::kRectangularWithSides
                                    : OpeningShape::kOther;
  if (w < 0 && l < 0) {
    if (h == 0) return same(w, l) ? OpeningShape::kCircular : OpeningShape::kEllipse;
    if (h > 0) return same(w, l) ? OpeningShape::kVerticalCylinder : OpeningShape::kVerticalEllipticalCylinder;
    return same(w, l) && same(w, h) ? OpeningShape::kSphere : OpeningShape::kEllipsoid;
  }
  if (w < 0 && l > 0 && h < 0) return OpeningShape::kHorizontalCylinderAlongLength;
  if (w > 0 && l < 0 && h < 0) return OpeningShape::kHorizontalCylinderAlongWidth;
  if ((w < 0 && l == 0 && h < 0)) return same(w, h) ? OpeningShape::kVerticalCircle : OpeningShape::kVerticalEllipse;
  if ((w == 0 && l < 0 && h < 0)) return same(l, h) ? OpeningShape::kVerticalCircle : OpeningShape::kVerticalEllipse;
  if (w < 0 && l == 0 && h == 0) return OpeningShape::kCircular;  // pre-2019: negative width = round
  return OpeningShape::kOther;
}

PhotometricWeb readIes(const std::filesystem::path& path, const IesOptions& options) {
  return parseIes(readInputFile(path, "file"), path.string(), path.parent_path(), options);
}

PhotometricWeb parseIes(std::string_view text, const std::string& fileName,
                        const std::filesystem::path& folder, const IesOptions& options) {
  const std::vector<std::string> lines = splitLines(text);
  if (lines.empty()) throw InputError(FileLoc{fileName, 1, 0}, "empty IES file");
  PhotometricInfo info;
  info.fileName = fileName;

  // First line: the edition. LM-63-1986 has none; its first line is already free text.
  std::string edition = "1986";
  size_t li = 0;
  {
    std::string first = trim(lines[0]);
    std::string upper = first;
    std::transform(upper.begin(), upper.end(), upper.begin(), upperChar);
    if (upper.rfind("IESNA:LM-63-", 0) == 0 || upper.rfind("IES:LM-63-", 0) == 0) {
      edition = trim(upper.substr(upper.find("LM-63-") + 6));
      if (edition != "1995" && edition != "2002" && edition != "2019")
        throw InputError(FileLoc{fileName, 1, 0}, "unknown IES edition '" + first +
                                                      "' (expected LM-63-1995, -2002 or -2019)");
      li = 1;
    } else if (upper.rfind("IESNA91", 0) == 0) {
      edition = "1991";
      li = 1;
    }
  }
  info.format = "IES LM-63-" + edition;
  const bool is2019 = edition == "2019";

  // Header lines up to TILT=.
  std::string lastKey;
  for (; li < lines.size(); ++li) {
    const std::string line = trim(lines[li]);
    std::string upper = line.substr(0, 5);
    std::transform(upper.begin(), upper.end(), upper.begin(), upperChar);
    if (upper == "TILT=") break;
    if (!line.empty() && line.front() == '[' && line.find(']') != std::string::npos) {
      std::string key = line.substr(1, line.find(']') - 1);
      std::transform(key.begin(), key.end(), key.begin(), upperChar);
      const std::string value = trim(line.substr(line.find(']') + 1));
      if (key == "MORE" && !lastKey.empty()) key = lastKey;
      auto& slot = info.keywords[key];
      slot = slot.empty() ? value : slot + "\n" + value;
      lastKey = key;
    } else if (!line.empty()) {
      auto& slot = info.keywords["TEXT"];  // LM-63-1986 labels and stray lines
      slot = slot.empty() ? line : slot + "\n" + line;
    }
  }
  if (li >= lines.size())
    throw InputError(FileLoc{fileName, int(lines.size()), 0}, "no TILT= line before the end of the file");
  const int tiltLine = int(li) + 1;
  const std::string tiltValue = trim(trim(lines[li]).substr(5));

  Tokens t(fileName, lines, li + 1);
  info.tilt.appliedAngleDeg = options.tiltAngleDeg;
  std::string tiltUpper = tiltValue;
  std::transform(tiltUpper.begin(), tiltUpper.end(), tiltUpper.begin(), upperChar);
  if (tiltUpper == "NONE" || tiltUpper.empty()) {
    info.tilt.source = "NONE";
  } else if (tiltUpper == "INCLUDE") {
    info.tilt.source = "INCLUDE";
    readTiltBlock(t, info.tilt);
  } else {
    // TILT=<file>: the same block in a file of its own, beside the IES file.
    info.tilt.source = tiltValue;
    readTiltFile(tiltValue, folder, FileLoc{fileName, tiltLine, 0}, info.tilt);
  }
  if (info.tilt.source != "NONE")
    info.tilt.appliedMultiplier = tiltMultiplier(info.tilt, options.tiltAngleDeg);

  info.numLamps = t.integer("number of lamps");
  if (info.numLamps < 0) throw InputError(t.loc(), "number of lamps must not be negative");
  info.lumensPerLamp = t.number("lumens per lamp");
  if (info.lumensPerLamp == 0.0 || (info.lumensPerLamp < 0.0 && info.lumensPerLamp != -1.0))
    throw InputError(t.loc(), "lumens per lamp must be positive or -1 (absolute photometry), got " +
                                  Tokens::fmt(info.lumensPerLamp));
  info.lampLumens = info.lumensPerLamp > 0.0 ? info.lumensPerLamp * info.numLamps : -1.0;
  info.candelaMultiplier = t.number("candela multiplier");
  if (!(info.candelaMultiplier > 0.0))
    throw InputError(t.loc(), "candela multiplier must be positive, got " + Tokens::fmt(info.candelaMultiplier));
  const int nv = t.integer("number of vertical angles");
  if (nv < 2) throw InputError(t.loc(), "number of vertical angles must be at least 2, got " + std::to_string(nv));
  const int nh = t.integer("number of horizontal angles");
  if (nh < 1) throw InputError(t.loc(), "number of horizontal angles must be at least 1, got " + std::to_string(nh));
  const int ptype = t.integer("photometric type");
  if (ptype == 3)
    throw InputError(t.loc(), "photometric type 3 (type A, automotive) is not supported; convert the file to type C");
  if (ptype != 1 && ptype != 2)
    throw InputError(t.loc(), "unknown photometric type " + std::to_string(ptype) +
                                  " (expected 1 = type C or 2 = type B)");
  const int units = t.integer("units type");
  if (units != 1 && units != 2)
    throw InputError(t.loc(), "units type must be 1 (feet) or 2 (metres), got " + std::to_string(units));
  const double toM = units == 1 ? kFeetToMetres : 1.0;
  const double w = t.number("luminous opening width");
  info.openingLoc = t.loc();
  const double l = t.number("luminous opening length"), h = t.number("luminous opening height");
  info.openingShape = iesOpeningShape(w, l, h);
  info.openingWidthM = std::fabs(w) * toM;
  info.openingLengthM = std::fabs(l) * toM;
  info.openingHeightM = std::fabs(h) * toM;
  if (info.openingShape == OpeningShape::kCircular && l == 0.0) info.openingLengthM = info.openingWidthM;

  info.ballastFactor = t.number("ballast factor");
  if (!(info.ballastFactor > 0.0))
    throw InputError(t.loc(), "ballast factor must be positive, got " + Tokens::fmt(info.ballastFactor));
  const double third = t.number(is2019 ? "file generation type" : "ballast-lamp photometric factor");
  if (is2019) {
    info.fileGenerationType = third;  // a code (1.00001 ...), never a multiplier
  } else {
    if (!(third > 0.0))
      throw InputError(t.loc(), "ballast-lamp photometric factor must be positive, got " + Tokens::fmt(third));
    info.ballastLampFactor = third;
  }
  info.inputWatts = t.number("input watts");
  if (info.inputWatts < 0.0) throw InputError(t.loc(), "input watts must not be negative");

  // The angles and the candela table must all be in the file: checked before anything is
  // allocated, so that counts such as 46341 x 46341 (whose product overflows an int) or 10^9 are
  // a truncated file, not gigabytes.
  const size_t tableSize = size_t(nv) * size_t(nh);
  const size_t needed = size_t(nv) + size_t(nh) + tableSize;
  if (needed > t.remaining())
    throw InputError(t.endLoc(), "file ends before the candela table: " + std::to_string(nv) + " vertical x " +
                                     std::to_string(nh) + " horizontal angles need " + std::to_string(needed) +
                                     " more numbers, the file has " + std::to_string(t.remaining()) +
                                     " (truncated data, or wrong numbers of angles)");
  std::vector<double> vAngles = t.angles(nv, "vertical angles");
  const FileLoc vLoc = t.loc();
  std::vector<double> hAngles = t.angles(nh, "horizontal angles");
  const FileLoc hLoc = t.loc();

  PlaneSymmetry sym = PlaneSymmetry::kNone;
  const PhotometricType type = ptype == 1 ? PhotometricType::kC : PhotometricType::kB;
  if (type == PhotometricType::kC) {
    if (vAngles.front() < 0.0 || vAngles.back() > 180.0)
      throw InputError(vLoc, "type C vertical angles must lie in 0-180, got " + Tokens::fmt(vAngles.front()) +
                                 "-" + Tokens::fmt(vAngles.back()));
    const double h0 = hAngles.front(), h1 = hAngles.back();
    if (nh == 1) {
      sym = PlaneSymmetry::kRotational;
    } else if (h0 == 0.0 && h1 == 90.0) {
      sym = PlaneSymmetry::kQuadrant;
    } else if (h0 == 0.0 && h1 == 180.0) {
      sym = PlaneSymmetry::kMirrorC0C180;
    } else if (h0 == 0.0 && h1 > 180.0 && h1 <= 360.0) {
      sym = PlaneSymmetry::kNone;
    } else if (h0 == 90.0 && h1 == 270.0) {
      sym = PlaneSymmetry::kMirrorC90C270;  // legacy: symmetric about the 90-270 plane
    } else {
      throw InputError(hLoc, "type C horizontal angles " + Tokens::fmt(h0) + "-" + Tokens::fmt(h1) +
                                 " are not a known symmetry (0; 0-90; 0-180; 0-360; 90-270)");
    }
  } else {
    if (vAngles.front() < -180.0 || vAngles.back() > 180.0)
      throw InputError(vLoc, "type B vertical angles must lie in -180..180");
    if (hAngles.front() < -90.0 || hAngles.back() > 90.0 || nh < 2)
      throw InputError(hLoc, "type B horizontal angles must be at least two angles in -90..90");
  }

  const double factor = info.candelaMultiplier * info.ballastFactor * info.ballastLampFactor *
                        info.tilt.appliedMultiplier;
  std::vector<double> cd;
  cd.reserve(tableSize);
  for (size_t i = 0; i < tableSize; ++i) {
    const double v = t.number("candela values");
    if (v < 0.0) throw InputError(t.loc(), "negative candela value " + Tokens::fmt(v));
    cd.push_back(v * factor);
  }
  // Some exporters close the file with a line "END" (blank lines are never tokens): accepted when
  // it is the last thing in the file.
  bool closedByEnd = false;
  if (t.remaining() == 1) {
    std::string last = t.peek();
    std::transform(last.begin(), last.end(), last.begin(), upperChar);
    closedByEnd = last == "END";
  }
  if (!t.done() && !closedByEnd)
    throw InputError(t.peekLoc(), "unexpected value '" + t.peek() +
                                      "' after the candela table (check the numbers of angles)");
  return PhotometricWeb(std::move(info), type, sym, std::move(hAngles), std::move(vAngles), std::move(cd));
}

}  // namespace candela
