// The UGR table's steps against closed forms and the published tables of CIE 190:2010. Literal
// reference numbers were computed separately (a few lines of Python with the formulas quoted in
// each test) or are CIE 190's own, cited where used.
#include "metrics/ugr_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace candela {
namespace {

// γ of a luminaire-local direction from the nadir (−Z).
double cosGamma(const Vec3& d) { return -glm::normalize(d).z; }

// A downlight I = i0 cos γ below the horizontal (Lambertian: the flux in the cone γ ≤ g is
// π i0 sin² g) with a flat opening a × b.
UgrLuminaire lambertian(double i0, double a, double b) {
  UgrLuminaire l;
  l.intensityCd = [i0](const Vec3& d) { return std::max(0.0, i0 * cosGamma(d)); };
  l.projectedAreaM2 = [a, b](const Vec3& d) { return a * b * std::abs(glm::normalize(d).z); };
  const double cosCone[4] = {0.75, 0.5, 0.25, 0.0};
  for (int n = 0; n < 4; ++n) l.downwardConeLm[n] = kPi * i0 * (1.0 - cosCone[n] * cosCone[n]);
  return l;
}

// A linear luminaire: brighter across its long axis (C0) than along it (C90).
UgrLuminaire linear() {
  UgrLuminaire l = lambertian(1000.0, 0.1, 1.2);
  l.intensityCd = [](const Vec3& d) {
    const Vec3 u = glm::normalize(d);
    return u.z < 0.0 ? 1000.0 * -u.z * (0.6 + 0.4 * std::abs(u.x) / std::max(1e-12, std::hypot(u.x, u.y))) : 0.0;
  };
  return l;
}

TEST(UgrTable, StandardRoomsAndReflectancesAreCie190s) {
  const std::vector<UgrRoom>& rooms = standardUgrRooms();
  ASSERT_EQ(rooms.size(), 19u);
  EXPECT_EQ(rooms.front().xH, 2.0);
  EXPECT_EQ(rooms.front().yH, 2.0);
  EXPECT_EQ(rooms.back().xH, 12.0);
  EXPECT_EQ(rooms.back().yH, 8.0);
  ASSERT_EQ(standardUgrReflectances().size(), 5u);
  EXPECT_EQ(standardUgrReflectances()[1].walls, 0.3);
}

TEST(UgrTable, RotationallySymmetricLuminaireLooksTheSameCrosswiseAndEndwise) {
  // I depends on γ alone and the opening is a square box: turning the luminaire by 90° about
  // the vertical changes nothing the observer sees.
  UgrLuminaire l = lambertian(1000.0, 0.6, 0.6);
  l.projectedAreaM2 = [](const Vec3& dir) {
    const Vec3 d = glm::normalize(dir);
    return 0.36 * std::abs(d.z) + 0.6 * 0.08 * (std::abs(d.x) + std::abs(d.y));
  };
  const UgrTable t = computeUgrTable(l);
  for (size_t i = 0; i < t.crosswise.size(); ++i)
    for (size_t j = 0; j < t.crosswise[i].size(); ++j) {
      EXPECT_TRUE(std::isfinite(t.crosswise[i][j]));
      EXPECT_NEAR(t.crosswise[i][j], t.endwise[i][j], 1e-9) << "room " << i << " reflectances " << j;
    }
  // The test can tell the two apart: a linear luminaire differs.
  const UgrTable lin = computeUgrTable(linear());
  EXPECT_GT(std::abs(lin.crosswise[10][0] - lin.endwise[10][0]), 0.3);
}

TEST(UgrTable, OneLuminaireAgainstTheFormulaByHand) {
  // A luminaire R = 3 m ahead, T = 1.5 m to the side, H = 2 m above the eye; flat opening
  // 0.6 × 1.2 m; I = 800 + 400 dx + 100 dy cd along the local direction d; Lb = 40 cd/m².
  UgrLuminaire l;
  l.intensityCd = [](const Vec3& d) { return 800.0 + 400.0 * d.x + 100.0 * d.y; };
  l.projectedAreaM2 = [](const Vec3& d) { return 0.72 * std::abs(glm::normalize(d).z); };
  const double r = 3.0, t = 1.5, h = 2.0, lb = 40.0;
  const double dist = std::sqrt(r * r + t * t + h * h);
  // Guth (CIE 117, IES handbook form): σ from the line of sight, τ from the vertical in the image.
  const double sigma = radToDeg(std::acos(r / dist)), tau = radToDeg(std::atan(t / h));
  const double p = std::exp((35.2 - 0.31889 * tau - 1.22 * std::exp(-2.0 * tau / 9.0)) * 1e-3 * sigma +
                            (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
  const double area = 0.72 * h / dist, omega = area / (dist * dist);
  // Crosswise the local +X (C0) points back to the observer: d = (R, −T, −H)/dist; endwise
  // +Y (C90) does: d = (T, R, −H)/dist.
  const double iCross = 800.0 + 400.0 * r / dist - 100.0 * t / dist;
  const double iEnd = 800.0 + 400.0 * t / dist + 100.0 * r / dist;
  const auto ugrOf = [&](double i) {
    const double lum = i / area;
    return 8.0 * std::log10(0.25 / lb * lum * lum * omega / (p * p));
  };
  const GlareSource cross = ugrGlareSource(l, UgrViewing::kCrosswise, r, t, h);
  const GlareSource end = ugrGlareSource(l, UgrViewing::kEndwise, r, t, h);
  EXPECT_NEAR(cross.solidAngleSr, omega, 1e-15);
  EXPECT_NEAR(cross.positionIndex, p, 1e-12);
  EXPECT_NEAR(unifiedGlareRating(lb, {cross}), ugrOf(iCross), 1e-9);
  EXPECT_NEAR(unifiedGlareRating(lb, {end}), ugrOf(iEnd), 1e-9);
  // The same numbers from a separate Python evaluation of these formulas.
  EXPECT_NEAR(unifiedGlareRating(lb, {cross}), 15.394672119050368, 1e-9);
  EXPECT_NEAR(unifiedGlareRating(lb, {end}), 15.140366753568893, 1e-9);
  // The sign of T does not matter to P; it mirrors the luminaire.
  EXPECT_NEAR(ugrGlareSource(l, UgrViewing::kCrosswise, r, -t, h).positionIndex, p, 1e-12);
}

TEST(UgrTable, FieldIsTheExtentOfTheGuthTable) {
  EXPECT_TRUE(inUgrField(1.0, 3.0, 1.9));    // T/R = 3, H/R = 1.9: the table's corner
  EXPECT_FALSE(inUgrField(1.0, 3.01, 1.0));
  EXPECT_FALSE(inUgrField(1.0, 0.0, 1.91));
  EXPECT_FALSE(inUgrField(0.0, 0.0, 1.0));   // overhead
  EXPECT_FALSE(inUgrField(-1.0, 0.0, 0.1));  // behind
}

// The view factor between parallel opposed rectangles by a midpoint sum over one of them of
// the differential-area-to-rectangle factor (Howell's catalogue B-3, four corner rectangles).
double cornerFactor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  return 1.0 / kTwoPi *
         (x / std::sqrt(1.0 + x * x) * std::atan(y / std::sqrt(1.0 + x * x)) +
          y / std::sqrt(1.0 + y * y) * std::atan(x / std::sqrt(1.0 + y * y)));
}
double pointToRectangle(double px, double py, double a, double b, double c) {
  return cornerFactor(px, py, c) + cornerFactor(a - px, py, c) + cornerFactor(px, b - py, c) +
         cornerFactor(a - px, b - py, c);
}

TEST(UgrTable, ParallelRectanglesViewFactorAgainstAQuadrature) {
  for (const auto& [a, b, c] : {std::array<double, 3>{2, 2, 1}, {4, 8, 1}, {12, 6, 1}, {1, 3, 2}}) {
    const int n = 400;
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) sum += pointToRectangle((i + 0.5) * a / n, (j + 0.5) * b / n, a, b, c);
    // The midpoint rule on a smooth integrand with 400² cells: far below 1e-4.
    EXPECT_NEAR(parallelRectanglesViewFactor(a, b, c), sum / (n * n), 1e-4) << a << " " << b << " " << c;
  }
}

TEST(UgrTable, WallTransferInLimitsWithOneReflectingSurface) {
  const double x = 8.0, y = 4.0, h = 2.0;
  const double floorToCeiling = parallelRectanglesViewFactor(x, y, h);
  const double floorToWalls = 1.0 - floorToCeiling;
  const double wallsToWalls = 1.0 - 2.0 * floorToWalls * x * y / (2.0 * h * (x + y));
  const double rho = 0.6;
  // Only the floor reflects: a lumen on it sends ρ F_fw to the walls, which absorb it.
  WallTransferFactors f = wallTransferFactors(x, y, h, {0.0, 0.0, rho});
  EXPECT_NEAR(f.fromFloor, rho * floorToWalls, 1e-12);
  EXPECT_NEAR(f.fromWalls, 0.0, 1e-12);
  EXPECT_NEAR(f.fromCeiling, 0.0, 1e-12);
  // Only the ceiling reflects: F_cw = F_fw by symmetry.
  f = wallTransferFactors(x, y, h, {rho, 0.0, 0.0});
  EXPECT_NEAR(f.fromCeiling, rho * floorToWalls, 1e-12);
  EXPECT_NEAR(f.fromFloor, 0.0, 1e-12);
  // Only the walls reflect: wall to wall again and again, Σ (ρ F_ww)^n for n ≥ 1.
  f = wallTransferFactors(x, y, h, {0.0, rho, 0.0});
  EXPECT_NEAR(f.fromWalls, rho * wallsToWalls / (1.0 - rho * wallsToWalls), 1e-12);
  // Black room: nothing comes back.
  f = wallTransferFactors(x, y, h, {0.0, 0.0, 0.0});
  EXPECT_EQ(f.fromFloor + f.fromWalls + f.fromCeiling, 0.0);
}

TEST(UgrTable, WallTransferReproducesCie190Table5) {
  // CIE 190:2010 Table 5 (F_T,FW, F_T,WW − 1, F_T,CW), three decimals: room (X, Y) in H.
  struct Row {
    double x, y;
    RoomReflectances rho;
    double fw, ww, cw;
  };
  const Row rows[] = {
      {2, 2, {0.7, 0.5, 0.2}, 0.220, 0.422, 0.646}, {4, 8, {0.7, 0.5, 0.2}, 0.115, 0.211, 0.307},
      {4, 8, {0.7, 0.3, 0.2}, 0.106, 0.117, 0.283}, {8, 8, {0.5, 0.5, 0.2}, 0.071, 0.137, 0.147},
      {2, 12, {0.5, 0.3, 0.2}, 0.128, 0.140, 0.276}, {12, 6, {0.3, 0.3, 0.2}, 0.058, 0.067, 0.081},
      {12, 6, {0.7, 0.5, 0.2}, 0.083, 0.153, 0.216},
  };
  for (const Row& r : rows) {
    const WallTransferFactors f = wallTransferFactors(r.x * 2.0, r.y * 2.0, 2.0, r.rho);
    // Rounded to three decimals in the table: within 0.0005 (and a hair for the rounding).
    EXPECT_NEAR(f.fromFloor, r.fw, 5.01e-4) << r.x << "x" << r.y;
    EXPECT_NEAR(f.fromWalls, r.ww, 5.01e-4) << r.x << "x" << r.y;
    EXPECT_NEAR(f.fromCeiling, r.cw, 5.01e-4) << r.x << "x" << r.y;
  }
}

TEST(UgrTable, Table4GivesTheExactDirectRatioOfDownlightsAtUnitSpacing) {
  // CIE 190's F_GL are for arrays at S = H. For point downlights at the cell centres of an X × Y
  // room, H above the reference plane, the flux on it is exact: Lambertian, the differential
  // factor to the rectangle; uniform (I constant below the horizontal), its solid angle / 2π
  // (four corner rectangles, Ω = atan(ab / (c √(a² + b² + c²)))).
  const auto solidAngleFraction = [](double px, double py, double a, double b) {
    const auto corner = [](double u, double v) { return std::atan(u * v / std::sqrt(u * u + v * v + 1.0)); };
    return (corner(px, py) + corner(a - px, py) + corner(px, b - py) + corner(a - px, b - py)) / kTwoPi;
  };
  const double cosCone[4] = {0.75, 0.5, 0.25, 0.0};
  for (const UgrRoom& room : standardUgrRooms()) {
    const int nx = int(room.xH), ny = int(room.yH);
    double lambert = 0.0, uniform = 0.0;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j) {
        lambert += pointToRectangle(i + 0.5, j + 0.5, room.xH, room.yH, 1.0);
        uniform += solidAngleFraction(i + 0.5, j + 0.5, room.xH, room.yH);
      }
    lambert /= nx * ny;
    uniform /= nx * ny;
    const std::array<double, 4> fgl = directRatioCoefficients(room.xH * room.yH / (room.xH + room.yH));
    double lambertTable = 0.0, uniformTable = 0.0;  // Σ Φ_zLn F_GLn per lumen downwards
    for (int n = 0; n < 4; ++n) {
      lambertTable += (1.0 - cosCone[n] * cosCone[n]) * fgl[n];
      uniformTable += (1.0 - cosCone[n]) * fgl[n];
    }
    // Four coefficients rounded to 0.001: within 0.002, and a little for the fit. Rooms 4H × 3H
    // and 2H × 12H share one room index (12/7) and so one row; 4H × 3H is 0.005 off.
    const double tol = room.xH == 4 && room.yH == 3 ? 0.006 : 0.003;
    EXPECT_NEAR(lambertTable, lambert, tol) << room.xH << "x" << room.yH;
    EXPECT_NEAR(uniformTable, uniform, tol) << room.xH << "x" << room.yH;
  }
}

