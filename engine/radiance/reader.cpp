#include "engine/radiance/reader.h"

#include "base/input_file.h"
#include "base/units.h"
#include "engine/antimatter.h"
#include "engine/obj_reader.h"
#include "engine/materials/family.h"
#include "engine/radiance/file_lookup.h"
#include "engine/radiance/function_patterns.h"
#include "engine/radiance/generators.h"
#include "engine/radiance/polygon_reader.h"
#include "engine/radiance/sky.h"
#include "engine/source_distribution.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace candela {

namespace {
// Files included by generators (xform) nest at most this deep: a file that includes itself is
// refused at this depth instead of recursing without end.
constexpr int kMaxIncludeDepth = 32;

// The types read, for the message that refuses another: the materials are the registry's.
std::string supportedTypes() {
  return "supported: polygon, sphere, bubble, ring, cone, cup, cylinder, tube, source, mesh (of an OBJ file); " +
         materialTypeNames() + ", mixfunc; alias; patterns: see docs/engine.md";
}

using Primitive = RadPrimitive;
}  // namespace

class SceneReader::Builder {
 public:
  Builder(Scene& scene, SceneReadOptions options) : scene_(scene), options_(options) {
    functionFiles_.setRoot(options_.rootFolder);
    for (size_t i = 0; i < scene.materials.size(); ++i) materials_[scene.materials[i].name] = static_cast<int>(i);
  }

  // Parses a file's text, expands its commands (recursively, files relative to `folder`) and
  // passes every primitive to `sink` in order.
  void expand(std::string_view text, const std::string& fileName, const std::filesystem::path& folder, int depth,
              const std::function<void(RadPrimitive&&)>& sink) {
    RadExpandContext ctx;
    ctx.folder = folder;
    ctx.root = options_.rootFolder;
    ctx.maxMemoryBytes = options_.maxMemoryBytes;
    ctx.warnings = &scene_.inputWarnings;
    ctx.readFile = [this, depth](const std::filesystem::path& file, const FileLoc& from) {
      if (depth + 1 > kMaxIncludeDepth)
        throw InputError(from, "files include each other more than " + std::to_string(kMaxIncludeDepth) +
                                   " levels deep (does a file include itself?)");
      std::vector<RadPrimitive> out;
      const std::string text = readInputFile(file, "scene file");
      expand(text, file.string(), file.parent_path(), depth + 1, [&out](RadPrimitive&& p) { out.push_back(std::move(p)); });
      return out;
    };
    parseRadiance(text, fileName, sink, [&](RadCommand&& cmd) {
      for (RadPrimitive& p : expandRadCommand(cmd, ctx)) sink(std::move(p));
    });
  }

  void read(std::string_view text, const std::string& fileName, const std::filesystem::path& folder) {
    topFile_ = fileName;
    topFolder_ = folder;
    expand(text, fileName, folder, 0, [this](RadPrimitive&& p) { add(p); });
    sky_.apply(scene_);
    polygons_.flush(scene_.inputWarnings);
  }

  // An OBJ file with the modifiers defined so far (obj2rad's naming rules, or the mapping file).
  void readObj(const std::filesystem::path& path, ObjReadOptions opt = {}) {
    if (!options_.objMapping.empty() && !mapping_) mapping_ = readObjMapping(options_.objMapping);
    if (!opt.forcedModifier && mapping_) opt.mapping = &*mapping_;
    opt.resolve = [this](const std::string& name, const std::string& why, const FileLoc& where) {
      return objModifier(name, why, where);
    };
    readObjFile(path, scene_, opt);
  }

 private:
  [[noreturn]] void fail(const Primitive& p, const std::string& msg) { throw InputError(p.loc, msg); }

  void expectReals(const Primitive& p, size_t n) {
    if (p.reals.size() != n)
      fail(p, p.type + " '" + p.name + "' needs " + std::to_string(n) + " real arguments, got " +
                       std::to_string(p.reals.size()));
  }
  void expectStrings(const Primitive& p, size_t maxN) {
    if (p.strings.size() > maxN)
      fail(p, p.type + " '" + p.name + "' takes at most " + std::to_string(maxN) + " string arguments, got " +
                       std::to_string(p.strings.size()));
  }

  Vec3 vec(const Primitive& p, size_t i) const { return Vec3(p.reals[i], p.reals[i + 1], p.reals[i + 2]); }

