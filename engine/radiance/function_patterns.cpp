#include "engine/radiance/function_patterns.h"

#include "base/input_file.h"
#include "engine/radiance/bsdf_xml.h"
#include "engine/radiance/file_lookup.h"
#include "engine/radiance/picture.h"
#include "engine/radiance/spectrum.h"
#include "engine/radiance/text_pattern.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>
#include <unordered_map>

namespace candela {

FunctionFiles::FunctionFiles() : program_(std::make_shared<cal::Program>()) {}

const FunctionFiles::Read& FunctionFiles::once(const std::string& name, const RadPrimitive& p,
                                               const std::filesystem::path& folder, const std::string& role,
                                               const std::function<void(const std::filesystem::path&, Read&)>& read) {
  const std::filesystem::path path = findSceneFile(name, folder, p.loc, p.type + " '" + p.name + "'", role, root_);
  std::error_code ec;
  const std::string key = role + ":" + std::filesystem::weakly_canonical(path, ec).string();
  auto it = read_.find(key);
  if (it == read_.end()) {
    Read r{path.string(), {}, nullptr, nullptr, nullptr};
    read(path, r);
    files_.push_back(path.string());
    it = read_.emplace(key, std::move(r)).first;
  }
  return it->second;
}

std::string FunctionFiles::load(const std::string& name, const RadPrimitive& p, const std::filesystem::path& folder) {
  if (name == ".") return {};
  // A file of Radiance's library its generators name (surf.cal, ...): a copy found where files
  // are looked up is read; otherwise candela's own. Looked for once a name and folder (gensurf -s
  // names it for every cell).
  if (const std::optional<std::string_view> text = cal::libraryFile(name)) {
    const auto [choice, first] = libraryChoice_.emplace(name + '\n' + folder.string(), true);
    if (first) {
      try {
        findSceneFile(name, folder, p.loc, p.type + " '" + p.name + "'", "function file", root_);
      } catch (const InputError&) {
        choice->second = false;
      }
    }
    if (!choice->second) {
      const std::string used = name + " (built in)";
      if (read_.emplace("function file:" + used, Read{used, {}, nullptr, nullptr, nullptr}).second) {
        program_->addText(*text, used);
        files_.push_back(used);
      }
      return used;
    }
  }
  return once(name, p, folder, "function file", [this](const std::filesystem::path& path, Read&) {
           program_->addText(readInputFile(path, "function file"), path.string());
         }).path;
}

std::shared_ptr<const RadDataArray> FunctionFiles::data(const std::string& name, const RadPrimitive& p,
                                                        const std::filesystem::path& folder) {
  return once(name, p, folder, "data file", [&p](const std::filesystem::path& path, Read& r) {
           r.arrays = Arrays{std::make_shared<const RadDataArray>(readRadDataFile(path, p.loc))};
         }).arrays[0];
}

FunctionFiles::Arrays FunctionFiles::picture(const std::string& name, const RadPrimitive& p,
                                             const std::filesystem::path& folder) {
  return once(name, p, folder, "picture", [](const std::filesystem::path& path, Read& r) {
           std::array<RadDataArray, 3> rgb = readRadiancePicture(path);
           for (size_t c = 0; c < 3; ++c) r.arrays[c] = std::make_shared<const RadDataArray>(std::move(rgb[c]));
         }).arrays;
}

std::shared_ptr<const RadDataArray> FunctionFiles::hyperspectral(const std::string& name, const RadPrimitive& p,
                                                                 const std::filesystem::path& folder) {
  return once(name, p, folder, "hyperspectral picture", [](const std::filesystem::path& path, Read& r) {
           r.arrays = Arrays{std::make_shared<const RadDataArray>(readHyperspectralPicture(path))};
         }).arrays[0];
}

namespace {
// What a text pattern's file holds is read whole into memory; beyond these sizes it is refused
// (Radiance's own fonts are below 100 kB, its texts a few lines).
constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t(1) << 20;

// readInputFile's refusal (too large, unreadable) at the pattern's line, naming the file.
std::string readPatternFile(const std::filesystem::path& path, const RadPrimitive& p, const std::string& role,
                            std::uintmax_t maxBytes) {
  try {
    return readInputFile(path, role, maxBytes);
  } catch (const InputError& e) {
    throw InputError(p.loc, p.type + " '" + p.name + "': " + role + " '" + path.string() + "': " + e.message());
  }
}
}  // namespace

std::shared_ptr<const RadFont> FunctionFiles::font(const std::string& name, const RadPrimitive& p,
                                                   const std::filesystem::path& folder) {
  return once(name, p, folder, "font file", [&p](const std::filesystem::path& path, Read& r) {
           const std::string text = readPatternFile(path, p, "font file", kMaxFontFileBytes);
           r.font = std::make_shared<const RadFont>(parseRadianceFont(text, path.string()));
         }).font;
}

std::shared_ptr<const std::vector<std::string>> FunctionFiles::textLines(const std::string& name,
                                                                         const RadPrimitive& p,
                                                                         const std::filesystem::path& folder) {
  return once(name, p, folder, "text file", [&p](const std::filesystem::path& path, Read& r) {
           const std::string text = readPatternFile(path, p, "text file", kMaxTextFileBytes);
           r.lines = std::make_shared<const std::vector<std::string>>(textFileLines(text));
         }).lines;
}

std::shared_ptr<const Bsdf> FunctionFiles::bsdf(const std::string& name, const RadPrimitive& p,
                                                const std::filesystem::path& folder) {
  return once(name, p, folder, "BSDF file", [](const std::filesystem::path& path, Read& r) {
           r.bsdf = readBsdfXml(path);  // its errors at the XML's line
         }).bsdf;
}

namespace {
bool isDataPattern(const RadPrimitive& p) {
  return (p.type == "brightdata" && p.strings.size() >= 3 && p.strings[2] != "source.cal") ||
         p.type == "colordata" || p.type == "colorpict" || p.type == "mixdata" || p.type == "mixpict" ||
         p.type == "texdata";
}
}  // namespace

bool isFunctionPattern(const RadPrimitive& p) {
  return isTextPattern(p) || (p.type == "brightfunc" && p.strings.size() >= 2) || (p.type == "colorfunc" && p.strings.size() >= 4) ||
         (p.type == "mixfunc" && p.strings.size() >= 4) || (p.type == "texfunc" && p.strings.size() >= 4) ||
         p.type == "spectrum" || p.type == "specfile" || p.type == "specfunc" || p.type == "specdata" ||
         p.type == "specpict" || isDataPattern(p);
}

bool isMixture(const RadPrimitive& p) {
  return p.type == "mixfunc" || p.type == "mixdata" || p.type == "mixpict" || p.type == "mixtext";
}

bool isPatternType(const std::string& t) {
  static const char* const kTypes[] = {"brightfunc", "brightdata", "brighttext", "colorfunc", "colordata",
                                       "colorpict", "colortext",  "texfunc",    "texdata",   "mixfunc",
                                       "mixdata",   "mixpict",    "mixtext",    "specfunc",  "specdata",
                                       "specpict",  "spectrum",   "specfile"};
  return std::any_of(std::begin(kTypes), std::end(kTypes), [&](const char* k) { return t == k; });
}

std::optional<PatternKind> implementedPattern(const RadPrimitive& p) {
  if (p.type == "brightfunc" && p.strings.size() >= 2) {
    if (p.strings[0] == "skyfunc" || p.strings[1] == "skybright.cal") {
      if (p.strings[1] == "skybright.cal") return PatternKind::kSkyBright;
    }
    if (p.strings[1] == "perezlum.cal") return PatternKind::kPerezLum;
  }
  if (p.type == "brightdata" && p.strings.size() >= 3 && p.strings[2] == "source.cal") {
    const std::string& f = p.strings[0];
    if (f == "corr" || f == "flatcorr" || f == "boxcorr" || f == "cylcorr") return PatternKind::kSourceDistribution;
  }
  return std::nullopt;
}

std::string patternFile(const RadPrimitive& p) {
  static const std::unordered_map<std::string, size_t> kIndex = {
      {"brightfunc", 1}, {"colorfunc", 3}, {"texfunc", 3},   {"mixfunc", 3},   {"specfunc", 1},
      {"brightdata", 1}, {"colordata", 3}, {"texdata", 3},   {"mixdata", 3},   {"specdata", 1},
      {"colorpict", 3},  {"mixpict", 3},   {"specpict", 1},  {"brighttext", 0}, {"colortext", 0},
      {"mixtext", 2},    {"specfile", 0}};
  const auto it = kIndex.find(p.type);
  if (it == kIndex.end() || p.strings.size() <= it->second) return {};
  return p.strings[it->second];
}

namespace {

// spectrum (`0 0 5+ nmA nmB s1 … sN`: values evenly spaced from nmA to nmB nm) and specfile (`1
// file 0 0`: a one-dimensional data file over wavelength): the spectrum as an RGB colour.
ScenePattern readSpectrumPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                                 ScenePattern sp) {
  const std::string what = p.type + " '" + p.name + "'";
  sp.constant = true;
  sp.channels = 3;
  if (p.type == "spectrum") {
    if (!p.strings.empty() || p.reals.size() < 5)
      throw InputError(p.loc, what + " needs no string and 5 or more real arguments (nmA nmB s1 s2 s3 ...), got " +
                                  std::to_string(p.strings.size()) + " and " + std::to_string(p.reals.size()));
    const double a = p.reals[0], b = p.reals[1];
    if (!(std::isfinite(a) && std::isfinite(b) && a > 0.0 && b > 0.0 && a != b && a < 1e4 && b < 1e4))
      throw InputError(p.loc, what + ": its wavelengths must be two different positive numbers of nm, got " +
                                  compactNumber(a) + " and " + compactNumber(b));
    const std::vector<double> v(p.reals.begin() + 2, p.reals.end());
    for (double x : v)
      if (!(x >= 0.0 && x <= 1e30)) throw InputError(p.loc, what + ": a value is negative or not a number");
    const double step = (b - a) / static_cast<double>(v.size() - 1);
    sp.constantColour = spectrumToRgb(
        [&](double nm) {
          const double t = std::clamp((nm - a) / step, 0.0, static_cast<double>(v.size() - 1));
          const size_t i = std::min(static_cast<size_t>(t), v.size() - 2);
          return v[i] + (t - static_cast<double>(i)) * (v[i + 1] - v[i]);
        },
        a, b);
    return sp;
  }
  if (p.strings.size() != 1 || !p.reals.empty())
    throw InputError(p.loc, what + " needs its data file as its one string argument and no real argument");
  const std::shared_ptr<const RadDataArray> d = files.data(p.strings[0], p, folder);
  if (d->dimensions() != 1)
    throw InputError(p.loc, what + ": its data file '" + p.strings[0] + "' must have one dimension (wavelength), has " +
                                std::to_string(d->dimensions()));
  const RadDataArray::Axis& axis = d->axes[0];
  const double a = axis.points.empty() ? axis.begin : axis.points.front();
  const double b = axis.points.empty() ? axis.end : axis.points.back();
  sp.constantColour = spectrumToRgb([&](double nm) { return std::max(0.0, d->value(&nm)); }, a, b);
  return sp;
}

// The wavelengths at which specfunc evaluates its function: evenly spaced at most this far apart
// (nm), CIE 15's interval for colorimetric sums; the reduction's error against 1 nm steps is
// bounded in tests/engine/radiance/spectral_patterns_test.cpp.
constexpr double kSpecfuncStepNm = 5.0;

// specfunc (`2+ sfunc funcfile transform 0 2+ nmA nmB A3 …`, Radiance's p_func.c p_specfunc),
// specdata (`4+ sfunc datafile funcfile x1 … xn transform`, its data over n coordinates and then
// wavelength, p_data.c p_specdata) and specpict (`5+ sfunc picture funcfile u v transform`, a
// hyperspectral picture over its y, x and wavelength, p_data.c p_specpict): a spectrum of the ray,
// sfunc(nm) or sfunc(value, nm), reduced to RGB at each hit as a spectrum of those values at the
// nodes (spectrumNodeWeights): specdata's the data's wavelengths, specpict's the centres of the
// picture's bands.
ScenePattern readSpectralPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                                 ScenePattern sp, int index) {
  const std::string what = p.type + " '" + p.name + "'";
  const bool picture = p.type == "specpict";
  const bool data = p.type == "specdata" || picture;
  const size_t fileAt = data ? 2 : 1;
  const size_t minimum = picture ? 5 : fileAt + 1;
  if (p.strings.size() < minimum)
    throw InputError(p.loc, what + " needs " + std::to_string(minimum) + " or more string arguments (" +
                                (picture ? "sfunc picture funcfile u v [transform]"
                                 : data  ? "sfunc datafile funcfile x1 .. xn [transform]"
                                         : "sfunc funcfile [transform]") +
                                "), got " + std::to_string(p.strings.size()));
  files.load(p.strings[fileAt], p, folder);
  size_t at = fileAt + 1;
  if (data) {
    sp.data[0] = picture ? files.hyperspectral(p.strings[1], p, folder) : files.data(p.strings[1], p, folder);
    const RadDataArray& d = *sp.data[0];
    if (d.dimensions() < 2)
      throw InputError(p.loc, what + ": its data file '" + p.strings[1] + "' needs 2 or more dimensions (the last "
                                  "wavelength), has " + std::to_string(d.dimensions()));
    const size_t dims = static_cast<size_t>(d.dimensions()) - 1;
    if (p.strings.size() < at + dims)
      throw InputError(p.loc, what + " needs a coordinate for each of its data's " + std::to_string(dims) +
                                  " dimensions before wavelength, got " + std::to_string(p.strings.size() - at));
    // A picture's coordinates are u (along x) then v (along y), its data y then x (p_specpict).
    std::vector<std::string> coordinates(p.strings.begin() + static_cast<long>(at),
                                         p.strings.begin() + static_cast<long>(at + dims));
    if (picture) std::reverse(coordinates.begin(), coordinates.end());
    for (size_t k = 0; k < dims; ++k, ++at) {
      const std::string& text = coordinates[k];
      const std::string label = "`pattern" + std::to_string(index) + ".x" + std::to_string(k);
      try {
        sp.coordinates.push_back(files.program()->addExpression(text, label, p.loc));
      } catch (const InputError& e) {
        throw InputError(p.loc, what + ": its coordinate '" + text + "' is not an expression: " + e.message());
      }
      files.program()->check(label, -1, p.loc, text);
    }
    const RadDataArray::Axis& axis = d.axes.back();
    for (int k = 0; k < axis.count; ++k)
      sp.spectralNodesNm.push_back(axis.points.empty() ? axis.begin + (axis.end - axis.begin) * k / (axis.count - 1)
                                                       : axis.points[static_cast<size_t>(k)]);
    if (sp.spectralNodesNm.front() > sp.spectralNodesNm.back())
      std::reverse(sp.spectralNodesNm.begin(), sp.spectralNodesNm.end());
  } else {
    if (p.reals.size() < 2)
      throw InputError(p.loc, what + " needs 2 or more real arguments (nmA nmB A3 ..), got " +
                                  std::to_string(p.reals.size()));
    // Radiance's range of wavelengths, 380–780 nm (WLPART), outside which nothing is seen.
    const double lo = std::max(380.0, std::min(p.reals[0], p.reals[1]));
    const double hi = std::min(780.0, std::max(p.reals[0], p.reals[1]));
    if (!(lo < hi))
      throw InputError(p.loc, what + ": its wavelengths " + compactNumber(p.reals[0]) + " to " +
                                  compactNumber(p.reals[1]) + " nm leave nothing of 380-780 nm");
    const int steps = static_cast<int>(std::ceil((hi - lo) / kSpecfuncStepNm - 1e-9));
    for (int k = 0; k <= steps; ++k) sp.spectralNodesNm.push_back(lo + (hi - lo) * k / steps);
  }
  RadTransform toWorld;
  const size_t end = parseRadTransform(p.strings, at, toWorld, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] + "' is not " + (data ? "a coordinate or " : "") +
                                "a transform option (-t x y z, -rx/-ry/-rz deg, -s f, -mx/-my/-mz, -i N)");
  sp.toFunction = toWorld.inverse();
  sp.toWorld = toWorld;
  sp.functionScale = std::abs(toWorld.scale);
  const std::string& name = p.strings[0];
  const int args = data ? 2 : 1;
  if (!cal::isName(name))
    throw InputError(p.loc, what + ": '" + name + "' must name a function of " +
                                (data ? "the value and the wavelength (nm)" : "the wavelength (nm)"));
  files.program()->check(name, args, p.loc);
  sp.functions[0] = files.program()->find(name);
  sp.channels = 3;
  sp.spectralWeights = spectrumNodeWeights(sp.spectralNodesNm);
  return sp;
}