TEST(UgrTable, BackgroundLuminanceOfAnUplightUnderAReflectingCeiling) {
  // Only upward flux Φ, only the ceiling reflects: E_WID = N Φ ρ F_cw / A_w, Lb = E_WID / π.
  UgrLuminaire up;
  up.upwardLm = 1000.0;
  const double x = 8.0, y = 16.0, h = 2.0, rho = 0.7;
  const int n = 512;
  const double fcw = 1.0 - parallelRectanglesViewFactor(x, y, h);
  EXPECT_NEAR(ugrBackgroundLuminance(up, x, y, h, n, {rho, 0.0, 0.0}),
              n * 1000.0 * rho * fcw / (2.0 * h * (x + y)) / kPi, 1e-9);
  // A black room has none.
  EXPECT_EQ(ugrBackgroundLuminance(lambertian(1000.0, 0.6, 0.6), x, y, h, n, {0.0, 0.0, 0.0}), 0.0);
}

TEST(UgrTable, SizesOfTheLuminairesCountedAreReported) {
  // A flat 0.6 × 0.6 m opening: its projected area A cos γ is below 0.36 m², and no luminaire
  // is nearer than H = 2 m, so ω < 0.36 / 4 sr.
  const UgrTable t = computeUgrTable(lambertian(1000.0, 0.6, 0.6));
  EXPECT_GT(t.minProjectedAreaM2, 0.0);
  EXPECT_LT(t.minProjectedAreaM2, t.maxProjectedAreaM2);
  EXPECT_LT(t.maxProjectedAreaM2, 0.36);
  EXPECT_GT(t.minSolidAngleSr, 0.0);
  EXPECT_LT(t.maxSolidAngleSr, 0.36 / 4.0);
}

