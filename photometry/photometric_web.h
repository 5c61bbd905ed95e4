// One in-memory model of a luminaire's luminous intensity distribution, whatever file it came
// from (IES LM-63 or EULUMDAT): absolute candelas on an angular grid with the file's symmetry
// expanded, plus the header data a designer needs (lamp lumens, watts, luminous opening).
//
// Axes (luminaire-local, see docs/luminaires.md):
//   photometric nadir (gamma = 0) is -Z, the C0 plane points to +X and C90 to +Y, i.e. C is
//   measured counterclockwise from +X seen from above (IES LM-63 / CIE 121 convention).
//   Type B (floodlight) webs: the beam axis (H = V = 0) is -Z; V (the tilt of the B-plane about
//   the horizontal axis +Y) turns the beam towards +X; H (the angle inside a B-plane, i.e. the
//   latitude from the plane through the beam axis and X) turns it towards +Y.
#pragma once

#include "base/error.h"
#include "base/math.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace candela {

enum class PhotometricType { kC, kB };

// Which part of C 0-360 a type C file stores; the rest follows by mirror symmetry.
enum class PlaneSymmetry {
  kNone,          // full 0-360 (the last plane may stop short of 360; C wraps periodically)
  kRotational,    // one plane, the same in every C
  kMirrorC0C180,  // planes 0-180 stored; I(C) = I(360 - C)
  kMirrorC90C270, // planes 90-270 (or -90..90) stored; I(C) = I(180 - C)
  kQuadrant,      // planes 0-90 stored; symmetric about both planes
};

// Shape of the luminous opening (LM-63-2019 table 1 sign conventions; see ies_lm63.cpp).
enum class OpeningShape {
  kPoint,
  kRectangular,               // flat rectangle width x length
  kRectangularWithSides,      // box: rectangle with luminous sides of the given height
  kCircular,                  // flat disc, diameter = width
  kEllipse,                   // flat ellipse width x length
  kVerticalCylinder,          // diameter = width, height
  kVerticalEllipticalCylinder,
  kSphere,                    // diameter = width
  kEllipsoid,
  kHorizontalCylinderAlongWidth,   // axis along C0-C180 (X)
  kHorizontalCylinderAlongLength,  // axis along C90-C270 (Y)
  kVerticalCircle,                 // disc in a vertical plane
  kVerticalEllipse,
  kOther,                          // a sign combination not in the table
};
const char* openingShapeName(OpeningShape shape);

// The TILT data of an IES file and the multiplier that was applied for the installed
// orientation (see docs/luminaires.md "Tilt").
struct TiltData {
  std::string source = "NONE";  // NONE, INCLUDE or the TILT file's name
  int lampGeometry = 0;         // 1 vertical base-up/down, 2 horizontal along C90, 3 along C0
  std::vector<double> anglesDeg;
  std::vector<double> multipliers;
  double appliedAngleDeg = 0.0;
  double appliedMultiplier = 1.0;
};

// One EULUMDAT lamp set (line 26a-f).
struct LampSet {
  int count = 0;             // negative: absolute photometry (common practice)
  std::string type;
  double totalFluxLm = 0.0;  // total luminous flux of the set's lamps
  std::string colour;
  std::string colourRendering;
  double wattsW = 0.0;       // including ballast
};

// Header data shared by both formats. Lengths in metres, flux in lumens, power in watts.
struct PhotometricInfo {
  std::string format;                          // "IES LM-63-2002", "EULUMDAT", ...
  std::string fileName;
  std::map<std::string, std::string> keywords; // IES [KEYWORD] lines; EULUMDAT text fields
  int numLamps = 1;
  double lumensPerLamp = -1.0;                 // -1: absolute photometry
  double lampLumens = -1.0;                    // rated total; <= 0 when absolute
  double candelaMultiplier = 1.0;
  double ballastFactor = 1.0;
  double ballastLampFactor = 1.0;              // LM-63-1986/1991 "ballast-lamp photometric factor", 1995/2002 "future use"
  double fileGenerationType = 0.0;             // LM-63-2019 only (not a multiplier)
  double inputWatts = 0.0;                     // 0 when not given
  double openingWidthM = 0.0;                  // along C0-C180 (X); diameter for round shapes
  double openingLengthM = 0.0;                 // along C90-C270 (Y)
  double openingHeightM = 0.0;                 // along Z
  OpeningShape openingShape = OpeningShape::kPoint;
  FileLoc openingLoc;                          // where the file gives the opening (IES: its width; EULUMDAT: line 16)
  double luminaireLengthM = 0.0;               // EULUMDAT lines 13-15 (outer dimensions); 0 if unknown
  double luminaireWidthM = 0.0;
  double luminaireHeightM = 0.0;
  TiltData tilt;
  std::vector<LampSet> lampSets;               // EULUMDAT
  double declaredLorPercent = -1.0;            // EULUMDAT line 23; -1 when not given
  double declaredDownwardFluxPercent = -1.0;   // EULUMDAT line 22
  double conversionFactor = 1.0;               // EULUMDAT line 24
};

