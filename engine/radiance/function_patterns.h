// brightfunc and colorfunc patterns and mixfunc mixtures of the function language (Radiance
// reference manual, "Brightfunc", "Colorfunc", "Mixfunc"): `mod brightfunc id 2+ refl funcfile
// transform 0 n A1..An`, `mod colorfunc id 4+ red green blue funcfile transform 0 n A1..An` and
// `mod mixfunc id 4+ foreground background vname funcfile transform 0 n A1..An`, each function an
// expression over the function file's names, evaluated at a hit by
// engine/materials/pattern_hook.h.
//
// Function files are found as Radiance finds them: a name relative to the working directory,
// then to each folder of RAYPATH (':'-separated), then to the folder of the file that names it;
// an absolute name or one with a '..' is refused (nothing outside those places is opened). Each
// file is read once; a later definition of a name replaces an earlier one (as in Radiance).
// rayinit.cal's definitions are built in (engine/radiance/cal/cal_library.cpp).
// The data patterns (brightdata, colordata, colorpict, mixdata, mixpict, texdata), spectra and
// the text patterns (brighttext, colortext, mixtext: engine/radiance/text_pattern.h) are read
// here too, their files (data, pictures, fonts, texts) through the same FunctionFiles.
#pragma once

#include "engine/radiance/parse.h"
#include "engine/radiance/cal/cal.h"
#include "engine/radiance/font.h"
#include "engine/scene.h"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class FunctionFiles {
 public:
  FunctionFiles();
  // The program every pattern's expressions are added to, shared with the scene.
  const std::shared_ptr<cal::Program>& program() const { return program_; }
  // Reads function file `name` (named by p; "." is none) into the program unless read before;
  // returns the path used ("" for ".").
  std::string load(const std::string& name, const RadPrimitive& p, const std::filesystem::path& folder);
  // A data file (.dat) or the three channels of a picture (.hdr) named by p, read once.
  std::shared_ptr<const RadDataArray> data(const std::string& name, const RadPrimitive& p,
                                           const std::filesystem::path& folder);
  std::array<std::shared_ptr<const RadDataArray>, 3> picture(const std::string& name, const RadPrimitive& p,
                                                             const std::filesystem::path& folder);
  // A hyperspectral picture (specpict: engine/radiance/picture.h), y, x and wavelength, read once.
  std::shared_ptr<const RadDataArray> hyperspectral(const std::string& name, const RadPrimitive& p,
                                                    const std::filesystem::path& folder);
  // A text pattern's font (engine/radiance/font.h) and text file (its lines), read once.
  std::shared_ptr<const RadFont> font(const std::string& name, const RadPrimitive& p,
                                      const std::filesystem::path& folder);
  std::shared_ptr<const std::vector<std::string>> textLines(const std::string& name, const RadPrimitive& p,
                                                            const std::filesystem::path& folder);
  // A window system's scattering (LBNL BSDF XML: engine/radiance/bsdf_xml.h) named by p, read once.
  std::shared_ptr<const Bsdf> bsdf(const std::string& name, const RadPrimitive& p, const std::filesystem::path& folder);
  // An expression of a pattern's function compiled and checked before (the same text means the
  // same names: a later definition replaces a name's meaning for every user alike), so that
  // thousands of patterns of one expression (gensurf -s's cells) share it; nullopt the first time.
  std::optional<cal::Symbol> compiled(const std::string& expression) const {
    const auto it = compiled_.find(expression);
    return it == compiled_.end() ? std::nullopt : std::optional<cal::Symbol>(it->second);
  }
  void remember(const std::string& expression, cal::Symbol symbol) { compiled_.emplace(expression, symbol); }
  // A model's root, looked in last for every file (engine/radiance/file_lookup.h).
  void setRoot(const std::filesystem::path& root) { root_ = root; }
  // The files read, in order (for summary.json).
  const std::vector<std::string>& files() const { return files_; }

 private:
  using Arrays = std::array<std::shared_ptr<const RadDataArray>, 3>;
  struct Read {
    std::string path;  // as found
    Arrays arrays;     // what a data file or picture holds (none for a function file)
    std::shared_ptr<const RadFont> font;                    // a font file's glyphs
    std::shared_ptr<const std::vector<std::string>> lines;  // a text file's lines
    std::shared_ptr<const Bsdf> bsdf;                       // a BSDF file's scattering
  };
  // Finds `name` (a `role`: "function file", "data file", "picture", "hyperspectral picture", "font
  // file", "text file") as
  // every file a scene names is found; the first time its canonical path is met in that role,
  // `read` reads it into the Read and the file is listed in files(); later, what was read then.
  const Read& once(const std::string& name, const RadPrimitive& p, const std::filesystem::path& folder,
                   const std::string& role, const std::function<void(const std::filesystem::path&, Read&)>& read);

  std::shared_ptr<cal::Program> program_;
  std::filesystem::path root_;
  std::map<std::string, Read> read_;  // by role and canonical path
  std::map<std::string, cal::Symbol> compiled_;  // functions' expressions compiled (compiled)
  std::map<std::string, bool> libraryChoice_;     // a library file (load) by name and folder: found?
  std::vector<std::string> files_;
};

// Whether p is a pattern or mixture candela evaluates at the pattern hook: brightfunc, colorfunc,
// mixfunc, and the data types brightdata (but source.cal's: engine/source_distribution.h),
// colordata, colorpict, mixdata, mixpict (with the function language); the text types
// brighttext, colortext, mixtext (engine/radiance/text_pattern.h).
bool isFunctionPattern(const RadPrimitive& p);
// Whether p is a mixture of two materials (mixfunc, mixdata, mixpict, mixtext).
bool isMixture(const RadPrimitive& p);
// Whether type t modifies a material's colour, brightness or normal, or mixes two materials.
bool isPatternType(const std::string& t);
// The patterns candela evaluates natively, by the function file they name (gensky's and
// gendaylit's sky functions, ies2rad's source.cal; docs/engine.md), else nullopt.
std::optional<PatternKind> implementedPattern(const RadPrimitive& p);
// The file a pattern needs, for messages: the picture of *pict types, the data file of *data
// types, the font of *text types, else the function file (Radiance reference manual, argument
// order of each type). "." is a function written inline.
std::string patternFile(const RadPrimitive& p);

// The pattern p describes, its expressions added to files.program() and checked (every name they
// reach defined, each used as it is defined): an InputError at p's line otherwise. `index` is the
// pattern's index in Scene::patterns, `next` the pattern modifying it (-1: none); `part` which
// of a material's patterns (BRTDfunc: 0 its specular reflectance, 1 its transmittance, 2 its
// directional functions).
ScenePattern readFunctionPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                                 int index, int next, int part = 0);

}  // namespace candela
