#include "engine/radiance/function_patterns.h"

#include "base/input_file.h"
#include "engine/radiance/file_lookup.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace candela {

FunctionFiles::FunctionFiles() : program_(std::make_shared<cal::Program>()) {}

std::string FunctionFiles::load(const std::string& name, const RadPrimitive& p, const std::filesystem::path& folder) {
  if (name == ".") return {};
  const std::filesystem::path path = findSceneFile(name, folder, p.loc, p.type + " '" + p.name + "'", "function file");
  std::error_code ec;
  const std::string key = std::filesystem::weakly_canonical(path, ec).string();
  if (!loaded_.count(key)) {
    loaded_[key] = true;
    files_.push_back(path.string());
    program_->addText(readInputFile(path, "function file"), path.string());
  }
  return path.string();
}

bool isFunctionPattern(const RadPrimitive& p) {
  return (p.type == "brightfunc" && p.strings.size() >= 2) || (p.type == "colorfunc" && p.strings.size() >= 4) ||
         (p.type == "mixfunc" && p.strings.size() >= 4);
}

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
  // brightfunc: refl file; colorfunc: red green blue file; mixfunc: foreground background vname
  // file; plastic2, metal2, trans2: ux uy uz file; BRTDfunc: its specular reflectance (part 0)
  // and transmittance (part 1) of rrefl grefl brefl rtrns gtrns btrns rbrtd gbrtd bbrtd file.
  const bool mixture = p.type == "mixfunc";
  const bool vector = p.type == "plastic2" || p.type == "metal2" || p.type == "trans2";
  const bool brtd = p.type == "BRTDfunc";
  if (vector && p.strings.size() < 4)
    throw InputError(p.loc, what + " needs 4 or more string arguments (ux uy uz funcfile [transform]), got " +
                                std::to_string(p.strings.size()));
  if (brtd && p.strings.size() < 10)
    throw InputError(p.loc, what + " needs 10 or more string arguments (rrefl grefl brefl rtrns gtrns btrns rbrtd "
                                   "gbrtd bbrtd funcfile [transform]), got " + std::to_string(p.strings.size()));
  sp.channels = p.type == "colorfunc" || vector || brtd ? 3 : 1;
  const size_t firstFunction = mixture ? 2 : brtd ? 3 * static_cast<size_t>(part) : 0;
  const size_t fileAt = brtd ? 9 : firstFunction + static_cast<size_t>(sp.channels);
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
  static const char* const kBrtd[] = {"rrefl", "grefl", "brefl", "rtrns", "gtrns", "btrns"};
  for (int k = 0; k < sp.channels; ++k) {
    const std::string label = "`pattern" + std::to_string(index) + "." + std::to_string(k);
    const std::string& expression = p.strings[firstFunction + static_cast<size_t>(k)];
    try {
      sp.functions[static_cast<size_t>(k)] = files.program()->addExpression(expression, label, p.loc);
    } catch (const InputError& e) {
      throw InputError(p.loc, what + ": " +
                                  (sp.channels == 1 ? "its function"
                                   : brtd           ? std::string("its ") + kBrtd[firstFunction + static_cast<size_t>(k)]
                                                    : std::string(vector ? kAxis[k] : kChannel[k]) + " function") +
                                  " '" + expression + "' is not an expression: " + e.message());
    }
    // A plain name is checked as itself (its messages name it); an expression as a whole.
    if (cal::isName(expression)) files.program()->check(expression, -1, p.loc);
    files.program()->check(label, -1, p.loc, expression);
  }
  return sp;
}

}  // namespace candela
