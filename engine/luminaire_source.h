// A luminaire placed in a scene: its candlepower distribution, position and orientation.
// The tracer samples it as a light source (see lights.cpp) over its luminous opening at every
// distance, each point of the opening carrying I/A so that the opening as a whole reproduces I
// and a screen that hides part of the opening gives the right penumbra; a point luminaire (no
// opening) follows the point law E = I(θ, φ) cos ι / d².
#pragma once

#include "base/math.h"
#include "photometry/photometric_web.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

namespace candela {

struct LuminaireSource {
  std::shared_ptr<const PhotometricWeb> web;
  std::string name;
  Vec3 position{0.0};    // photometric centre, m
  // Luminaire axes in world coordinates: x = C0 plane, y = C90 plane, z = up (= −nadir).
  Vec3 axisX{1.0, 0.0, 0.0}, axisY{0.0, 1.0, 0.0}, axisZ{0.0, 0.0, 1.0};
  double scale = 1.0;    // multiplier × maintenance factor
  // Luminous opening (m) in the luminaire's x/y plane: a rectangle widthM × lengthM, a disc of
  // diameter widthM (circular), or a point (both zero).
  double widthM = 0.0, lengthM = 0.0;
  bool circular = false;
  // The opening as a surface of the scene (`opening_reflectance`, addOpeningSurface): its shape
  // index, which the luminaire's own shadow rays pass through; UINT32_MAX (kNoShape): none.
  uint32_t openingShape = std::numeric_limits<uint32_t>::max();

  // Largest intensity (cd, scaled) over all C planes in each of kCosBins bands of cos γ (γ from
  // the nadir), for cheap light selection without trigonometry (engine/light_selection.h).
  static constexpr int kCosBins = 32;
  std::array<double, kCosBins> peakByCosGamma{};
  bool peakTabulated = false;
  // Intensity in cd towards the world direction `dir` (from the luminaire), scaled.
  double intensityCd(const Vec3& dir) const {
    return scale * web->intensityCd(Vec3(glm::dot(dir, axisX), glm::dot(dir, axisY), glm::dot(dir, axisZ)));
  }
  double sizeM() const { return std::max(widthM, lengthM); }
  double openingAreaM2() const { return circular ? 0.25 * kPi * widthM * widthM : widthM * lengthM; }
};

// Orients a luminaire: `aim` is the direction of the photometric nadir (world), `spinDeg` turns
// it about its own up axis (−aim) counter-clockwise seen from above a downlight, so that with
// aim [0,0,−1] and spin 0 the C0 plane points to +X and C90 to +Y; with spin 90, C0 → +Y.
void orientLuminaire(LuminaireSource& l, const Vec3& aim, double spinDeg);

// Fills peakByCosGamma from the web (sampled every 5° in C and at the ends and middle of each
// cos γ band).
void tabulatePeakIntensity(LuminaireSource& l);

// How a luminaire is mounted in a scene.
struct LuminaireMounting {
  std::string name;
  Vec3 positionM{0.0};       // photometric centre, m
  Vec3 aim{0.0, 0.0, -1.0};  // unit direction of the photometric nadir
  double spinDeg = 0.0;      // about the aim (orientLuminaire); 0: C0 plane towards +X
  double scale = 1.0;        // multiplies every intensity
};

// A luminaire of photometric web `web` mounted as `m`: oriented, its opening set from the web and
// its peak intensities tabulated.
LuminaireSource placeLuminaire(std::shared_ptr<const PhotometricWeb> web, const LuminaireMounting& m);

// Sets the opening from the photometric file's luminous opening: flat rectangles and discs as
// given; other shapes by their plan (width × length) footprint; a point when both are zero.
void setOpeningFromWeb(LuminaireSource& l);

}  // namespace candela
