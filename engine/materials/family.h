// The material seam: one family of Radiance materials (the types that behave alike where a ray
// meets them) behind one interface, as Radiance's own type table (ofun[]) does. A family says how
// its primitive is read, what reflectance and transmittance parts it derives, and what a surface
// of it does at a hit: absorb, emit, pass a straight (shadow) ray, send a path on specularly, or
// scatter at a diffuse vertex. The integrators and the study ask the family; none tests a type.
// Families are listed in one table (engine/materials/registry.cpp), one family a file beside this.
#pragma once

#include "base/rng.h"
#include "engine/materials/material.h"
#include "engine/radiance/parse.h"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

class PatternEvaluator;
struct PatternPoint;

// What a ray that is not a shadow ray finds at a surface of the family.
enum class HitRole {
  kAbsorb,    // void: nothing is seen, the path ends
  kEmit,      // light, spotlight, illum, glow: the radiance it sends back
  kSpecular,  // mirror, glass, dielectric: the path goes on, with no diffuse vertex
  kScatter,   // plastic, metal, trans: a diffuse vertex (diffuse, glossy and transmitted parts)
  kMix,       // mixfunc: one of two materials, chosen at the hit (engine/materials/pattern_hook.h)
};

// A surface met along unit d: geometric normal ng, nf = ng turned to face the ray, front when
// the ray meets ng's side, t the distance travelled to it (m).
struct SurfaceHit {
  Vec3 d{0.0}, ng{0.0}, nf{0.0};
  bool front = true;
  double t = 0.0;
};

// One sampled specular event of a path (its weight is multiplied into the path's throughput).
struct SpecularSample {
  enum class Kind {
    kAbsorbed,  // the path ends
    kMirror,    // a mirror's reflection (its virtual sources were sampled: engine/lights.h)
    kStraight,  // straight on through the surface (thin glass): the ray's state is kept
    kReflected, // reflected (glass)
    kBent,      // a dielectric's reflection or refraction
  };
  Kind kind = Kind::kAbsorbed;
  Vec3 dir{0.0};
  bool transmitted = false;  // leaves on the far side of the surface
};

// Every specular part at once, for the camera (engine/render.cpp), which follows each of them:
// factor × Σ weight_i L(dir_i); `scaled` false when the factor is exactly 1.
struct SpecularSplit {
  struct Part {
    Rgb weight{0.0};
    Vec3 dir{0.0};
    bool transmitted = false;
  };
  Rgb factor{1.0};
  bool scaled = false;
  int count = 0;
  Part parts[2];
};

// One continuation drawn from a scattering function (MaterialFamily::sampleScattering): the
// direction the light is sought in, its weight (value over density, the part's choice included),
// whether it leaves on the far side, and whether it goes straight on (a direct part: sources
// count as for the ray that arrived).
struct ScatterSample {
  Vec3 dir{0.0};
  Rgb weight{0.0};
  bool transmitted = false;
  bool straight = false;
};

// Mirror direction of d about unit normal n.
inline Vec3 mirrorDirection(const Vec3& d, const Vec3& n) { return d - 2.0 * glm::dot(d, n) * n; }

// Photopic fractions of the light arriving along the normal.
struct NormalIncidence {
  double reflectance = 0.0, specularReflectance = 0.0;
  std::optional<double> transmittance;  // families that let light through as they report it
};

// What a family's reader gets: the primitive and the materials defined before it.
struct MaterialReadContext {
  const RadPrimitive& primitive;
  // The index of the material named so far (-1: not defined): illum's alternate.
  std::function<int(const std::string&)> findMaterial;
  // The function pattern a modifier name stands for (an index into Scene::patterns; -1: void, a
  // material, or a pattern replaced by its base); a name not defined, or one whose refusal is kept,
  // is refused: WGMDfunc's parts' modifiers.
  std::function<int(const std::string&)> findPattern;
  // The window system's scattering of a BSDF file the primitive names (engine/bsdf.h), read once
  // per file and owned by the scene; InputError at the primitive when it cannot be found or read.
  std::function<const Bsdf*(const std::string&)> findBsdf;

  [[noreturn]] void fail(const std::string& message) const;
  // "TYPE 'NAME'", the start of every message about the primitive.
  std::string what() const;
  void expectReals(size_t n) const;
  void expectStrings(size_t maxN) const;
  Vec3 vec(size_t i) const;
  // Refuses a negative colour component.
  void expectNonNegative(const Rgb& color) const;
  // Refuses an emitter's radiance with a negative component or above 1e30 W/sr/m² (far above the
  // sun's 2e7; beyond it the light would overflow in products).
  void expectRadiance(const Rgb& radiance) const;
  // The alternate material the first string argument names (-1: none or void).
  int alternate() const;
};

