// The UGR table of a luminaire: the CIE 117-1995 tabular method in the presentation of
// CIE 190:2010 ("Calculation and presentation of unified glare rating tables for indoor lighting
// luminaires"). Pure functions of the luminaire's intensities, opening and flux; no file types.
//
// Geometry (room frame): the observer's eye at the middle of one wall (x = X/2, y = 0, z = 0),
// looking horizontally along +y; the luminaires in a regular array at height H above the eye,
// spacing S in both directions, centred in cells: ((i + ½) S, (j + ½) S, H), filling the X × Y
// room. A luminaire at distance R along the line of sight and T across it counts when
// 0 < H/R ≤ 1.9 and |T|/R ≤ 3, the extent of CIE 117's position-index table (Table 4.1).
//
// Viewing (the luminaire's long axis along C90-C270, LM-63's "length"):
//   crosswise: the line of sight crosses the luminaires; their C0 plane points back at the
//              observer (local +X = room −y, +Y = room +x);
//   endwise:   the line of sight runs along them; C90 points back at the observer
//              (local +X = room −x, +Y = room −y).
// So crosswise C = atan(T/R) from C0, endwise from C90 (CIE 117 eqs. 4.5, 4.6).
#pragma once

#include "base/math.h"
#include "metrics/glare.h"

#include <array>
#include <functional>
#include <vector>

namespace candela {

// A luminaire as the table needs it, in luminaire-local axes (nadir −Z, C0 +X, C90 +Y).
struct UgrLuminaire {
  std::function<double(const Vec3& dirLocal)> intensityCd;      // cd along a unit direction
  std::function<double(const Vec3& dirLocal)> projectedAreaM2;  // its luminous opening seen along it, m²
  // Flux in lm within the cones about the nadir of γ ≤ acos 0.75 (41.4°), 60°, acos 0.25 (75.5°)
  // and 90°: the cumulative zonal fluxes Φ_zL1…4 of CIE 190 eq. (9) (CIE 52's zones).
  std::array<double, 4> downwardConeLm{};
  double upwardLm = 0.0;  // lm above the horizontal
};

struct RoomReflectances {
  double ceiling = 0.0, walls = 0.0, floor = 0.0;  // the floor is the reference plane at eye height
};

struct UgrRoom {
  double xH = 0.0;  // across the line of sight, in units of H
  double yH = 0.0;  // along the line of sight, in units of H
};

// CIE 190's 19 rooms: X = 2H with Y = 2, 3, 4, 6, 8, 12H; X = 4H with the same; X = 8H with
// Y = 4, 6, 8, 12H; X = 12H with Y = 4, 6, 8H.
const std::vector<UgrRoom>& standardUgrRooms();
// CIE 190's reflectance combinations ceiling/walls/floor: 0.70/0.50/0.20, 0.70/0.30/0.20,
// 0.50/0.50/0.20, 0.50/0.30/0.20, 0.30/0.30/0.20.
const std::vector<RoomReflectances>& standardUgrReflectances();

enum class UgrViewing { kCrosswise, kEndwise };

struct UgrTableSettings {
  double heightM = 2.0;          // H, luminaire plane above the eye, m (the table is scale-free)
  double spacingToHeight = 0.25; // S/H (CIE 117's tabular method; CIE 190's standard condition is 1)
  std::vector<UgrRoom> rooms = standardUgrRooms();
  std::vector<RoomReflectances> reflectances = standardUgrReflectances();
};

struct UgrTable {
  UgrTableSettings settings;
  std::vector<std::vector<double>> crosswise, endwise;  // UGR [room][reflectance]
  std::vector<int> luminaires;                          // N of each room's array
  // Of the luminaires counted, every room and both viewings (0 when none): CIE 117's formula is
  // meant for 3·10⁻⁴ to 0.1 sr, CIE 147 for projected areas of 0.005 to 1.5 m².
  double minSolidAngleSr = 0.0, maxSolidAngleSr = 0.0;
  double minProjectedAreaM2 = 0.0, maxProjectedAreaM2 = 0.0;
};

UgrTable computeUgrTable(const UgrLuminaire& luminaire, const UgrTableSettings& settings = {});

// --- The steps, exposed for tests -------------------------------------------------------------

// View factor between two equal, parallel, directly opposed rectangles a × b at distance c
// (any length unit), e.g. Howell's catalogue of configuration factors, C-11.
double parallelRectanglesViewFactor(double a, double b, double c);

// Flux-transfer factors to the walls of the room between the reference plane and the luminaire
// plane (X × Y × H): the flux incident on the walls, directly and after any number of
// reflections, per lumen first incident on the floor (F_T,FW), on the walls, less that first
// lumen (F_T,WW − 1), and on the ceiling (F_T,CW). Three uniformly diffuse surfaces with exact
// view factors; this reproduces CIE 190 Table 5 to its three decimals.
struct WallTransferFactors {
  double fromFloor = 0.0, fromWalls = 0.0, fromCeiling = 0.0;
};
WallTransferFactors wallTransferFactors(double xM, double yM, double hM, const RoomReflectances& rho);

// F_GL1…4 of CIE 190 Table 4 at room index k = XY / (H (X + Y)): the direct flux on the floor is
// Σ Φ_zLn F_GLn (eq. 9). Linear in k between the table's 13 room indices (1 … 4.8), held beyond.
std::array<double, 4> directRatioCoefficients(double roomIndex);

// Background luminance in cd/m² (CIE 190 eqs. 7, 8, 10-12): Lb = E_WID / π with the indirect
// illuminance at the eye taken as the walls' E_WID = N / A_w · (Φ_DF F_T,FW + Φ_DW (F_T,WW − 1)
// + Φ_DC F_T,CW), A_w = 2 H (X + Y), Φ_DF = Σ Φ_zLn F_GLn, Φ_DW = Φ_zL4 − Φ_DF, Φ_DC the
// upward flux, N luminaires of the room.
double ugrBackgroundLuminance(const UgrLuminaire& luminaire, double xM, double yM, double hM, int luminaires,
                              const RoomReflectances& rho);

// Whether a luminaire at `alongM` (R) ahead and `acrossM` (T) to the side, H above the eye,
// counts (the field described at the top of this file).
bool inUgrField(double alongM, double acrossM, double hM);

// One luminaire as the observer sees it: L = I / A_p towards the eye, ω = A_p / d², P of
// positionIndex (Guth above the line of sight). A zero projected area gives L = ω = 0.
GlareSource ugrGlareSource(const UgrLuminaire& luminaire, UgrViewing viewing, double alongM, double acrossM,
                           double hM);

}  // namespace candela