struct CGamma {
  double cDeg = 0.0;
  double gammaDeg = 0.0;
};

class PhotometricWeb {
 public:
  PhotometricWeb() = default;
  // planeAnglesDeg: C (type C) or H (type B) angles as stored, strictly increasing.
  // polarAnglesDeg: gamma (type C) or V (type B) angles, strictly increasing.
  // candelaCd[i * polar.size() + j]: absolute candela at plane i, polar angle j, every multiplier
  // already applied. Type C planes are expanded by `symmetry`; type B grids whose first H (or V)
  // angle is 0 are mirrored to negative angles (LM-63: laterally symmetric).
  PhotometricWeb(PhotometricInfo info, PhotometricType type, PlaneSymmetry symmetry,
                 std::vector<double> planeAnglesDeg, std::vector<double> polarAnglesDeg,
                 std::vector<double> candelaCd);

  // Intensity in cd: bilinear in (C, gamma) on the expanded grid, C periodic, zero outside the
  // measured gamma range. Type B webs convert (C, gamma) to a direction and then to (H, V).
  double intensityCd(double cDeg, double gammaDeg) const;
  // Intensity in cd towards a luminaire-local direction (any length > 0), axes as above.
  double intensityCd(const Vec3& dirLocal) const;

  // Luminous flux in lm: exact integral of the bilinear interpolant over the sphere.
  double totalLumens() const;
  // Flux in lm in zones of zoneDeg of gamma from nadir (0-zone, zone-2zone, ... up to 180).
  std::vector<double> zonalLumens(double zoneDeg = 10.0) const;
  // Flux in lm between gamma0Deg and gamma1Deg (all C).
  double lumensBetween(double gamma0Deg, double gamma1Deg) const;

  double maxIntensityCd() const { return maxCd_; }
  CGamma maxIntensityDirection() const { return maxDir_; }

  double lampLumens() const { return info_.lampLumens; }
  bool isAbsolute() const { return !(info_.lampLumens > 0.0); }
  // totalLumens / lampLumens; NaN when the lamp lumens are unknown (absolute photometry).
  double lightOutputRatio() const;
  double inputWatts() const { return info_.inputWatts; }
  const std::string& format() const { return info_.format; }
  const std::map<std::string, std::string>& keywords() const { return info_.keywords; }
  double openingWidthM() const { return info_.openingWidthM; }
  double openingLengthM() const { return info_.openingLengthM; }
  double openingHeightM() const { return info_.openingHeightM; }
  OpeningShape openingShape() const { return info_.openingShape; }
  const PhotometricInfo& info() const { return info_; }
  PhotometricType type() const { return type_; }

  // The expanded grid (type C: C 0..360 inclusive; type B: H) and the polar angles.
  const std::vector<double>& planeAnglesDeg() const { return planes_; }
  const std::vector<double>& polarAnglesDeg() const { return polar_; }
  double gridCd(size_t plane, size_t polar) const { return cd_[plane * polar_.size() + polar]; }

  // Unit luminaire-local direction of (C, gamma), and back.
  static Vec3 directionOf(double cDeg, double gammaDeg);
  static CGamma cGammaOf(const Vec3& dirLocal);

 private:
  double gridInterp(double planeDeg, double polarDeg) const;

  PhotometricInfo info_;
  PhotometricType type_ = PhotometricType::kC;
  std::vector<double> planes_, polar_, cd_;
  double maxCd_ = 0.0;
  CGamma maxDir_;
};

}  // namespace candela