class MaterialFamily {
 public:
  virtual ~MaterialFamily() = default;

  virtual MaterialType type() const = 0;
  // Radiance's name of the type.
  virtual const char* name() const = 0;
  virtual HitRole role() const = 0;

  // Reads the primitive's arguments into m (its type, name, location and pattern are set) and
  // refuses what cannot exist (more light out than in, a radiance that would overflow).
  virtual void read(const MaterialReadContext& ctx, Material& m) const = 0;
  // The reflectance and transmittance parts the integrators use, from the arguments (Radiance's
  // definitions); nothing for families that have none.
  virtual void derive(MaterialParameters& /*m*/) const {}

  // Emits light; and among emitters, is sampled explicitly as a light source (glow is not: it is
  // found by the hemisphere's rays).
  virtual bool emits() const { return false; }
  virtual bool sampledSource() const { return false; }
  // The material non-shadow rays see instead (illum: its alternate, -1 meaning none, so the ray
  // passes straight on); nullopt: the material itself.
  virtual std::optional<int> seenInstead(const Material& /*m*/) const { return std::nullopt; }

  // Shadow rays (Tracer::transmittance): whether surfaces of m may let a straight ray through
  // (the tracer then walks its shadow rays hit by hit), and the fraction they let through along
  // unit dir (geometric normal ng): nullopt when opaque.
  virtual bool mayPassShadowRays(const Material& /*m*/) const { return false; }
  virtual std::optional<Rgb> straightTransmittance(const Material& /*m*/, const Vec3& /*dir*/,
                                                   const Vec3& /*ng*/) const {
    return std::nullopt;
  }
  // Whether the sky is seen straight through surfaces of m (guides sky sampling as a portal:
  // engine/portals.h), and whether they are window glazing (the annual study's window groups and
  // blinds name the glass a beam came through).
  virtual bool seeThrough(const Material& /*m*/) const { return false; }
  virtual bool isGlazing() const { return false; }
  // Flat surfaces of the family reflect the light sources as virtual sources, which the direct
  // integrator samples (engine/lights.h); such surfaces are kept as shapes, never mesh triangles.
  virtual bool mirrorsSources() const { return false; }
  // Surfaces of the family let light through (drawn as glazing on plans): glass, dielectric,
  // trans, illum (mkillum's windows).
  virtual bool transmitting() const { return false; }
  // The photopic fraction of a view seen straight through a surface of m (sight lines: what an
  // observer sees past it); 0 for opaque families. illum: see seenMaterial.
  virtual double viewTransmittance(const Material& /*m*/) const { return 0.0; }
  // Reflectance and transmittance at normal incidence (photopic), for the report's material
  // table: by default the derived reflectance ρ_d + ρ_s and no transmittance.
  virtual NormalIncidence normalIncidence(const Material& m) const;

  // kScatter: whether the irradiance cache may serve its diffuse reflection (opaque, diffusely
  // reflecting), and whether all it reflects is ρE/π (no lobe, nothing transmitted), so that an
  // irradiance estimate may stand in for a path.
  virtual bool cacheable(const Material& /*m*/) const { return false; }
  virtual bool matteOpaque(const Material& /*m*/) const { return false; }
  // kScatter: one direction of the glossy lobe for a ray arriving along inDir on the side of nf;
  // false when the sample is lost (engine/materials/normal.h).
  virtual bool sampleLobe(const Material& /*m*/, const Vec3& /*inDir*/, const Vec3& /*nf*/, Rng& /*rng*/,
                          Vec3& /*out*/) const {
    return false;
  }
  // kScatter: the weight a direction `out` drawn by sampleLobe carries (its BRDF times the cosine
  // over the density it was drawn with), at most m.specularReflectance, by which paths choose the
  // lobe. Radiance's Ward lobes carry the specular reflectance itself (the default); ashik2's
  // carries less where its BRDF's max(cos θi, cos θo) falls short of the density's.
  virtual Rgb lobeWeight(const Material& m, const Vec3& /*inDir*/, const Vec3& /*nf*/, const Vec3& /*out*/) const {
    return m.specularReflectance;
  }
  // kScatter: whether m's specular transmission is a rough lobe about the straight-through
  // direction (WGMDfunc with ts roughness) rather than straight through; then one direction of it
  // for a ray arriving along inDir, nf the normal facing that ray (false: the draw was lost).
  virtual bool roughTransmission(const Material& /*m*/) const { return false; }
  virtual bool sampleTransmittedLobe(const Material& /*m*/, const Vec3& /*inDir*/, const Vec3& /*nf*/, Rng& /*rng*/,
                                     Vec3& /*out*/) const {
    return false;
  }
  // The number of patterns of functions the family's primitive names (plastic2's u direction: 1;
  // BRTDfunc's specular reflectance and transmittance: 2): the reader reads them into
  // Scene::patterns, the first at Material::functions, before read().
  virtual int functionPatterns() const { return 0; }
  // The parts at a hit p of a material with such functions, in out (m's parameters, its colour
  // already multiplied by its patterns' colour patternColour, its parts derived from it):
  // engine/materials/pattern_hook.h calls it.
  virtual void atHit(const Material& /*m*/, const PatternPoint& /*p*/, const Rgb& /*patternColour*/,
                     PatternEvaluator& /*eval*/, MaterialParameters& /*out*/) const {}

