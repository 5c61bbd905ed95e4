// Reader for Radiance's scene description language (Radiance reference manual, "Scene
// Description"): primitives `modifier type identifier`, then string, integer and real arguments,
// each preceded by its count; `#` comments; several files in order, modifiers defined before use.
// Inline commands of Radiance's generators are expanded (engine/radiance/generators.h), never run.
// docs/engine.md lists what of the language is read, expanded, replaced or refused.
#pragma once

#include "engine/radiance/parse.h"
#include "engine/scene.h"

#include <filesystem>
#include <memory>
#include <string_view>
#include <vector>

namespace candela {

// Tolerances of the polygon checks: a vertex farther than kPlanarTolerance × the polygon's
// diameter from its best plane makes it non-planar; an area below kDegenerateTolerance ×
// diameter² makes it degenerate.
inline constexpr double kPlanarTolerance = 1e-3;
// A vertex within kPlanarAbsoluteToleranceM (0.1 mm) of the plane never makes a polygon non-planar.
inline constexpr double kPlanarAbsoluteToleranceM = 1e-4;
inline constexpr double kDegenerateTolerance = 1e-10;

// Patterns, textures and mixtures (texfunc, colorpict, brightfunc with a file candela does not
// implement, mixfunc, ...): refused, or replaced by the material they modify, with a warning each.
enum class PatternPolicy { kRefuse, kBase };
// A polygon farther from planar than kPlanarTolerance: refused, or triangulated with a warning.
enum class NonplanarPolicy { kRefuse, kTriangulate };

// The names of the policies as case files and the command line write them ("refuse", "base",
// "triangulate"); the parsers throw std::invalid_argument naming the accepted names.
PatternPolicy parsePatternPolicy(const std::string& name);
NonplanarPolicy parseNonplanarPolicy(const std::string& name);

struct SceneReadOptions {
  PatternPolicy patterns = PatternPolicy::kRefuse;
  NonplanarPolicy nonplanar = NonplanarPolicy::kRefuse;
  // An obj2rad mapping file (obj2rad -m; engine/obj_reader.h) for every OBJ file read, plain or
  // through a `mesh` with a void modifier; empty: usemtl, then group, then "white".
  std::filesystem::path objMapping;
  // --max-memory in bytes (0: none): bounds what one inline command may make
  // (engine/radiance/gen.h, generatedPrimitivesAllowed).
  uint64_t maxMemoryBytes = 0;
  // A model's root, looked in last for every file a scene file names (engine/radiance/
  // file_lookup.h): a Honeybee radiance folder's (study/case/honeybee_folder.h); empty: none.
  std::filesystem::path rootFolder;
};

// Reads scene files, in order, into one scene: modifiers defined in one file serve the next.
// Warnings (replaced patterns, triangulated polygons) go to scene.inputWarnings.
class SceneReader {
 public:
  explicit SceneReader(Scene& scene, SceneReadOptions options = {});
  ~SceneReader();
  SceneReader(const SceneReader&) = delete;
  SceneReader& operator=(const SceneReader&) = delete;

  // Throws InputError("file:line: ...") on any error. A file ending in .obj (any case) is read
  // as Wavefront OBJ (engine/obj_reader.h) with the modifiers read so far.
  void readFile(const std::filesystem::path& path);
  // Text already in memory; `fileName` names it in messages, commands' files are resolved
  // relative to `folder`.
  void readText(std::string_view text, const std::string& fileName,
                const std::filesystem::path& folder = std::filesystem::path("."));

  class Builder;

 private:
  std::unique_ptr<Builder> builder_;
};

// One file or text with the default options (a reader of its own).
void readRadianceFile(const std::filesystem::path& path, Scene& scene);
void readRadianceText(std::string_view text, const std::string& fileName, Scene& scene);

// Every file of a list through one reader: the Radiance files in their order, then the OBJ
// files in theirs, so that `model.obj materials.rad` finds its materials (docs/engine.md).
void readSceneFiles(const std::vector<std::filesystem::path>& files, Scene& scene,
                    const SceneReadOptions& options = {});

}  // namespace candela