TEST(UgrTable, ScaleFree) {
  // Rooms, spacing and distances all in units of H: the table does not depend on H.
  UgrTableSettings two, three;
  two.heightM = 2.0;
  three.heightM = 3.0;
  const UgrTable a = computeUgrTable(linear(), two), b = computeUgrTable(linear(), three);
  for (size_t i = 0; i < a.crosswise.size(); ++i)
    for (size_t j = 0; j < a.crosswise[i].size(); ++j) {
      EXPECT_NEAR(a.crosswise[i][j], b.crosswise[i][j], 1e-9);
      EXPECT_NEAR(a.endwise[i][j], b.endwise[i][j], 1e-9);
    }
  EXPECT_EQ(a.luminaires, b.luminaires);
  EXPECT_EQ(a.luminaires[10], 16 * 32);  // 4H × 8H at S = H/4
}

TEST(UgrTable, DoublingIntensityAndFluxAddsEightLogTwo) {
  // L doubles (same opening), so Σ L² ω / P² is 4 ×; Lb (linear in the fluxes) 2 ×; their ratio
  // 2 ×: UGR + 8 log10 2 in every cell.
  const UgrLuminaire one = linear();
  UgrLuminaire two = one;
  two.intensityCd = [one](const Vec3& d) { return 2.0 * one.intensityCd(d); };
  for (double& f : two.downwardConeLm) f *= 2.0;
  const UgrTable a = computeUgrTable(one), b = computeUgrTable(two);
  for (size_t i = 0; i < a.crosswise.size(); ++i)
    for (size_t j = 0; j < a.crosswise[i].size(); ++j) {
      EXPECT_NEAR(b.crosswise[i][j] - a.crosswise[i][j], 8.0 * std::log10(2.0), 1e-9);
      EXPECT_NEAR(b.endwise[i][j] - a.endwise[i][j], 8.0 * std::log10(2.0), 1e-9);
    }
}

}  // namespace
}  // namespace candela