  // A material or pattern candela cannot use is refused only when something uses it (shared
  // material libraries define dozens): its refusal is kept under its name until then.
  void defer(const std::string& name, const InputError& refusal) {
    deferred_.insert_or_assign(name, refusal);
    materials_.erase(name);
    patterns_.erase(name);
  }
  void defer(const Primitive& p, const std::string& message) { defer(p.name, InputError(p.loc, message)); }
  // Throws the kept refusal of `name`, saying what uses it, if it has one.
  void refuseIfDeferred(const std::string& name, const std::string& user) const {
    const auto d = deferred_.find(name);
    if (d != deferred_.end()) throw InputError(d->second.loc(), d->second.message() + " (used by " + user + ")");
  }
  static std::string userOf(const Primitive& p) {
    return p.type + " '" + p.name + "' at line " + std::to_string(p.loc.line);
  }

  // The material a surface's modifier names (-1: void), through patterns replaced by their base.
  int modifierOf(const Primitive& p) {
    std::string name = p.modifier;
    for (;;) {
      if (name == "void") return -1;
      const auto it = materials_.find(name);
      if (it != materials_.end()) return it->second;
      const auto pt = patterns_.find(name);
      refuseIfDeferred(name, userOf(p));
      if (pt == patterns_.end())
        fail(p, "modifier '" + p.modifier + "' of " + p.type + " '" + p.name + "' is not defined before use");
      if (pt->second.pattern >= 0)
        fail(p, p.type + " '" + p.name + "' has the pattern '" + name +
                    "' as its modifier: a pattern modifies a material, which surfaces then use");
      name = pt->second.base;
    }
  }

  // The material an OBJ face's modifier name stands for (-1: void), as modifierOf.
  int objModifier(const std::string& name, const std::string& why, const FileLoc& where) {
    std::string n = name;
    for (;;) {
      if (n == "void") return -1;
      const auto it = materials_.find(n);
      if (it != materials_.end()) {
        if (const ScenePattern* sky = skyPatternOf(it->second))
          throw InputError(where, "modifier '" + name + "' (" + why + ") is modified by the sky function '" +
                                      sky->name + "' (" + sky->strings[1] + "): candela evaluates sky functions on "
                                      "the sky and ground `source` hemispheres only");
        return it->second;
      }
      const auto pt = patterns_.find(n);
      refuseIfDeferred(n, "an OBJ face at " + where.file + ":" + std::to_string(where.line));
      if (pt == patterns_.end())
        throw InputError(where, "modifier '" + name + "' (" + why +
                                    ") is not defined in the Radiance files read before: define it in a .rad "
                                    "file given with the OBJ file, or map names with an obj2rad mapping file");
      if (pt->second.pattern >= 0)
        throw InputError(where, "modifier '" + name + "' (" + why +
                                    ") is a pattern: a pattern modifies a material, which faces then use");
      n = pt->second.base;
    }
  }

  // The folder a primitive's files are relative to: its own file's.
  std::filesystem::path folderOf(const Primitive& p) const {
    return p.loc.file == topFile_ ? topFolder_ : std::filesystem::path(p.loc.file).parent_path();
  }

  // `mod mesh id 1+ file [transform]` (Radiance reference manual, "Mesh"): an OBJ file is read
  // with the transform applied; a void modifier lets the faces' own names apply, any other
  // replaces them all (obj2mesh.1). Compiled meshes (.rtm) are refused: candela reads the source.
  void addMesh(const Primitive& p) {
    if (p.strings.empty()) fail(p, "mesh '" + p.name + "' needs its file as first string argument");
    const std::string& file = p.strings[0];
    const std::string ext = lower(std::filesystem::path(file).extension().string());
    std::string objFile = file;
    if (ext == ".rtm" || ext == ".msh") {
      // The OBJ file obj2mesh compiled it from, when it lies beside it (same name, .obj), is read
      // in its place with a warning; otherwise the mesh is refused.
      const std::filesystem::path beside = std::filesystem::path(file).replace_extension(".obj");
      try {
        findSceneFile(beside.string(), folderOf(p), p.loc, "mesh '" + p.name + "'", "OBJ file", options_.rootFolder);
      } catch (const InputError&) {
        fail(p, "mesh '" + p.name + "' names a Radiance compiled mesh (" + file +
                    "); pass its source OBJ file instead (mesh ... model.obj, the file obj2mesh compiled it from)");
      }
      scene_.inputWarnings.push_back(Warning{
          "compiled_mesh_replaced",
          "mesh '" + p.name + "' names the compiled mesh " + file + ": the OBJ file beside it, " + beside.string() +
              ", is read in its place (its materials by its usemtl names unless the mesh has a modifier)",
          p.loc});
      objFile = beside.string();
    }
    const std::string& fileRead = objFile;
    if (!isObjPath(fileRead))
      fail(p, "mesh '" + p.name + "' names '" + fileRead + "', which is not an OBJ file (.obj)");
    if (!p.reals.empty()) fail(p, "mesh '" + p.name + "' takes no real arguments, got " + std::to_string(p.reals.size()));
    ObjReadOptions opt;
    const size_t end = parseRadTransform(p.strings, 1, opt.transform, p.loc, "mesh '" + p.name + "'");
    if (end != p.strings.size())
      fail(p, "mesh '" + p.name + "': '" + p.strings[end] +
                  "' is not a transform option (-t x y z, -rx/-ry/-rz deg, -s f, -mx/-my/-mz, -i N)");
    if (p.modifier != "void") {
      modifierOf(p);  // defined before use, as every modifier
      opt.forcedModifier = p.modifier;
    }
    const std::filesystem::path path = findSceneFile(fileRead, folderOf(p), p.loc, "mesh '" + p.name + "'", "OBJ file", options_.rootFolder);
    try {
      checkInputFile(path, "OBJ file");
    } catch (const InputError&) {
      fail(p, "mesh '" + p.name + "': cannot read its OBJ file " + path.string());
    }
    readObj(path, opt);
  }

