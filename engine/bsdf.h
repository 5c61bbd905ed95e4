// A window system's measured or simulated scattering (LBNL's BSDF XML: Klems matrices or tensor
// trees, read by engine/radiance/bsdf_xml.h), queried by the BSDF and aBSDF materials
// (engine/materials/bsdf.cpp).
//
// Frame: Radiance's local BSDF frame (src/common/bsdf.h, src/rt/m_bsdf.c): +z is the side the
// Radiance surface normal points to, which is the XML's "back" (the room side of a WINDOW or
// genBSDF export); the XML's "front" (the exterior) is -z; +y is the material's up vector
// projected on the surface, x = y × z. Both directions of every query point away from the
// surface: `in` towards where the light comes from, `out` towards where it goes (the viewer).
// Same hemisphere: reflection; opposite hemispheres: transmission.
#pragma once

#include "base/units.h"  // Rgb (and base/math.h)

#include <memory>
#include <string>

namespace candela {

class Bsdf {
 public:
  // One direction drawn by sampleIn.
  struct Sample {
    Vec3 in{0.0};      // unit, away from the surface
    Rgb weight{0.0};   // f(in, out) |cos in| / pdf
    double pdf = 0.0;  // per sr
  };

  virtual ~Bsdf() = default;

  // The scattering (per sr) of light arriving from `in` towards `out`, both unit, local frame.
  // Where the file lacks the component asked for, Radiance's rules apply: transmission from the
  // other side by reciprocity (f_t(in, out) = f_t'(out, in)), reflection zero. With
  // withoutPeak, the direct (peak) part that peakThrough reports is left out.
  virtual Rgb eval(const Vec3& in, const Vec3& out, bool withoutPeak = false) const = 0;

  // Draws the direction light arrives from for a viewer along `out`, with a density as close to
  // f(in, out)|cos in| as the representation gives (a Klems patch by its share, uniform in
  // projected solid angle inside it; a tree's cell likewise), from u (two uniform numbers, for
  // the position inside the patch or cell) and pick (one uniform number, for choosing it).
  // False when nothing scatters towards out. withoutPeak as for eval.
  virtual bool sampleIn(const Vec3& out, const Vec2& u, double pick, Sample& s, bool withoutPeak = false) const = 0;
  // The density (per sr) with which sampleIn draws `in` for `out`.
  virtual double pdfIn(const Vec3& in, const Vec3& out, bool withoutPeak = false) const = 0;

  // ∫ f(in, out) |cos in| d(in) over the hemisphere the light arrives from: on out's side
  // (transmitted false) or the other (true). The total weight sampleIn's draws carry.
  virtual Rgb albedoToward(const Vec3& out, bool transmitted, bool withoutPeak = false) const = 0;
  // ∫ f(in, out) |cos out| d(out) for light arriving from `in`: the hemispherical transmittance
  // (transmitted) or reflectance the file describes for that direction.
  virtual Rgb hemispherical(const Vec3& in, bool transmitted) const = 0;

  // The direct part for light arriving from `in`: the fraction that passes straight through
  // unscattered (to -in), as Radiance's aBSDF takes it out of the data (src/rt/m_bsdf.c,
  // compute_through): zero where the data have no peak standing out in the through direction.
  virtual Rgb peakThrough(const Vec3& in) const = 0;

  // Whether the file gives reflection on the +z side (back) and on the -z side (front), and any
  // transmission.
  virtual bool reflects(bool plusZSide) const = 0;
  virtual bool transmits() const = 0;

  // "Klems full", "Klems half", "Klems quarter", "tensor tree 3", "tensor tree 4" (for summary
  // and messages).
  virtual std::string kind() const = 0;
};

}  // namespace candela
