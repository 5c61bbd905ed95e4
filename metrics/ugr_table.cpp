#include "metrics/ugr_table.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace candela {

namespace {

// CIE 117 Table 4.1 covers H/R up to 1.9 and T/R up to 3.
constexpr double kMaxHeightOverAlong = 1.9;
constexpr double kMaxAcrossOverAlong = 3.0;

// CIE 190:2010 Table 4: F_GL1…4 for the room indices of its 19 rooms (values as transcribed in
// the eulumdat-ugr project's background.py; tests/metrics/ugr_table_test.cpp checks them against
// the exact direct ratio of Lambertian and uniform downlights in arrays at S = H).
struct DirectRatioRow {
  double k;
  std::array<double, 4> fgl;
};
const DirectRatioRow kTable4[] = {
    {1.0, {0.690, 0.109, 0.085, -0.016}},       {1.2, {0.578, 0.200, 0.127, -0.018}},
    {4.0 / 3.0, {0.528, 0.218, 0.170, -0.017}}, {1.5, {0.485, 0.215, 0.222, -0.012}},
    {1.6, {0.466, 0.207, 0.249, -0.006}},       {12.0 / 7.0, {0.448, 0.198, 0.272, 0.005}},
    {2.0, {0.338, 0.257, 0.351, -0.018}},       {2.4, {0.296, 0.203, 0.449, -0.006}},
    {8.0 / 3.0, {0.280, 0.165, 0.499, 0.006}},  {3.0, {0.264, 0.125, 0.541, 0.027}},
    {24.0 / 7.0, {0.248, 0.058, 0.628, 0.032}}, {4.0, {0.239, -0.012, 0.690, 0.058}},
    {4.8, {0.232, -0.084, 0.740, 0.098}},
};

// The luminaire-local direction of a room-frame vector for each viewing (header comment).
Vec3 toLuminaireLocal(const Vec3& room, UgrViewing viewing) {
  return viewing == UgrViewing::kCrosswise ? Vec3(-room.y, room.x, room.z) : Vec3(-room.x, -room.y, room.z);
}

}  // namespace

const std::vector<UgrRoom>& standardUgrRooms() {
  static const std::vector<UgrRoom> rooms = {
      {2, 2}, {2, 3}, {2, 4}, {2, 6}, {2, 8}, {2, 12}, {4, 2}, {4, 3}, {4, 4}, {4, 6},
      {4, 8}, {4, 12}, {8, 4}, {8, 6}, {8, 8}, {8, 12}, {12, 4}, {12, 6}, {12, 8},
  };
  return rooms;
}

const std::vector<RoomReflectances>& standardUgrReflectances() {
  static const std::vector<RoomReflectances> rho = {
      {0.7, 0.5, 0.2}, {0.7, 0.3, 0.2}, {0.5, 0.5, 0.2}, {0.5, 0.3, 0.2}, {0.3, 0.3, 0.2},
  };
  return rho;
}