  // Light of the sampled sources that depends on its direction (Radiance's dirbrdf,
  // src/rt/m_brdf.c: plasfunc, metfunc, transfunc, their data forms, BRTDfunc's directional
  // functions): whether m has such a part. Its surfaces then take the sampled sources' light with
  // sourceBrdf, and the rest (the sky, light met by paths) with the parts derived (diffuse
  // reflectance and transmittance over π), as Radiance's ambient does.
  virtual bool directionalSources(const Material& /*m*/) const { return false; }
  // The BRDF (per sr) for light of a sampled source arriving along unit ldir, the source's solid
  // angle from the hit omegaSr, at hit p of m (its parts as the hook left them): reflected on the
  // side the ray met (transmitted false), or through from the other side.
  virtual Rgb sourceBrdf(const Material& /*m*/, const PatternPoint& /*p*/, PatternEvaluator& /*eval*/,
                         const Vec3& /*ldir*/, double /*omegaSr*/, bool /*transmitted*/) const {
    return Rgb(0.0);
  }

  // kScatter families whose paths go on in directions drawn from a scattering function (BSDF,
  // aBSDF) instead of the diffuse, lobe and straight parts; their sampled sources' light is
  // sourceBrdf's (directionalSources), the sky's arrives along the drawn paths only.
  virtual bool samplesScattering(const Material& /*m*/) const { return false; }
  // One continuation for the ray met at p (its direction p.d, the material's parts as the hook
  // left them), u two stratified uniform numbers; false when the path ends there.
  virtual bool sampleScattering(const Material& /*m*/, const PatternPoint& /*p*/, const Vec2& /*u*/, Rng& /*rng*/,
                                ScatterSample& /*s*/) const {
    return false;
  }
  // Where a transmitted continuation starts, from the hit (BSDF's thickness: beyond a proxy's
  // detail geometry); geometric normal ng.
  virtual Vec3 transmittedOffset(const Material& /*m*/, const Vec3& /*ng*/) const { return Vec3(0.0); }
  // Whether rays arriving on that side (front: the normal's) pass straight on (a BSDF proxy's
  // hidden side).
  virtual bool hidesSide(const Material& /*m*/, bool /*front*/) const { return false; }
  // Whether the camera's primary rays pass straight through surfaces of m (a BSDF proxy: the
  // detail geometry behind it is what a view shows, as Radiance's m_bsdf.c lets rays that are
  // neither specular nor ambient through).
  virtual bool passesPrimaryRays(const Material& /*m*/) const { return false; }

  // kSpecular: one sampled event (paths), or every part at once (the camera).
  virtual SpecularSample sampleSpecular(const Material& /*m*/, const SurfaceHit& /*h*/, Rng& /*rng*/,
                                        Rgb& /*beta*/) const {
    return {};
  }
  virtual SpecularSplit splitSpecular(const Material& /*m*/, const SurfaceHit& /*h*/) const { return {}; }
};

// The family of a material type, and the family a Radiance type name reads (nullptr: no family;
// "spotlight" reads as light).
const MaterialFamily& familyOf(MaterialType type);
inline const MaterialFamily& familyOf(const Material& m) { return familyOf(m.type); }
const MaterialFamily* familyNamed(std::string_view radianceType);
// The Radiance types the families read, comma-separated (for messages).
std::string materialTypeNames();

// What non-shadow rays see of `m` among `materials`: m itself, illum's alternate, or nullptr
// (an illum with no alternate: rays pass straight on).
inline const Material* seenMaterial(const std::vector<Material>& materials, const Material& m) {
  const std::optional<int> other = familyOf(m).seenInstead(m);
  if (!other) return &m;
  return *other < 0 ? nullptr : &materials[static_cast<size_t>(*other)];
}

}  // namespace candela
