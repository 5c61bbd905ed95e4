// The one hook where patterns meet materials, as Radiance's raytexture: before a material is
// evaluated at a hit, the patterns that modify it (brightfunc, colorfunc, their data kin,
// brighttext, colortext) are evaluated there and multiply its colour; the material's family then derives its parts from the patterned colour.
// Every user of a hit's material (paths, the camera, shadow rays) goes through it.
#pragma once

#include "engine/materials/family.h"
#include "engine/radiance/cal/cal.h"
#include "engine/scene.h"

#include <memory>
#include <optional>

namespace candela {

// Where a pattern is evaluated: the hit point, the ray's unit direction, the surface's geometric
// normal (unit, as stored: not turned to the ray) and the distance travelled (m).
struct PatternPoint {
  Vec3 x{0.0}, d{0.0}, ng{0.0};
  double t = 0.0;
};

// The function language's evaluator of one top-level trace (made on first use: one per thread).
class PatternEvaluator {
 public:
  explicit PatternEvaluator(const Scene& scene) : scene_(scene) {}
  // The product of the colours of pattern `index` and the patterns modifying it, at p.
  Rgb colour(int index, const PatternPoint& p);
  // The value of pattern `index`'s (first) function at p: a mixture's coefficient (mixtext's: 1
  // inside a glyph, 0 outside).
  double value(int index, const PatternPoint& p);
  // Pattern `index`'s three functions at p as a direction in the world (plastic2's u).
  Vec3 direction(int index, const PatternPoint& p);
  // The sum of the perturbations of the textures along pattern `index`'s chain at p (world).
  Vec3 perturbation(int index, const PatternPoint& p);
  // Pattern `index`'s three functions at p with the variables Radiance's BRTDfunc defines: NxP
  // NyP NzP and RdotP turned towards the ray, CrP CgP CbP the material's pattern colour.
  Rgb oriented(int index, const PatternPoint& p, const Rgb& patternColour);
  // Pattern `index`'s directional functions (Radiance's dirbrdf: plasfunc's refl, plasdata's
  // function of its data, BRTDfunc's rbrtd gbrtd bbrtd) at p for light arriving along unit ldir
  // (world) from a source of solid angle omegaSr, with the variables of `oriented` (CrP CgP CbP:
  // colourP): each called with the direction in the function's coordinates and omegaSr; a data
  // form's coordinates called so, its function with the value looked up first. One value (grey)
  // or three; a function given as 0 is 0.
  Rgb directional(int index, const PatternPoint& p, const Rgb& colourP, const Vec3& ldir, double omegaSr);

 private:
  // Starts an evaluation of pattern sp at p (the ray's variables in its coordinates).
  void begin(const ScenePattern& sp, const PatternPoint& p);
  // Starts one with the variables Radiance's BRTDfunc defines (oriented, directional).
  void beginOriented(const ScenePattern& sp, const PatternPoint& p, const Rgb& colourP);
  // The ray's variables of pattern sp at p (makes the evaluator on first use).
  void fill(const ScenePattern& sp, const PatternPoint& p, cal::Environment& env);
  // A spectral pattern's colour (specfunc, specdata) in the evaluation begun.
  Rgb spectral(const ScenePattern& sp);
  // Function k of sp in the evaluation begun (a data pattern's: called with its data at the point
  // its coordinates give); a failure is an InputError at the pattern's line.
  double function(const ScenePattern& sp, int k);

  const Scene& scene_;
  std::unique_ptr<cal::Evaluator> eval_;
};

// Where a ray meets a source at infinity, for a pattern evaluated there: this far along the ray
// (Radiance's FHUGE), the normal facing back along the ray.
constexpr double kDistantPointM = 1e10;

// The function pattern modifying emitter m's radiance (an index into Scene::patterns), or -1.
inline int functionPatternOf(const Scene& scene, const MaterialParameters& m) {
  return m.pattern >= 0 && scene.patterns[static_cast<size_t>(m.pattern)].kind == PatternKind::kFunction ? m.pattern
                                                                                                      : -1;
}

// The shading normal of a surface of m met on its front (or back) side, nf the normal facing the
// ray: nf turned by m's perturbation (turned to that side too), as Radiance's raynormal; nf
// itself without a texture, or where the two cancel.
inline Vec3 shadingNormal(const MaterialParameters& m, const Vec3& nf, bool front) {
  if (m.perturbation == Vec3(0.0)) return nf;
  const Vec3 n = nf + (front ? m.perturbation : -m.perturbation);
  const double l = glm::length(n);
  return l > 1e-9 ? n / l : nf;
}

// The shading normal on a smoothed mesh triangle (TriangleMesh::smoothNormal `smooth`, on the
// front's side): as Radiance's tmesh.cal texture, a perturbation of smooth − n_g added to m's own,
// so ±(smooth + m's perturbation) facing the ray, unit.
inline Vec3 smoothShadingNormal(const MaterialParameters& m, const Vec3& smooth, const Vec3& nf, bool front) {
  const Vec3 n = front ? smooth + m.perturbation : -(smooth + m.perturbation);
  const double l = glm::length(n);
  return l > 1e-9 ? n / l : nf;
}

// Whether m's colour is modified by a function pattern (the hook has work to do).
inline bool hasFunctionPattern(const Scene& scene, const MaterialParameters& m) {
  if (m.functions >= 0) return true;  // plastic2's u direction, BRTDfunc's specular parts
  return m.pattern >= 0 && scene.patterns[static_cast<size_t>(m.pattern)].kind == PatternKind::kFunction &&
         familyOf(m.type).role() != HitRole::kMix;  // a mixture's pattern is its coefficient
}

// The material as seen at p: m itself, or `out` holding m's parameters with its colour times its
// patterns' and its parts derived again.
const Material& patterned(const Scene& scene, const Material& m, const PatternPoint& p, PatternEvaluator& eval,
                          Material& out);

// The material a ray that is not a shadow ray meets at p for a surface of m: illum's alternate,
// and a mixture's foreground with the probability of its coefficient (clipped to [0, 1]; rng drawn
// only at a mixture), else its background; nullptr when that is void or an illum has no
// alternate (the ray passes straight on). Patterns are not applied here (patterned, after).
const Material* resolved(const Scene& scene, const Material& m, const PatternPoint& p, PatternEvaluator& eval,
                         Rng& rng);

// The material a ray that is not a shadow ray meets at p on a surface of m, as every user of a
// hit asks it: resolved (illum's alternate, a mixture's choice) and patterned (in patternedCopy,
// no string copied); nullptr: the ray passes straight on. Without function patterns in the scene
// only illum's alternate is looked at and nothing is drawn or made; otherwise the evaluator is
// made on first use.
const Material* materialAt(const Scene& scene, const Material& m, const PatternPoint& p,
                           std::unique_ptr<PatternEvaluator>& evaluator, Rng& rng,
                           std::optional<Material>& patternedCopy);

// What a straight (shadow) ray gets through a surface of m at p, patterns and mixtures evaluated
// (a mixture: its materials' transmittances weighted by its coefficient); nullopt when opaque.
std::optional<Rgb> straightThrough(const Scene& scene, const Material& m, const PatternPoint& p,
                                   PatternEvaluator& eval);

}  // namespace candela