// brightdata, colordata, colorpict, mixdata, mixpict (Radiance's p_data.c and mx_data.c): the
// functions called with the looked-up value(s), the data (files or a picture), the function file,
// one coordinate a dimension (a picture: u v), then the transform.
ScenePattern readDataPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                             ScenePattern sp, int index) {
  const std::string what = p.type + " '" + p.name + "'";
  const bool mixture = p.type == "mixdata" || p.type == "mixpict";
  const bool picture = p.type == "colorpict" || p.type == "mixpict";
  const bool colour = p.type == "colordata" || p.type == "colorpict" || p.type == "texdata";
  const size_t first = mixture ? 2 : 0;                       // the first value function
  const size_t nFunctions = colour ? 3 : 1;
  const size_t nData = p.type == "colordata" || p.type == "texdata" ? 3 : 1;
  sp.texture = p.type == "texdata";
  const size_t dataAt = first + nFunctions, fileAt = dataAt + nData;
  auto need = [&](size_t n, const char* layout) {
    if (p.strings.size() < n)
      throw InputError(p.loc, what + " needs " + std::to_string(n) + " or more string arguments (" + layout +
                                  "), got " + std::to_string(p.strings.size()));
  };
  static const std::map<std::string, const char*> kLayout = {
      {"brightdata", "func datafile funcfile x1 .. xn [transform]"},
      {"colordata", "rfunc gfunc bfunc rdatafile gdatafile bdatafile funcfile x1 .. xn [transform]"},
      {"texdata", "xfunc yfunc zfunc xdatafile ydatafile zdatafile funcfile x1 .. xn [transform]"},
      {"colorpict", "rfunc gfunc bfunc pictfile funcfile u v [transform]"},
      {"mixdata", "foreground background func datafile funcfile x1 .. xn [transform]"},
      {"mixpict", "foreground background func pictfile funcfile u v [transform]"}};
  need(fileAt + 1, kLayout.at(p.type));
  files.load(p.strings[fileAt], p, folder);
  if (picture) {
    sp.data = files.picture(p.strings[dataAt], p, folder);
    sp.picture = true;
  } else {
    for (size_t k = 0; k < nData; ++k) sp.data[k] = files.data(p.strings[dataAt + k], p, folder);
    for (size_t k = 1; k < nData; ++k)
      if (sp.data[k]->dimensions() != sp.data[0]->dimensions())
        throw InputError(p.loc, what + ": its data files have different numbers of dimensions");
  }
  const size_t dims = picture ? 2 : static_cast<size_t>(sp.data[0]->dimensions());
  need(fileAt + 1 + dims, kLayout.at(p.type));
  for (size_t k = 0; k < dims; ++k) {
    const std::string& expression = p.strings[fileAt + 1 + k];
    const std::string label = "`pattern" + std::to_string(index) + ".x" + std::to_string(k);
    try {
      sp.coordinates.push_back(files.program()->addExpression(expression, label, p.loc));
    } catch (const InputError& e) {
      throw InputError(p.loc, what + ": its coordinate '" + expression + "' is not an expression: " + e.message());
    }
    files.program()->check(label, -1, p.loc, expression);
  }
  RadTransform toWorld;
  const size_t end = parseRadTransform(p.strings, fileAt + 1 + dims, toWorld, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] + "' is not a coordinate or a transform option (the data " +
                                "have " + std::to_string(dims) + " dimensions)");
  sp.toFunction = toWorld.inverse();
  sp.toWorld = toWorld;
  sp.functionScale = std::abs(toWorld.scale);
  // The value functions: names of functions taking the looked-up value(s).
  const int args = nData == 3 || picture ? 3 : 1;
  sp.channels = static_cast<int>(nFunctions);
  for (size_t k = 0; k < nFunctions; ++k) {
    const std::string& name = p.strings[first + k];
    if (!cal::isName(name))
      throw InputError(p.loc, what + ": '" + name + "' must name a function of " + std::to_string(args) +
                                  (args == 1 ? " argument" : " arguments"));
    files.program()->check(name, args, p.loc);
    sp.functions[k] = files.program()->find(name);
  }
  return sp;
}