  static std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
  }

  // A material's modifier: void, a material, a pattern candela implements (returned as a pattern
  // index) or a pattern replaced by its base (followed).
  int patternOf(const Primitive& p) {
    std::string name = p.modifier;
    for (;;) {
      if (name == "void" || materials_.count(name)) return -1;
      const auto pt = patterns_.find(name);
      refuseIfDeferred(name, userOf(p));
      if (pt == patterns_.end())
        fail(p, "modifier '" + p.modifier + "' of " + p.type + " '" + p.name + "' is not defined before use");
      if (pt->second.pattern >= 0) return pt->second.pattern;
      name = pt->second.base;
    }
  }

  // A `source` modified by a pattern with no material under it (`skyfunc source skydome`): in
  // Radiance it is invisible and emits nothing, here too, with a warning.
  bool sourceOfAPattern(const Primitive& p) {
    std::string name = p.modifier;
    bool throughPattern = false;
    for (size_t k = 0; k <= patterns_.size(); ++k) {
      if (name == "void") {
        if (!throughPattern) return false;
        scene_.inputWarnings.push_back(
            Warning{"source_without_material",
                    "source '" + p.name + "' is modified by the pattern '" + p.modifier +
                        "' with no material (light, glow) under it: as in Radiance it is invisible and emits "
                        "nothing (a sky needs `skyfunc glow skyglow 0 0 4 1 1 1 0` and `skyglow source ...`)",
                    p.loc});
        return true;
      }
      if (materials_.count(name)) return false;
      const auto pt = patterns_.find(name);
      if (pt == patterns_.end()) return false;  // undefined: modifierOf refuses it
      throughPattern = true;
      name = pt->second.base;
    }
    return false;
  }

  // The first pattern candela implements along a modifier's chain (-1: none).
  int patternAlong(std::string name) {
    for (;;) {
      if (name == "void") return -1;
      const auto pt = patterns_.find(name);
      if (pt == patterns_.end()) return -1;  // a material: the caller's own rule refuses it (a kept refusal: above)
      if (pt->second.pattern >= 0) return pt->second.pattern;
      name = pt->second.base;
    }
  }

  void addPattern(const Primitive& p) {
    std::string unreadable;  // why a function pattern could not be read (--patterns base)
    if (!implementedPattern(p) && isFunctionPattern(p)) {
      refuseIfDeferred(p.modifier, userOf(p));
      // Radiance's other order, `mat texfunc t` then `t polygon ...` (gensurf -s, obj2rad's
      // smoothed triangles): the pattern stands for the material it modifies, patterned.
      const auto over = materials_.find(p.modifier);
      if (p.modifier != "void" && !patterns_.count(p.modifier) && over == materials_.end())
        fail(p, "modifier '" + p.modifier + "' of " + p.type + " '" + p.name + "' is not a pattern or material defined before use");
      try {
        const int index = static_cast<int>(scene_.patterns.size());
        if (isMixture(p)) return addMixture(p, index);
        scene_.patterns.push_back(readFunctionPattern(p, functionFiles_, folderOf(p), index, patternAlong(p.modifier)));
        scene_.functions = functionFiles_.program();
        scene_.functionFiles = functionFiles_.files();
        if (over != materials_.end()) return addPatternedMaterial(p, over->second, index);
        patterns_[p.name] = PatternEntry{index, p.modifier};
        materials_.erase(p.name);
        return;
      } catch (const InputError& e) {
        if (options_.patterns == PatternPolicy::kRefuse) {
          // Kept until something uses the pattern (the message names the file that failed).
          defer(p.name, InputError(e.loc(), e.message() + "; run with --patterns base to use the material" +
                                                (isMixture(p) ? "s it mixes" : " it modifies") + " unmodified, with a warning"));
          return;
        }
        unreadable = " (" + e.message() + ")";
      }
    }
    if (const auto kind = implementedPattern(p)) {
      ScenePattern sp;
      sp.kind = *kind;
      sp.type = p.type;
      sp.name = p.name;
      sp.loc = p.loc;
      sp.strings = p.strings;
      sp.reals = p.reals;
      if (sp.kind == PatternKind::kSourceDistribution)
        sp.source = std::make_shared<const SourceDistribution>(SourceDistribution::parse(sp));
      scene_.patterns.push_back(std::move(sp));
      patterns_[p.name] = PatternEntry{static_cast<int>(scene_.patterns.size() - 1), p.modifier};
      materials_.erase(p.name);
      return;
    }
    const std::string file = patternFile(p);
    const std::string what = p.type + " '" + p.name + "'" +
                             (file.empty() ? "" : file == "." ? " (its function written inline)" : " (" + file + ")");
    if (options_.patterns == PatternPolicy::kRefuse && p.type == "brightdata" && p.strings.size() > 2 &&
        p.strings[2] == "source.cal")
      return defer(p, what + " calls '" + p.strings[0] +
                          "', which is not one of source.cal's functions candela implements (corr, flatcorr, "
                          "boxcorr, cylcorr); run with --patterns base to use the light it modifies unmodified, "
                          "with a warning");
    if (options_.patterns == PatternPolicy::kRefuse)
      return defer(p, what + " is a pattern, texture or mixture candela does not implement; run with --patterns "
                             "base (or [settings] patterns = \"base\") to use the material it modifies unmodified, "
                             "with a warning");
    // A mixture (mixfunc, mixdata, mixpict, mixtext) is used as a material: it stands for its
    // foreground material, its first string argument ("void" for none).
    const bool mixture = p.type.rfind("mix", 0) == 0;
    if (mixture && p.strings.empty()) fail(p, what + " names no foreground material");
    const std::string base = mixture ? p.strings[0] : p.modifier;
    scene_.inputWarnings.push_back(
        Warning{"pattern_replaced",
                what + (mixture ? (unreadable.empty() ? " is not implemented" : " cannot be read" + unreadable) +
                                      ": its foreground material '" + base + "' is used in its place"
                                : (unreadable.empty() ? " is not implemented" : " cannot be read" + unreadable) +
                                      ": the materials it modifies are used unmodified"),
                p.loc});
    patterns_[p.name] = PatternEntry{-1, base};
    materials_.erase(p.name);
  }

  // A pattern modifying a material (`mat texfunc t`): t names a copy of the material with the
  // pattern (index) first along its chain (addCopy).
  void addPatternedMaterial(const Primitive& p, int material, int index) {
    bool used = false;
    materials_[p.name] = withPattern(p, material, index, used, 0);
    patterns_.erase(p.name);
  }
  // The copy of `material` with pattern `index` in front of its own patterns (the pattern itself
  // the first time, `used` then set; a copy of it after); of a mixture, the mixture of such copies
  // (Radiance applies the texture before the mixture chooses: genrev -s over a mixfunc, Radiance's
  // torus.rad).
  int withPattern(const Primitive& p, int material, int index, bool& used, int depth) {
    Material m = scene_.materials[static_cast<size_t>(material)];
    if (m.type == MaterialType::kMixture) {
      if (depth > 16) fail(p, p.type + " '" + p.name + "' modifies mixtures of mixtures more than 16 deep");
      if (m.foreground >= 0) m.foreground = withPattern(p, m.foreground, index, used, depth + 1);
      if (m.background >= 0) m.background = withPattern(p, m.background, index, used, depth + 1);
    } else if (!used) {
      scene_.patterns[static_cast<size_t>(index)].next = m.pattern;
      m.pattern = index;
      used = true;
    } else {
      ScenePattern sp = scene_.patterns[static_cast<size_t>(index)];
      sp.next = m.pattern;
      m.pattern = static_cast<int>(scene_.patterns.size());
      scene_.patterns.push_back(std::move(sp));
    }
    return addCopy(std::move(m), p);
  }

  // A material derived from another (an alias's, a pattern's over it) added as p's: an object of
  // its own, not clipped by what lists the material it copies. Its index.
  int addCopy(Material m, const Primitive& p) {
    m.name = p.name;
    m.loc = p.loc;
    m.clipBit = -1;
    return static_cast<int>(scene_.addMaterial(std::move(m)));
  }

  // A mixfunc: a material of its own (surfaces name it), mixing two materials defined before (or
  // void) by its coefficient.
  void addMixture(const Primitive& p, int index) {
    const std::string what = p.type + " '" + p.name + "'";
    if (p.modifier != "void")
      fail(p, what + " is modified by '" + p.modifier + "': candela evaluates no pattern on a mixture (apply it to "
                     "the mixed materials)");
    auto materialNamed = [&](const std::string& name, const char* role) {
      if (name == "void") return -1;
      const auto it = materials_.find(name);
      refuseIfDeferred(name, userOf(p));
      if (it == materials_.end())
        fail(p, what + ": its " + role + " '" + name + "' is not a material defined before use");
      return it->second;
    };
    // Its arguments first (their count checked), then the materials they name.
    ScenePattern sp = readFunctionPattern(p, functionFiles_, folderOf(p), index, -1);
    const int fore = materialNamed(p.strings[0], "foreground"), back = materialNamed(p.strings[1], "background");
    scene_.patterns.push_back(std::move(sp));
    scene_.functions = functionFiles_.program();
    scene_.functionFiles = functionFiles_.files();
    Material m;
    m.type = MaterialType::kMixture;
    m.name = p.name;
    m.loc = p.loc;
    m.pattern = index;
    m.foreground = fore;
    m.background = back;
    materials_[p.name] = static_cast<int>(scene_.addMaterial(std::move(m)));
    patterns_.erase(p.name);
  }

  // `mod alias new old`: `new` is `old`, modified by `mod` instead of old's own modifier when
  // `mod` is not "inherit" (Radiance reference manual, "Alias").
  void addAlias(const Primitive& p) {
    const auto it = materials_.find(p.strings[0]);
    refuseIfDeferred(p.strings[0], userOf(p));
    if (it == materials_.end())
      fail(p, "alias '" + p.name + "' stands for '" + p.strings[0] + "', which is not a material defined before use");
    int pattern = -1;
    if (p.modifier != "inherit" && p.modifier != "void") {
      Primitive probe = p;
      pattern = patternOf(probe);
    }
    Material m = scene_.materials[static_cast<size_t>(it->second)];
    if (p.modifier != "inherit") m.pattern = pattern;
    if (m.pattern == scene_.materials[static_cast<size_t>(it->second)].pattern) {
      materials_[p.name] = it->second;
    } else {
      materials_[p.name] = addCopy(std::move(m), p);
    }
    patterns_.erase(p.name);
  }

  // The functions of a material's own arguments (plastic2's u direction, BRTDfunc's specular
  // parts, plasfunc's BRDF) into Scene::patterns, the first at m.functions.
  void readOwnFunctions(const Primitive& p, const MaterialFamily& family, Material& m) {
    for (int part = 0; part < family.functionPatterns(); ++part) {
      const int index = static_cast<int>(scene_.patterns.size());
      scene_.patterns.push_back(readFunctionPattern(p, functionFiles_, folderOf(p), index, -1, part));
      scene_.functions = functionFiles_.program();
      scene_.functionFiles = functionFiles_.files();
      if (part == 0) m.functions = index;
    }
  }

  void addMaterial(const Primitive& p, const MaterialFamily& family) {
    Material m;
    // What the material reaches that candela cannot read (a pattern kept refused, its own function
    // files) refuses it only where a surface uses it (a library's plasfunc whose aniso.cal is not on
    // this RAYPATH); its own arguments are checked here (family.read), an undefined modifier too.
    try {
      m.pattern = patternOf(p);
      readOwnFunctions(p, family, m);
    } catch (const InputError& e) {
      if (p.modifier != "void" && !materials_.count(p.modifier) && !patterns_.count(p.modifier) &&
          !deferred_.count(p.modifier))
        throw;
      return defer(p.name, e);
    }
    m.type = family.type();
    if (m.pattern >= 0 && scene_.patterns[static_cast<size_t>(m.pattern)].source && !family.emits())
      fail(p, p.type + " '" + p.name + "' is modified by the source.cal distribution '" +
                  scene_.patterns[static_cast<size_t>(m.pattern)].name +
                  "', which candela applies to light, illum and glow only");
    int spectrum = -1;  // a spectrum along the chain of patterns (spectrum, specfile, specfunc, specdata)
    for (int i = m.pattern; i >= 0 && spectrum < 0; i = scene_.patterns[static_cast<size_t>(i)].next)
      if (scene_.patterns[static_cast<size_t>(i)].constant || scene_.patterns[static_cast<size_t>(i)].spectral())
        spectrum = i;
    if (spectrum >= 0 && family.emits())
      fail(p, p.type + " '" + p.name + "' is modified by the spectrum '" +
                  scene_.patterns[static_cast<size_t>(spectrum)].name +
                  "': candela reduces spectra of reflectance and transmittance to RGB, not yet a light's spectrum "
                  "(whose normalisation to the light's radiance it does not model); give the light its RGB radiance");
    m.name = p.name;
    m.loc = p.loc;
    // A name the material reads whose refusal is kept (an illum's alternate, a WGMDfunc part's
    // pattern) refuses the material where a surface uses it, as above.
    bool reachesKept = false;
    const MaterialReadContext ctx{p,
                                  [this, &p, &reachesKept](const std::string& name) {
                                    reachesKept = deferred_.count(name) != 0;
                                    refuseIfDeferred(name, userOf(p));
                                    const auto it = materials_.find(name);
                                    return it == materials_.end() ? -1 : it->second;
                                  },
                                  [this, &p, &reachesKept](const std::string& name) {
                                    reachesKept = deferred_.count(name) != 0;
                                    Primitive named = p;
                                    named.modifier = name;
                                    return patternOf(named);
                                  },
                                  // A BSDF file that cannot be read refuses the material where a
                                  // surface uses it, as its function files do.
                                  [this, &p, &reachesKept](const std::string& name) {
                                    reachesKept = true;
                                    const Bsdf* b = bsdfOf(p, name);
                                    reachesKept = false;
                                    return b;
                                  }};
    try {
      family.read(ctx, m);
      if (m.type == MaterialType::kAntimatter) giveClipBits(p, m);
    } catch (const InputError& e) {
      // An antimatter is refused only when a surface uses it (the reader's rule).
      if (!reachesKept && m.type != MaterialType::kAntimatter) throw;
      return defer(p.name, e);
    }
    materials_[p.name] = static_cast<int>(scene_.addMaterial(std::move(m)));
    patterns_.erase(p.name);
  }

  // The scattering of BSDF file `name` named by p, each file once in Scene::bsdfs.
  const Bsdf* bsdfOf(const Primitive& p, const std::string& name) {
    const std::shared_ptr<const Bsdf> b = functionFiles_.bsdf(name, p, folderOf(p));
    scene_.functionFiles = functionFiles_.files();
    for (const auto& known : scene_.bsdfs)
      if (known == b) return known.get();
    scene_.bsdfs.push_back(b);
    return b.get();
  }

  // An antimatter's materials get their bits in the rays' clip sets (engine/antimatter.h), numbered
  // over all the scene's antimatter, at most kMaxClippedMaterials of them; its mask is theirs.
  void giveClipBits(const Primitive& p, Material& m) {
    if (m.shownMaterial >= 0 && scene_.materials[static_cast<size_t>(m.shownMaterial)].type == MaterialType::kAntimatter)
      fail(p, "antimatter '" + p.name + "': its first modifier '" + p.strings[0] +
                  "' is an antimatter; the first modifier is the material its surface is seen as (void: none)");
    int used = 0;
    for (const Material& other : scene_.materials) used = std::max(used, other.clipBit + 1);
    for (int index : m.clipList) {
      Material& clipped = scene_.materials[static_cast<size_t>(index)];
      if (clipped.clipBit < 0) {
        if (used >= kMaxClippedMaterials)
          fail(p, "antimatter '" + p.name + "' clips '" + clipped.name + "', one more than the " +
                      std::to_string(kMaxClippedMaterials) +
                      " materials candela's clip sets hold for all the antimatter of a scene");
        clipped.clipBit = used++;
      }
      m.clipMask = static_cast<uint16_t>(m.clipMask | (1u << clipped.clipBit));
    }
  }

  // Geometry within 10 000 km of the origin: beyond, ray offsets and the accelerators' single
  // precision lose the surfaces (Embree aborts at ~1.8e18 m).
  void checkCoordinates(const Primitive& p) {
    for (double v : p.reals)
      if (std::abs(v) > kMaxCoordinateM)
        fail(p, p.type + " '" + p.name + "' has a coordinate or size beyond 1e7 m (" + compactNumber(v) + ")");
  }

  // A spotlight on a flat surface whose cone lies wholly behind the surface's front (the angle
  // from the front normal to the aim at least 90° + the half angle) sends no light at all, here
  // as in Radiance (a light emits from its front only): valid, but surely not meant, so a
  // warning (Radiance's own check, srcsupp.c checkspot, is another formula that lets an aim
  // straight back pass).
  void checkSpotAim(const Primitive& p, uint32_t mat, const Vec3& frontNormal) {
    if (mat >= scene_.materials.size()) return;
    const Material& m = scene_.materials[mat];
    if (!m.spot || m.spotCosHalf <= 0.0) return;  // a cone of 180° or more always reaches out
    const double d = glm::dot(m.spotAim, frontNormal);
    const double sinHalf = std::sqrt(std::max(0.0, 1.0 - m.spotCosHalf * m.spotCosHalf));
    if (d > -sinHalf) return;
    scene_.inputWarnings.push_back(Warning{
        "spotlight_behind_surface",
        p.type + " '" + p.name + "' uses the spotlight '" + m.name +
            "', whose cone lies wholly behind the surface's front: it sends no light (check the spotlight's "
            "direction and the surface's orientation)",
        p.loc});
  }

  // The sky function (skybright.cal, perezlum.cal) modifying material `mod`, if any.
  const ScenePattern* skyPatternOf(int mod) const {
    if (mod < 0) return nullptr;
    const int pt = scene_.materials[static_cast<size_t>(mod)].pattern;
    if (pt < 0 || !isSkyPattern(scene_.patterns[static_cast<size_t>(pt)].kind)) return nullptr;
    return &scene_.patterns[static_cast<size_t>(pt)];
  }

  void checkRadius(const Primitive& p, double r) {
    if (r < 0.0) fail(p, p.type + " '" + p.name + "' has a negative radius");
  }

  void add(const Primitive& p) {
    const std::string& t = p.type;
    if (!p.integers.empty())
      fail(p, t + " '" + p.name + "' takes no integer arguments, got " + std::to_string(p.integers.size()));
    const bool isSurface = t == "polygon" || t == "sphere" || t == "bubble" || t == "ring" || t == "cone" ||
                           t == "cup" || t == "cylinder" || t == "tube" || t == "source";
    if (!isSurface && t != "mesh" && t != "instance") deferred_.erase(p.name);  // a new definition
    if (const MaterialFamily* family = familyNamed(t)) return addMaterial(p, *family);
    if (t == "alias") return addAlias(p);
    if (isPatternType(t)) return addPattern(p);
    if (t == "mesh") return addMesh(p);
    if (t == "instance")
      fail(p, "instance '" + p.name + "' places a Radiance octree (" + (p.strings.empty() ? "" : p.strings[0]) +
                  "), which candela does not read; pass the scene files the octree was made from instead "
                  "(through !xform with the instance's transform)");
    // Any other type is a material or pattern (Radiance's surface types are those above).
    if (t == "prism1" || t == "prism2")
      return defer(p, t + " '" + p.name + "' redirects light through virtual sources, which candela does not "
                          "model (no model it was tried on needs it); replace it with glass or trans");
    if (!isSurface) return defer(p, "primitive type '" + t + "' is not supported (" + supportedTypes() + ")");
    if (t == "source" && sourceOfAPattern(p)) return;
    const int mod = modifierOf(p);
    if (t == "source") {
      expectStrings(p, 0);
      expectReals(p, 4);
      const Vec3 dir = vec(p, 0);
      if (glm::length(dir) == 0.0) fail(p, "source '" + p.name + "' has a zero direction");
      if (!(p.reals[3] > 0.0 && p.reals[3] <= 360.0))
        fail(p, "source '" + p.name + "' needs an angle in (0, 360] degrees");
      if (mod < 0) return;  // void: invisible, as in Radiance
      const MaterialType mt = scene_.materials[mod].type;
      if (!familyOf(mt).emits())
        fail(p, "source '" + p.name + "' needs a light, illum or glow modifier, not " + materialTypeName(mt));
      if (scene_.materials[mod].spot)
        fail(p, "source '" + p.name + "': a spotlight as a distant source is not supported (use light)");
      if (sourceDistributionOf(scene_, scene_.materials[mod]))
        fail(p, "source '" + p.name + "': its modifier has a source.cal distribution, which candela applies to "
                    "light surfaces only, not to sources at infinity");
      if (const ScenePattern* sky = skyPatternOf(mod)) {
        // gensky's and gendaylit's hemispheres: the scene's sky, not distant glow sources.
        if (mt != MaterialType::kGlow)
          fail(p, "source '" + p.name + "': the sky function '" + sky->name + "' (" + sky->strings[1] +
                      ") modifies a glow in candela, not " + materialTypeName(mt));
        sky_.addSource(scene_, static_cast<uint32_t>(mod), dir, p.reals[3], p.name, p.loc);
        return;
      }
      scene_.addDistant(dir, p.reals[3], static_cast<uint32_t>(mod), p.name);
      return;
    }
    if (const ScenePattern* sky = skyPatternOf(mod))
      fail(p, t + " '" + p.name + "' uses '" + scene_.materials[mod].name + "', modified by the sky function '" +
                  sky->name + "' (" + sky->strings[1] + "): candela evaluates sky functions on the sky and ground "
                  "`source` hemispheres only");
    // Geometry is checked even when its modifier is void (void surfaces are invisible in Radiance).
    const uint32_t mat = mod < 0 ? 0 : static_cast<uint32_t>(mod);
    Scene probe;  // void surfaces are validated into a scratch scene and dropped
    Scene& target = mod < 0 ? probe : scene_;
    checkCoordinates(p);
    if (t == "polygon") {
      expectStrings(p, 0);
      if (const std::optional<Vec3> n = polygons_.add(p, mat, target, &target == &scene_)) checkSpotAim(p, mat, *n);
    } else if (t == "sphere" || t == "bubble") {
      expectStrings(p, 0);
      expectReals(p, 4);
      checkRadius(p, p.reals[3]);
      if (p.reals[3] == 0.0) fail(p, t + " '" + p.name + "' has a zero radius");
      target.addSphere(vec(p, 0), p.reals[3], mat, t == "bubble", p.name);
    } else if (t == "ring") {
      expectStrings(p, 0);
      expectReals(p, 8);
      checkRadius(p, p.reals[6]);
      checkRadius(p, p.reals[7]);
      if (!(p.reals[7] > p.reals[6]))
        fail(p, "ring '" + p.name + "' needs an outer radius larger than its inner radius");
      if (glm::length(vec(p, 3)) == 0.0) fail(p, "ring '" + p.name + "' has a zero normal");
      checkSpotAim(p, mat, glm::normalize(vec(p, 3)));
      target.addRing(vec(p, 0), vec(p, 3), p.reals[6], p.reals[7], mat, p.name);
    } else {
      const bool isCone = t == "cone" || t == "cup";
      expectStrings(p, 0);
      expectReals(p, isCone ? 8 : 7);
      const double ra = p.reals[6];
      const double rb = isCone ? p.reals[7] : p.reals[6];
      checkRadius(p, ra);
      checkRadius(p, rb);
      if (ra == 0.0 && rb == 0.0) fail(p, t + " '" + p.name + "' has zero radii");
      if (glm::length(vec(p, 3) - vec(p, 0)) == 0.0) fail(p, t + " '" + p.name + "' has zero length");
      target.addCone(vec(p, 0), vec(p, 3), ra, rb, mat, t == "cup" || t == "tube", p.name);
    }
  }

  Scene& scene_;
  SceneReadOptions options_;
  FunctionFiles functionFiles_;
  std::unordered_map<std::string, int> materials_;
  // Patterns by name: one candela implements (pattern ≥ 0, into Scene::patterns) or one replaced
  // by the modifier it has (pattern −1, base followed).
  struct PatternEntry {
    int pattern = -1;
    std::string base;
  };
  std::unordered_map<std::string, PatternEntry> patterns_;
  std::unordered_map<std::string, InputError> deferred_;  // refusals kept until used (defer)
  std::optional<ObjMapping> mapping_;
  PolygonReader polygons_{options_.nonplanar};  // polygons, their planarity and splitting
  std::string topFile_;  // the file read now, and its folder (readText's may differ from its name's)
  std::filesystem::path topFolder_;
  SceneSkyBuilder sky_;
};

