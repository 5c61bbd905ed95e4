// The sky functions gensky and gendaylit write, evaluated natively: a `glow` modified by
// `brightfunc skyfunc ... skybright.cal` or `... perezlum.cal` on `source` hemispheres becomes
// the scene's SkyDome (engine/scene.h) instead of two distant glow sources. Formulas from
// Radiance's src/gen/skybright.cal and src/gen/perezlum.cal (docs/daylight.md, "Skies from gensky
// and gendaylit"); luminance in cd/m2 = 179 lm/W x the function's radiance x the glow's photopic
// colour.
#pragma once

#include "engine/scene.h"
#include "photometry/sky_model.h"

#include <optional>
#include <string>

namespace candela {

// Whether a pattern kind is a sky function (skybright.cal, perezlum.cal).
bool isSkyPattern(PatternKind kind);

// One sky function with its arguments as written. Throws InputError at the pattern's line for
// arguments the .cal file cannot use (wrong count, sky type not 1..4, a transform that tilts or
// mirrors the sky, a function the file does not define).
class RadianceSkyFunction {
 public:
  explicit RadianceSkyFunction(const ScenePattern& pattern);

  // The function's value (W/sr/m2 of a white glow) towards a unit direction in the pattern's own
  // frame, above or below the horizon: skybright.cal's `skybr` or perezlum.cal's `skybright`,
  // the ground brightness blended in near the horizon as the files do.
  double value(const Vec3& dir) const;
  // The ground brightness argument (A3 of skybright.cal, A2 of perezlum.cal), W/sr/m2.
  double groundBrightness() const { return ground_; }
  // The sun direction among the arguments (CIE clear and intermediate, Perez); none for the
  // overcast and uniform skies.
  std::optional<Vec3> sunDirection() const { return sun_; }
  // Degrees the pattern is turned about +Z (counter-clockwise seen from above) by its transform
  // arguments (-rz, or xform's appended words).
  double rotationDeg() const { return rotationDeg_; }
  // "gensky CIE overcast (skybright.cal)", "gendaylit Perez (perezlum.cal)", ...
  std::string description() const;
  // 1 CIE clear, 2 CIE overcast, 3 uniform, 4 CIE intermediate; 0 for perezlum.cal.
  int skyType() const { return type_; }

 private:
  PatternKind kind_;
  int type_ = 0;
  std::vector<double> a_;  // the real arguments A1..An
  double ground_ = 0.0;
  std::optional<Vec3> sun_;
  double rotationDeg_ = 0.0;
};

// The sky hemisphere as a SkyModel: luminance (cd/m2) = factor x function value, factor = 179 x
// photopic(glow colour). Its scale is 1: the luminance is absolute, as written in the scene.
class RadianceSky : public SkyModel {
 public:
  RadianceSky(const RadianceSkyFunction& f, double factorCdPerW);
  double relativeLuminance(const Vec3& dirTrue) const override;
  std::string name() const override { return "scene:" + f_.description(); }
  const RadianceSkyFunction& function() const { return f_; }

 private:
  RadianceSkyFunction f_;
  double factor_;
};

// Collects the sky and ground hemispheres of one scene as the reader meets their `source`
// primitives and sets Scene::sky from them.
class SceneSkyBuilder {
 public:
  // A `source` (direction, full angle in degrees) whose material is a glow modified by a sky
  // pattern. Throws InputError at `loc` for a cone that is not the upper or lower hemisphere or
  // the whole sphere, for a second sky pattern, or for a hemisphere given twice.
  void addSource(const Scene& scene, uint32_t material, const Vec3& dir, double angleDeg, const std::string& name,
                 const FileLoc& loc);
  // Sets scene.sky from what was collected (nothing when no sky source was met); the sun is the
  // brightest small distant `light` source (full angle up to 5 degrees), if any. Called at the
  // end of every file read; rebuilds only after a new sky source or a new distant source (a sun
  // in a later file).
  void apply(Scene& scene);

 private:
  struct Part {
    int material = -1;
    std::string name;
    FileLoc loc;
  };
  int pattern_ = -1;
  Part sky_, ground_;
  bool changed_ = false;
  bool applied_ = false;  // scene.sky is this builder's
  size_t distantSeen_ = 0;
};

}  // namespace candela