// Names a function of the light's direction: a plain name defined with at least `args`
// parameters (Radiance's funvalue calls it with them; extra arguments are unused).
cal::Symbol directionalFunction(const RadPrimitive& p, FunctionFiles& files, const std::string& name, int args,
                                const std::string& role) {
  const std::string what = p.type + " '" + p.name + "'";
  if (!cal::isName(name))
    throw InputError(p.loc, what + ": its " + role + " '" + name + "' must name a function of " +
                                (args == 4 ? "the light's direction (lx, ly, lz, omega)"
                                           : "the value looked up and the light's direction (v, lx, ly, lz, omega)"));
  files.program()->check(name, args, p.loc);
  return files.program()->find(name);
}

// The functions of a light source's direction (Radiance's dirbrdf, src/rt/m_brdf.c):
// plasfunc, metfunc, transfunc `2+ refl funcfile transform`; plasdata, metdata, transdata `4+ func
// datafile funcfile x1 … xn transform` (each xi a function of the direction, func one of the value
// looked up and the direction); BRTDfunc's rbrtd gbrtd bbrtd (0: none).
ScenePattern readDirectionalPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                                    ScenePattern sp) {
  const std::string what = p.type + " '" + p.name + "'";
  const bool brtd = p.type == "BRTDfunc";
  const bool data = p.type == "plasdata" || p.type == "metdata" || p.type == "transdata";
  const size_t fileAt = brtd ? 9 : data ? 2 : 1;
  if (p.strings.size() < fileAt + 1)
    throw InputError(p.loc, what + " needs " + std::to_string(fileAt + 1) + " or more string arguments (" +
                                (data ? "func datafile funcfile x1 .. xn [transform]" : "refl funcfile [transform]") +
                                "), got " + std::to_string(p.strings.size()));
  files.load(p.strings[fileAt], p, folder);
  size_t next = fileAt + 1;
  sp.channels = brtd ? 3 : 1;
  if (brtd) {
    for (size_t k = 0; k < 3; ++k)
      if (p.strings[6 + k] != "0")
        sp.functions[k] = directionalFunction(p, files, p.strings[6 + k], 4, "directional function");
  } else if (data) {
    sp.data[0] = files.data(p.strings[1], p, folder);
    const size_t dims = static_cast<size_t>(sp.data[0]->dimensions());
    if (p.strings.size() < next + dims)
      throw InputError(p.loc, what + ": its data file '" + p.strings[1] + "' has " + std::to_string(dims) +
                                  " dimensions: give as many coordinate functions after the function file");
    for (size_t k = 0; k < dims; ++k)
      sp.coordinates.push_back(directionalFunction(p, files, p.strings[next + k], 4, "coordinate"));
    next += dims;
    sp.functions[0] = directionalFunction(p, files, p.strings[0], 5, "function");
  } else {
    sp.functions[0] = directionalFunction(p, files, p.strings[0], 4, "function");
  }
  RadTransform toWorld;
  const size_t end = parseRadTransform(p.strings, next, toWorld, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] +
                                "' is not a transform option (-t x y z, -rx/-ry/-rz deg, -s f, -mx/-my/-mz, -i N)");
  sp.toFunction = toWorld.inverse();
  sp.toWorld = toWorld;
  sp.functionScale = std::abs(toWorld.scale);
  return sp;
}

}  // namespace