SceneReader::SceneReader(Scene& scene, SceneReadOptions options)
    : builder_(std::make_unique<Builder>(scene, options)) {}
SceneReader::~SceneReader() = default;

void SceneReader::readFile(const std::filesystem::path& path) {
  if (isObjPath(path)) return builder_->readObj(path);
  builder_->read(readInputFile(path, "scene file"), path.string(), path.parent_path());
}

void SceneReader::readText(std::string_view text, const std::string& fileName, const std::filesystem::path& folder) {
  builder_->read(text, fileName, folder);
}

PatternPolicy parsePatternPolicy(const std::string& name) {
  if (name == "refuse") return PatternPolicy::kRefuse;
  if (name == "base") return PatternPolicy::kBase;
  throw std::invalid_argument("unknown pattern policy '" + name + "' (expected refuse or base)");
}

NonplanarPolicy parseNonplanarPolicy(const std::string& name) {
  if (name == "refuse") return NonplanarPolicy::kRefuse;
  if (name == "triangulate") return NonplanarPolicy::kTriangulate;
  throw std::invalid_argument("unknown non-planar policy '" + name + "' (expected refuse or triangulate)");
}

void readRadianceText(std::string_view text, const std::string& fileName, Scene& scene) {
  SceneReader(scene).readText(text, fileName);
}

void readRadianceFile(const std::filesystem::path& path, Scene& scene) { SceneReader(scene).readFile(path); }

void readSceneFiles(const std::vector<std::filesystem::path>& files, Scene& scene, const SceneReadOptions& options) {
  SceneReader reader(scene, options);
  for (const std::filesystem::path& f : files)
    if (!isObjPath(f)) reader.readFile(f);
  for (const std::filesystem::path& f : files)
    if (isObjPath(f)) reader.readFile(f);
}

}  // namespace candela