double parallelRectanglesViewFactor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1.0 + x * x), y1 = std::sqrt(1.0 + y * y);
  return 2.0 / (kPi * x * y) *
         (std::log(x1 * y1 / std::sqrt(1.0 + x * x + y * y)) + x * y1 * std::atan(x / y1) +
          y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

WallTransferFactors wallTransferFactors(double xM, double yM, double hM, const RoomReflectances& rho) {
  // Surfaces 0 floor, 1 walls, 2 ceiling; F[i][j] the view factor from i to j (reciprocity and
  // the sums to 1 give all from the floor-ceiling one).
  const double floorArea = xM * yM, wallArea = 2.0 * hM * (xM + yM);
  const double fc = parallelRectanglesViewFactor(xM, yM, hM), fw = 1.0 - fc;
  const double wf = fw * floorArea / wallArea;
  const double F[3][3] = {{0.0, fw, fc}, {wf, 1.0 - 2.0 * wf, wf}, {fc, fw, 0.0}};
  const double r[3] = {rho.floor, rho.walls, rho.ceiling};
  // Incident flux E_i = e_i + Σ_j ρ_j F_ji E_j, i.e. A E = e with A_ij = δ_ij − ρ_j F_ji. GLM
  // matrices are indexed [column][row].
  Mat3 a(0.0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[j][i] = (i == j ? 1.0 : 0.0) - r[j] * F[j][i];
  const Mat3 inv = glm::inverse(a);
  // Column s of the inverse: incident flux everywhere per lumen first incident on s.
  return WallTransferFactors{inv[0][1], inv[1][1] - 1.0, inv[2][1]};
}

std::array<double, 4> directRatioCoefficients(double k) {
  const size_t n = std::size(kTable4);
  if (k <= kTable4[0].k) return kTable4[0].fgl;
  if (k >= kTable4[n - 1].k) return kTable4[n - 1].fgl;
  size_t i = 0;
  while (kTable4[i + 1].k < k) ++i;
  const double t = (k - kTable4[i].k) / (kTable4[i + 1].k - kTable4[i].k);
  std::array<double, 4> out{};
  for (size_t m = 0; m < 4; ++m) out[m] = (1.0 - t) * kTable4[i].fgl[m] + t * kTable4[i + 1].fgl[m];
  return out;
}

double ugrBackgroundLuminance(const UgrLuminaire& lum, double xM, double yM, double hM, int luminaires,
                              const RoomReflectances& rho) {
  const std::array<double, 4> fgl = directRatioCoefficients(xM * yM / (hM * (xM + yM)));
  double toFloor = 0.0;
  for (size_t n = 0; n < 4; ++n) toFloor += lum.downwardConeLm[n] * fgl[n];
  const double toWalls = lum.downwardConeLm[3] - toFloor;
  const WallTransferFactors t = wallTransferFactors(xM, yM, hM, rho);
  const double wallArea = 2.0 * hM * (xM + yM);
  const double indirectLux =
      luminaires / wallArea * (toFloor * t.fromFloor + toWalls * t.fromWalls + lum.upwardLm * t.fromCeiling);
  return indirectLux / kPi;
}

bool inUgrField(double alongM, double acrossM, double hM) {
  return alongM > 0.0 && hM <= kMaxHeightOverAlong * alongM && std::abs(acrossM) <= kMaxAcrossOverAlong * alongM;
}

GlareSource ugrGlareSource(const UgrLuminaire& lum, UgrViewing viewing, double alongM, double acrossM, double hM) {
  const double d = std::sqrt(alongM * alongM + acrossM * acrossM + hM * hM);
  // From the luminaire to the eye (room frame), and from the eye to the luminaire in the view
  // frame of glare.h (x right = room +x, y up = room +z, z forward = room +y).
  const Vec3 local = toLuminaireLocal(Vec3(-acrossM, -alongM, -hM) / d, viewing);
  GlareSource s;
  s.positionIndex = positionIndex(Vec3(acrossM, hM, alongM));
  const double area = lum.projectedAreaM2(local);
  if (!(area > 0.0)) return GlareSource{0.0, 0.0, s.positionIndex};
  s.luminanceCdM2 = lum.intensityCd(local) / area;
  s.solidAngleSr = area / (d * d);
  return s;
}

UgrTable computeUgrTable(const UgrLuminaire& lum, const UgrTableSettings& settings) {
  UgrTable table;
  table.settings = settings;
  const double h = settings.heightM, spacing = settings.spacingToHeight * h;
  const double inf = std::numeric_limits<double>::infinity();
  double minOmega = inf, maxOmega = 0.0, minArea = inf, maxArea = 0.0;
  std::vector<GlareSource> sources;
  for (const UgrRoom& room : settings.rooms) {
    const double x = room.xH * h, y = room.yH * h;
    const int nx = int(std::lround(x / spacing)), ny = int(std::lround(y / spacing));
    table.luminaires.push_back(nx * ny);
    std::vector<double> lb;
    for (const RoomReflectances& rho : settings.reflectances)
      lb.push_back(ugrBackgroundLuminance(lum, x, y, h, nx * ny, rho));
    for (UgrViewing viewing : {UgrViewing::kCrosswise, UgrViewing::kEndwise}) {
      sources.clear();
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const double along = (j + 0.5) * spacing, across = (i + 0.5) * spacing - 0.5 * x;
          if (!inUgrField(along, across, h)) continue;
          const GlareSource s = ugrGlareSource(lum, viewing, along, across, h);
          if (!(s.solidAngleSr > 0.0)) continue;
          sources.push_back(s);
          const double area = s.solidAngleSr * (along * along + across * across + h * h);
          minOmega = std::min(minOmega, s.solidAngleSr);
          maxOmega = std::max(maxOmega, s.solidAngleSr);
          minArea = std::min(minArea, area);
          maxArea = std::max(maxArea, area);
        }
      std::vector<double> row;
      for (double b : lb) row.push_back(unifiedGlareRating(b, sources));
      (viewing == UgrViewing::kCrosswise ? table.crosswise : table.endwise).push_back(row);
    }
  }
  table.minSolidAngleSr = maxOmega > 0.0 ? minOmega : 0.0;
  table.maxSolidAngleSr = maxOmega;
  table.minProjectedAreaM2 = maxArea > 0.0 ? minArea : 0.0;
  table.maxProjectedAreaM2 = maxArea;
  return table;
}

}  // namespace candela
