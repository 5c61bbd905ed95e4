// EULUMDAT reader. Line layout (Stockmar 1990; the field list as commonly published):
//  1 company   2 Ityp   3 Isym   4 Mc   5 Dc   6 Ng   7 Dg   8 report   9 luminaire name
// 10 luminaire number  11 file name  12 date/user  13-15 luminaire length/width/height (mm)
// 16-17 luminous area length/width (mm; width 0 = circular)  18-21 luminous heights in the
// C0/C90/C180/C270 planes (mm)  22 DFF (%)  23 LORL (%)  24 conversion factor  25 tilt (deg)
// 26 n lamp sets, then n lines each of: 26a lamp count, 26b type, 26c total flux (lm),
// 26d colour, 26e colour rendering, 26f watts incl. ballast  27 ten direct ratios
// 28 Mc C angles  29 Ng gamma angles  30 intensities (cd/klm) of planes Mc1..Mc2, Ng each.
#include "photometry/eulumdat.h"
#include "photometry/text_lines.h"

#include "base/error.h"
#include "base/input_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace candela {

namespace {

// A line without its surrounding blanks.
std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// A number as EULUMDAT files write it: a decimal comma is common in files written with a European
// locale, a leading '+' is allowed. False for anything else (and for NaN or infinity).
bool parseLdtNumber(std::string s, double& x) {
  if (s.find('.') == std::string::npos) std::replace(s.begin(), s.end(), ',', '.');
  std::string_view v = s;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  return !v.empty() && ec == std::errc() && p == v.data() + v.size() && std::isfinite(x);
}

class LdtLines {
 public:
  LdtLines(std::string file, std::string_view text) : file_(std::move(file)), lines_(splitLines(text)) {}

  std::string text(const std::string& what) {
    if (pos_ >= lines_.size())
      throw InputError(FileLoc{file_, int(lines_.size()), 0},
                       "file ends before " + what + " (line " + std::to_string(pos_ + 1) + ", truncated data)");
    return trimmed(lines_[pos_++]);
  }
  double number(const std::string& what) {
    const std::string s = text(what);
    double x = 0.0;
    if (!parseLdtNumber(s, x)) {
      // The message shows the value as read, with a decimal comma turned into a point.
      std::string shown = s;
      if (shown.find('.') == std::string::npos) std::replace(shown.begin(), shown.end(), ',', '.');
      throw InputError(loc(), "bad number '" + shown + "' for " + what);
    }
    return x;
  }
  int integer(const std::string& what) {
    const double v = number(what);
    if (v != std::floor(v) || std::fabs(v) > 1e9)
      throw InputError(loc(), what + " must be a whole number, got " + lines_[pos_ - 1]);
    return int(v);
  }
  FileLoc loc() const { return FileLoc{file_, int(pos_), 0}; }
  bool done() const { return pos_ >= lines_.size(); }
  // Whether line `index` (0-based, read or not) holds a number, without reading it.
  bool numberAt(size_t index) const {
    double x = 0.0;
    return index < lines_.size() && parseLdtNumber(trimmed(lines_[index]), x);
  }
  size_t position() const { return pos_; }
  // Lines not read yet.
  size_t remaining() const { return lines_.size() - std::min(pos_, lines_.size()); }
  // A count read from the header (`what`, at the line just read) needs `perItem` lines per item:
  // refused before anything is allocated when the file cannot hold them (a 756-byte file with
  // Mc = 400 000 000 once allocated 3.1 GB).
  void checkCount(long long count, long long perItem, const std::string& what) const {
    if (count > 0 && count * perItem > static_cast<long long>(remaining()))
      throw InputError(loc(), what + " = " + std::to_string(count) + " needs " + std::to_string(count * perItem) +
                                  " more lines, but the file has " + std::to_string(remaining()));
  }