ScenePattern readFunctionPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                                 int index, int next, int part) {
  const std::string what = p.type + " '" + p.name + "'";
  ScenePattern sp;
  sp.kind = PatternKind::kFunction;
  sp.type = p.type;
  sp.name = p.name;
  sp.loc = p.loc;
  sp.strings = p.strings;
  sp.reals = p.reals;
  sp.args = p.reals;
  sp.next = next;
  if (isDataPattern(p)) return readDataPattern(p, files, folder, std::move(sp), index);
  if (isTextPattern(p)) return readTextPattern(p, files, folder, std::move(sp));
  if (p.type == "spectrum" || p.type == "specfile") return readSpectrumPattern(p, files, folder, std::move(sp));
  if ((p.type == "BRTDfunc" && part == 2) || p.type == "plasfunc" || p.type == "metfunc" || p.type == "transfunc" ||
      p.type == "plasdata" || p.type == "metdata" || p.type == "transdata")
    return readDirectionalPattern(p, files, folder, std::move(sp));
  if (p.type == "specfunc" || p.type == "specdata" || p.type == "specpict")
    return readSpectralPattern(p, files, folder, std::move(sp), index);
  // brightfunc: refl file; colorfunc: red green blue file; mixfunc: foreground background vname
  // file; plastic2, metal2, trans2, ashik2: ux uy uz file; BRTDfunc: its specular reflectance (part 0)
  // and transmittance (part 1) of rrefl grefl brefl rtrns gtrns btrns rbrtd gbrtd bbrtd file.
  const bool mixture = p.type == "mixfunc";
  // BSDF: thick file ux uy uz funcfile; aBSDF: file ux uy uz funcfile (the up vector).
  const size_t vectorAt = p.type == "BSDF" ? 2 : p.type == "aBSDF" ? 1 : 0;
  const bool vector = p.type == "plastic2" || p.type == "metal2" || p.type == "trans2" || p.type == "ashik2" || vectorAt > 0;
  sp.texture = p.type == "texfunc";  // xpert ypert zpert funcfile
  const bool brtd = p.type == "BRTDfunc";
  // WGMDfunc: rs rs_urough rs_vrough (part 0), ts ts_urough ts_vrough (part 1), ux uy uz (part 2)
  // of rs_mod rs rs_urough rs_vrough ts_mod ts ts_urough ts_vrough td_mod ux uy uz file.
  const bool wgmd = p.type == "WGMDfunc";
  if (wgmd && p.strings.size() < 13)
    throw InputError(p.loc, what + " needs 13 or more string arguments (rs_mod rs rs_urough rs_vrough ts_mod ts "
                                   "ts_urough ts_vrough td_mod ux uy uz funcfile [transform]), got " +
                                std::to_string(p.strings.size()));
  if (vector && p.strings.size() < 4 + vectorAt)
    throw InputError(p.loc, what + " needs " + std::to_string(4 + vectorAt) + " or more string arguments (" +
                                (p.type == "BSDF" ? "thick BSDFfile " : vectorAt ? "BSDFfile " : "") +
                                "ux uy uz funcfile [transform]), got " + std::to_string(p.strings.size()));
  if (brtd && p.strings.size() < 10)
    throw InputError(p.loc, what + " needs 10 or more string arguments (rrefl grefl brefl rtrns gtrns btrns rbrtd "
                                   "gbrtd bbrtd funcfile [transform]), got " + std::to_string(p.strings.size()));
  sp.channels = p.type == "colorfunc" || vector || brtd || wgmd || sp.texture ? 3 : 1;
  const size_t firstFunction =
      mixture ? 2 : brtd ? 3 * static_cast<size_t>(part) : wgmd ? 4 * static_cast<size_t>(part) + 1 : vectorAt;
  const size_t fileAt = brtd ? 9 : wgmd ? 12 : firstFunction + static_cast<size_t>(sp.channels);
  files.load(p.strings[fileAt], p, folder);
  RadTransform toWorld;
  const size_t end = parseRadTransform(p.strings, fileAt + 1, toWorld, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] +
                                "' is not a transform option (-t x y z, -rx/-ry/-rz deg, -s f, -mx/-my/-mz, -i N)");
  sp.toFunction = toWorld.inverse();
  sp.toWorld = toWorld;
  sp.functionScale = std::abs(toWorld.scale);
  // Each function is an expression (a name, or written inline), a definition of its own.
  static const char* const kChannel[] = {"red", "green", "blue"};
  static const char* const kAxis[] = {"ux", "uy", "uz"};
  static const char* const kPert[] = {"xpert", "ypert", "zpert"};
  static const char* const kBrtd[] = {"rrefl", "grefl", "brefl", "rtrns", "gtrns", "btrns"};
  static const char* const kWgmd[] = {"rs", "rs_urough", "rs_vrough", "ts", "ts_urough", "ts_vrough", "ux", "uy", "uz"};
  for (int k = 0; k < sp.channels; ++k) {
    const std::string label = "`pattern" + std::to_string(index) + "." + std::to_string(k);
    const std::string& expression = p.strings[firstFunction + static_cast<size_t>(k)];
    if (const std::optional<cal::Symbol> known = files.compiled(expression)) {
      sp.functions[static_cast<size_t>(k)] = *known;
      continue;
    }
    try {
      sp.functions[static_cast<size_t>(k)] = files.program()->addExpression(expression, label, p.loc);
    } catch (const InputError& e) {
      throw InputError(p.loc, what + ": " +
                                  (sp.channels == 1 ? "its function"
                                   : brtd           ? std::string("its ") + kBrtd[firstFunction + static_cast<size_t>(k)]
                                   : wgmd           ? std::string("its ") + kWgmd[3 * static_cast<size_t>(part) + static_cast<size_t>(k)]
                                                    : std::string(vector ? kAxis[k] : sp.texture ? kPert[k] : kChannel[k]) +
                                                          " function") +
                                  " '" + expression + "' is not an expression: " + e.message());
    }
    // A plain name is checked as itself (its messages name it); an expression as a whole.
    if (cal::isName(expression)) files.program()->check(expression, -1, p.loc);
    files.program()->check(label, -1, p.loc, expression);
    files.remember(expression, sp.functions[static_cast<size_t>(k)]);
  }
  return sp;
}

}  // namespace candela
