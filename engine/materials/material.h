// A material as read from a scene: its Radiance type, its arguments and the reflectance and
// transmittance parts its family derives from them (engine/materials/family.h). What a surface of
// the material does where a ray meets it is its family's to say, never the integrators'.
#pragma once

#include "base/error.h"
#include "base/math.h"
#include "base/units.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace candela {

class Bsdf;

// The material families, one a file in engine/materials/ (registry.cpp: the table, in this order).
enum class MaterialType {
  kVoid, kPlastic, kMetal, kTrans, kMirror, kGlass, kDielectric, kLight, kIllum, kGlow, kMixture, kInterface,
  kPlastic2, kMetal2, kTrans2, kMist, kBrtdFunc, kPlasFunc, kMetFunc, kTransFunc, kPlasData, kMetData, kTransData,
  kAshik2, kWgmdFunc, kAntimatter, kBsdf, kABsdf
};
inline constexpr int kMaterialTypeCount = 28;

// Radiance's name of the type ("plastic", ...): the family's (engine/materials/registry.cpp).
const char* materialTypeName(MaterialType t);

// A material's parameters as read from the scene, with the derived reflectances the integrators
// use: all of a material but its name and where it was read, so that a patterned copy at a hit
// (engine/materials/pattern_hook.h) copies no string. Colours are Radiance RGB; emission is a
// radiance in W/sr/m² (179 lm/W).
struct MaterialParameters {
  MaterialType type = MaterialType::kVoid;
  Rgb color{0.0};        // plastic/metal/trans/mirror/glass colour, light/glow/illum radiance or
                         // dielectric transmission per metre of path inside (fraction, per channel)
  double specularity = 0.0;   // plastic, metal, trans, plasfunc… (fraction)
  double roughness = 0.0;     // plastic, metal, trans (rms slope); plastic2, metal2, trans2: along u
  // plastic2, metal2, trans2 (anisotropic Ward): the rms slope across u and the u direction at a
  // hit (world, set by engine/materials/pattern_hook.h; zero until then).
  double roughnessV = 0.0;
  // WGMDfunc at a hit: its specular transmission's rms slopes along u and across it (0: straight
  // through, Radiance's SP_TPURE).
  double transmissionRoughnessU = 0.0, transmissionRoughnessV = 0.0;
  Vec3 anisotropyU{0.0};  // BSDF, aBSDF: the up vector at a hit (world)
  // At a hit: the perturbation of the front normal by the textures modifying the material
  // (texfunc, texdata: Radiance's r->pert, world), set by engine/materials/pattern_hook.h; zero
  // elsewhere.
  Vec3 perturbation{0.0};
  // The first of the patterns (Scene::patterns) holding the functions of the family's own
  // arguments, evaluated at each hit (MaterialFamily::atHit): plastic2's u direction; BRTDfunc's
  // specular reflectance, then (functions + 1) its specular transmittance. -1: none.
  int functions = -1;
  // BRTDfunc: the back side's diffuse reflectance and the diffuse transmittance as given (color is
  // the front's), and whether its specular transmittance can be non-zero.
  Rgb backColor{0.0};
  Rgb transmissionColor{0.0};
  bool specularTransmission = false;
  // BRTDfunc: whether its directional functions (rbrtd gbrtd bbrtd) are not all 0. WGMDfunc at a
  // hit: whether its mirror is Fresnel-raised there, so that the sampled sources' light on its
  // diffuse parts takes the second factor of their own angle (m_wgmdf.c's dirwgmdf).
  bool directionalFunctions = false;
  // At a hit: the colour of the patterns modifying the material (1 elsewhere), set by
  // engine/materials/pattern_hook.h (BRTDfunc's CrP CgP CbP).
  Rgb patternColour{1.0};
  double transmissivity = 0.0;  // trans, transfunc, transdata: fraction of non-specular light transmitted
  double transmittedSpecular = 0.0;  // the same: fraction of transmitted light that is specular
  double refractiveIndex = 1.52;     // glass, dielectric (relative to the medium on the front side)
  double hartmannConstant = 0.0;     // dielectric: read, not used (no dispersion; docs/engine.md)
  // interface: the medium on the front side (the outside), its transmission per metre and index;
  // color and refractiveIndex are the inside's. A dielectric's outside is a vacuum (1, 1).
  Rgb outsideTransmission{1.0};
  double outsideIndex = 1.0;
  double glowRadiusM = 0.0;          // glow: Radiance's maximum radius for source testing
  int alternate = -1;                // illum: material seen by non-shadow rays (-1: none/void)
  // spotlight (a `light` with a cone, Radiance reference manual "Spotlight"): light leaves only
  // within spotCosHalf of spotAim (unit); the aim's length as given is the focal distance behind
  // the source, which scales the direct light at distance d by d²/(d + focal)² (Radiance
  // src/rt/source.c). spot false: an ordinary light.
  bool spot = false;
  double spotCosHalf = -1.0;
  Vec3 spotAim{0.0, 0.0, -1.0};
  double spotFocalM = 0.0;
  // mixfunc: the two materials mixed (-1: void), the coefficient being pattern's function.
  int foreground = -1, background = -1;
  // ashik2 (Ashikhmin-Shirley): the specular colour as given (color is the diffuse one) and the
  // lobe's Phong exponents along u and across it.
  Rgb specularColor{0.0};
  double exponentU = 0.0, exponentV = 0.0;
  // WGMDfunc: which of its specular reflection (1), specular transmission (2) and diffuse
  // transmission (4) take the material's own pattern colour (their modifier `inherit` or the
  // material's modifier; `void` leaves them white).
  int inheritsPattern = 0;
  // WGMDfunc: the pattern of each part's own modifier (rs_mod, ts_mod, td_mod; an index into
  // Scene::patterns), -1 where the part inherits the material's or has none.
  std::array<int, 3> partPatterns{-1, -1, -1};
  // BSDF, aBSDF (engine/materials/bsdf.cpp): the window system's scattering (Scene::bsdfs owns
  // it) and BSDF's thickness (m; 0 for aBSDF). color, backColor and transmissionColor
  // hold the diffuse parts added to it (front reflection, back reflection, transmission).
  const Bsdf* bsdf = nullptr;  // owned by the scene
  double thicknessM = 0.0;
  int pattern = -1;                  // the pattern modifying it that candela implements
                                     // (index into Scene::patterns; -1: none)
  // Antimatter (engine/antimatter.h): clipBit, this material's bit in the rays' clip sets when an
  // antimatter lists it (-1: none does); an antimatter's clipMask (the bits of the materials it
  // lists) and shownMaterial (its first modifier, what its surface is seen as from inside a
  // clipped object; -1: void).
  int clipBit = -1;
  uint16_t clipMask = 0;
  int shownMaterial = -1;
  // Derived (Radiance's definitions of plastic, metal and trans):
  Rgb diffuseReflectance{0.0};
  Rgb diffuseTransmittance{0.0};
  Rgb specularTransmittance{0.0};
  Rgb specularReflectance{0.0};

  // The spotlight's factor for light leaving towards unit direction `out` to a receiver at
  // distance d (1 for other materials): 0 outside the cone, d²/(d + focal)² inside.
  double spotFactor(const Vec3& out, double d) const {
    if (!spot) return 1.0;
    if (glm::dot(spotAim, out) < spotCosHalf) return 0.0;
    const double r = d / (d + spotFocalM);
    return r * r;
  }
  // Whether light leaves towards `out` at all (rays that meet the source see its radiance inside
  // the cone, black outside, as Radiance's srcvalue).
  bool emitsTowards(const Vec3& out) const { return !spot || glm::dot(spotAim, out) >= spotCosHalf; }

  // Emits light (light, spotlight, illum, glow): its family's word.
  bool isEmitter() const;
  // Light sources sampled explicitly (light, illum); glow is found by hemisphere sampling.
  bool isSampledSource() const;
};

struct Material : MaterialParameters {
  std::string name;
  FileLoc loc;
  // antimatter: the materials it lists, in order (void left out, each once); the reader gives
  // them their clip bits.
  std::vector<int> clipList;
};

// Fills a material's derived reflectances from its type and parameters (its family's derive).
void deriveMaterial(MaterialParameters& m);

}  // namespace candela