 private:
  std::string file_;
  std::vector<std::string> lines_;
  size_t pos_ = 0;
};

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

PhotometricWeb readEulumdat(const std::filesystem::path& path) {
  return parseEulumdat(readInputFile(path, "file"), path.string());
}

namespace {

// Lines 2-7: the counts that shape the rest of the file.
struct LdtShape {
  int isym = 0;  // symmetry indicator Isym, 0-4
  int mc = 0;    // number of C planes
  int ng = 0;    // number of gamma angles
};

// Lines 1-12: company, type, symmetry, the numbers of C planes and gamma angles, and the names.
LdtShape readIdentification(LdtLines& in, PhotometricInfo& info) {
  info.keywords["MANUFAC"] = in.text("company identification (line 1)");
  const int ityp = in.integer("type indicator Ityp");
  if (ityp < 0 || ityp > 3)
    throw InputError(in.loc(), "type indicator Ityp must be 0-3, got " + std::to_string(ityp));
  const int isym = in.integer("symmetry indicator Isym");
  if (isym < 0 || isym > 4)
    throw InputError(in.loc(), "symmetry indicator Isym must be 0-4, got " + std::to_string(isym));
  const int mc = in.integer("number of C planes Mc");
  if (mc < 1) throw InputError(in.loc(), "number of C planes Mc must be at least 1, got " + std::to_string(mc));
  in.checkCount(mc, 1, "Mc");
  if ((isym == 2 && mc % 2 != 0) || ((isym == 3 || isym == 4) && mc % 4 != 0))
    throw InputError(in.loc(), "Mc = " + std::to_string(mc) + " does not fit symmetry " + std::to_string(isym) +
                                   (isym == 2 ? " (needs an even number)" : " (needs a multiple of 4)"));
  in.number("C plane spacing Dc");
  const int ng = in.integer("number of gamma angles Ng");
  if (ng < 2) throw InputError(in.loc(), "number of gamma angles Ng must be at least 2, got " + std::to_string(ng));
  in.checkCount(ng, 1, "Ng");
  in.number("gamma spacing Dg");
  info.keywords["TEST"] = in.text("measurement report number");
  info.keywords["LUMINAIRE"] = in.text("luminaire name");
  info.keywords["LUMCAT"] = in.text("luminaire number");
  info.keywords["FILENAME"] = in.text("file name");
  info.keywords["DATE"] = in.text("date/user");
  return LdtShape{isym, mc, ng};
}

// Lines 13-21: luminaire and luminous area dimensions (mm in the file, m in `info`).
void readDimensions(LdtLines& in, PhotometricInfo& info) {
  const double mm = 1e-3;
  info.luminaireLengthM = in.number("luminaire length") * mm;
  info.luminaireWidthM = in.number("luminaire width") * mm;
  info.luminaireHeightM = in.number("luminaire height") * mm;
  const double la = in.number("luminous area length") * mm;
  info.openingLoc = in.loc();
  const double lb = in.number("luminous area width") * mm;
  double lh = 0.0;
  for (const char* plane : {"C0", "C90", "C180", "C270"})
    lh = std::max(lh, in.number(std::string("luminous area height in the ") + plane + " plane") * mm);
  if (la < 0 || lb < 0) throw InputError(in.loc(), "luminous area dimensions must not be negative");
  // EULUMDAT length is taken along C90-C270 and width along C0-C180, as LM-63's length/width.
  info.openingLengthM = la;
  info.openingWidthM = lb;
  info.openingHeightM = lh;
  if (la == 0.0 && lb == 0.0) {
    info.openingShape = OpeningShape::kPoint;
  } else if (lb == 0.0) {  // width 0: circular, diameter = length
    info.openingWidthM = la;
    info.openingShape = lh > 0.0 ? OpeningShape::kVerticalCylinder : OpeningShape::kCircular;
  } else {
    info.openingShape = lh > 0.0 ? OpeningShape::kRectangularWithSides : OpeningShape::kRectangular;
  }
}

// Lines 26a-f of n lamp sets. Files as manufacturers' tools write them keep each set's six lines
// together (count, type, flux, colour, colour rendering, watts, then the next set); some older
// writers stored each field for all sets in turn. The field-by-field reading is taken only when
// its numeric lines (counts, fluxes, watts) are numbers and the set-by-set reading's are not;
// otherwise, the common layout, whose errors then name the line.
bool setsAsFields(const LdtLines& in, int n) {
  const size_t at = in.position();
  bool byBlock = true, byField = true;
  for (size_t k = 0; k < size_t(n); ++k) {
    byBlock = byBlock && in.numberAt(at + 6 * k) && in.numberAt(at + 6 * k + 2) && in.numberAt(at + 6 * k + 5);
    byField = byField && in.numberAt(at + k) && in.numberAt(at + 2 * n + k) && in.numberAt(at + 5 * n + k);
  }
  return byField && !byBlock;
}

// Each set's six lines together. Returns the line of lamp set 1's flux.
int readLampSetsByBlock(LdtLines& in, PhotometricInfo& info) {
  int fluxLine = 0;
  for (LampSet& s : info.lampSets) {
    s.count = in.integer("number of lamps");
    s.type = in.text("lamp type");
    s.totalFluxLm = in.number("total lamp flux");
    if (&s == &info.lampSets.front()) fluxLine = in.loc().line;
    s.colour = in.text("colour appearance");
    s.colourRendering = in.text("colour rendering");
    s.wattsW = in.number("wattage including ballast");
  }
  return fluxLine;
}

// Each field for all sets in turn. Returns the line of lamp set 1's flux.
int readLampSetsByField(LdtLines& in, PhotometricInfo& info) {
  for (auto& s : info.lampSets) s.count = in.integer("number of lamps");
  for (auto& s : info.lampSets) s.type = in.text("lamp type");
  int fluxLine = 0;
  for (auto& s : info.lampSets) {
    s.totalFluxLm = in.number("total lamp flux");
    if (&s == &info.lampSets.front()) fluxLine = in.loc().line;
  }
  for (auto& s : info.lampSets) s.colour = in.text("colour appearance");
  for (auto& s : info.lampSets) s.colourRendering = in.text("colour rendering");
  for (auto& s : info.lampSets) s.wattsW = in.number("wattage including ballast");
  return fluxLine;
}

// Lines 22-27: DFF, LORL, conversion factor, tilt, the lamp sets and the direct ratios. Returns
// the line of lamp set 1's flux, for its error message.
int readLampData(LdtLines& in, PhotometricInfo& info) {
  info.declaredDownwardFluxPercent = in.number("downward flux fraction DFF");
  info.declaredLorPercent = in.number("light output ratio LORL");
  info.conversionFactor = in.number("conversion factor for intensities");
  if (!(info.conversionFactor > 0.0))
    throw InputError(in.loc(), "conversion factor must be positive, got " + fmt(info.conversionFactor));
  info.keywords["TILT"] = fmt(in.number("tilt during measurement"));
  const int nsets = in.integer("number of lamp sets");
  if (nsets < 1) throw InputError(in.loc(), "number of lamp sets must be at least 1, got " + std::to_string(nsets));
  in.checkCount(nsets, 6, "the number of lamp sets");
  info.lampSets.resize(size_t(nsets));
  const int fluxLine = setsAsFields(in, nsets) ? readLampSetsByField(in, info) : readLampSetsByBlock(in, info);
  for (int k = 0; k < 10; ++k) in.number("direct ratio");
  return fluxLine;
}

// Line 28: Mc increasing C angles in [0, 360).
std::vector<double> readCAngles(LdtLines& in, int mc) {
  std::vector<double> c(static_cast<size_t>(mc));
  for (int k = 0; k < mc; ++k) {
    c[size_t(k)] = in.number("C angle");
    if (c[size_t(k)] < 0.0 || c[size_t(k)] >= 360.0)
      throw InputError(in.loc(), "C angle must lie in 0..360 (360 excluded), got " + fmt(c[size_t(k)]));
    if (k > 0 && !(c[size_t(k)] > c[size_t(k) - 1]))
      throw InputError(in.loc(), "C angles must increase: " + fmt(c[size_t(k)]) + " follows " + fmt(c[size_t(k) - 1]));
  }
  return c;
}

// Line 29: Ng increasing gamma angles in [0, 180].
std::vector<double> readGammaAngles(LdtLines& in, int ng) {
  std::vector<double> g(static_cast<size_t>(ng));
  for (int k = 0; k < ng; ++k) {
    g[size_t(k)] = in.number("gamma angle");
    if (g[size_t(k)] < 0.0 || g[size_t(k)] > 180.0)
      throw InputError(in.loc(), "gamma angle must lie in 0-180, got " + fmt(g[size_t(k)]));
    if (k > 0 && !(g[size_t(k)] > g[size_t(k) - 1]))
      throw InputError(in.loc(), "gamma angles must increase: " + fmt(g[size_t(k)]) + " follows " + fmt(g[size_t(k) - 1]));
  }
  return g;
}

struct StoredPlanes {
  std::vector<double> planes;
  PlaneSymmetry sym = PlaneSymmetry::kNone;
};

// Stored planes Mc1..Mc2 (1-based, wrapping past Mc for Isym 3) and the checks that they
// are the planes the symmetry needs. `cEndLine` is the line of the last C angle.
StoredPlanes storedPlanes(const std::vector<double>& c, int isym, const std::string& fileName, int cEndLine) {
  const int mc = int(c.size());
  std::vector<double> planes;
  PlaneSymmetry sym = PlaneSymmetry::kNone;
  const auto need = [&](size_t k, double deg) {
    if (std::fabs(c[k] - deg) > 1e-6)
      throw InputError(FileLoc{fileName, cEndLine - mc + 1 + int(k), 0},
                       "symmetry " + std::to_string(isym) + " needs C plane " + std::to_string(k + 1) +
                           " at " + fmt(deg) + " deg, got " + fmt(c[k]));
  };
  need(0, 0.0);
  switch (isym) {
    case 0: planes = c; break;
    case 1: planes = {0.0}; sym = PlaneSymmetry::kRotational; break;
    case 2:
      need(size_t(mc / 2), 180.0);
      planes.assign(c.begin(), c.begin() + mc / 2 + 1);
      sym = PlaneSymmetry::kMirrorC0C180;
      break;
    case 3:
      need(size_t(3) * size_t(mc) / 4, 270.0);
      need(size_t(mc / 4), 90.0);
      for (size_t k = size_t(3) * size_t(mc) / 4; k < size_t(mc); ++k) planes.push_back(c[k] - 360.0);  // C270..C345 as -90..-15
      for (int k = 0; k <= mc / 4; ++k) planes.push_back(c[size_t(k)]);
      sym = PlaneSymmetry::kMirrorC90C270;
      break;
    case 4:
      need(size_t(mc / 4), 90.0);
      planes.assign(c.begin(), c.begin() + mc / 4 + 1);
      sym = PlaneSymmetry::kQuadrant;
      break;
  }
  return StoredPlanes{std::move(planes), sym};
}

// cd/klm -> cd with the flux of lamp set 1 (its "total luminous flux of lamps", already the
// sum over its lamps). A negative lamp count marks absolute photometry: the flux field then
// holds the luminaire flux and the lamp lumens are unknown. Returns the factor cd/klm -> cd.
double applyLampSet1(PhotometricInfo& info, const std::string& fileName, int fluxLine) {
  const LampSet& set1 = info.lampSets.front();
  if (!(set1.totalFluxLm > 0.0))
    throw InputError(FileLoc{fileName, fluxLine, 0},
                     "total lamp flux of lamp set 1 must be positive, got " + fmt(set1.totalFluxLm));
  info.numLamps = std::abs(set1.count);
  info.lampLumens = set1.count < 0 ? -1.0 : set1.totalFluxLm;
  info.lumensPerLamp = set1.count > 0 ? set1.totalFluxLm / set1.count : -1.0;
  info.inputWatts = set1.wattsW;
  return set1.totalFluxLm / 1000.0 * info.conversionFactor;
}

// Line 30: `count` intensities (cd/klm), scaled to cd; nothing may follow them.
std::vector<double> readIntensities(LdtLines& in, size_t count, double scale) {
  std::vector<double> cd;
  cd.reserve(std::min(count, in.remaining()));  // a truncated file ends in its own error below
  for (size_t i = 0; i < count; ++i) {
    const double v = in.number("luminous intensity (cd/klm)");
    if (v < 0.0) throw InputError(in.loc(), "negative luminous intensity " + fmt(v));
    cd.push_back(v * scale);
  }
  if (!in.done()) {
    in.text("end of file");
    throw InputError(in.loc(), "unexpected line after the intensity table (check Mc, Ng and Isym)");
  }
  return cd;
}

}  // namespace

PhotometricWeb parseEulumdat(std::string_view text, const std::string& fileName) {
  LdtLines in(fileName, text);
  PhotometricInfo info;
  info.fileName = fileName;
  info.format = "EULUMDAT";
  info.numLamps = 0;

  const LdtShape shape = readIdentification(in, info);
  readDimensions(in, info);
  const int fluxLine = readLampData(in, info);
  const std::vector<double> c = readCAngles(in, shape.mc);
  const int cEndLine = in.loc().line;
  std::vector<double> g = readGammaAngles(in, shape.ng);
  StoredPlanes stored = storedPlanes(c, shape.isym, fileName, cEndLine);
  const double scale = applyLampSet1(info, fileName, fluxLine);
  std::vector<double> cd = readIntensities(in, stored.planes.size() * size_t(shape.ng), scale);
  return PhotometricWeb(std::move(info), PhotometricType::kC, stored.sym, std::move(stored.planes), std::move(g),
                        std::move(cd));
}

}  // namespace candela
