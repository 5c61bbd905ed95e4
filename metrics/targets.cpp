#include "metrics/targets.h"

namespace candela {

const char* verdictName(Verdict v) {
  switch (v) {
    case Verdict::kPass: return "pass";
    case Verdict::kFail: return "fail";
    case Verdict::kNotChecked: break;
  }
  return "n/a";
}

TargetCheck checkTargets(const GridStats& stats, const GridTargets& targets, double relativeTolerance) {
  TargetCheck c;
  const double slack = 1.0 - relativeTolerance;
  if (targets.averageLux) {
    const double t = *targets.averageLux;
    c.averageRatio = t > 0.0 ? stats.averageLux / t : 0.0;
    c.average = stats.averageLux >= t * slack ? Verdict::kPass : Verdict::kFail;
  }
  if (targets.uniformity) {
    const double t = *targets.uniformity;
    c.uniformityRatio = t > 0.0 ? stats.u0 / t : 0.0;
    c.uniformity = stats.u0 >= t * slack ? Verdict::kPass : Verdict::kFail;
  }
  if (c.average == Verdict::kFail || c.uniformity == Verdict::kFail) {
    c.overall = Verdict::kFail;
  } else if (c.average == Verdict::kPass || c.uniformity == Verdict::kPass) {
    c.overall = Verdict::kPass;
  }
  return c;
}

double immediateSurroundingLux(double taskLux) {
  // (task Ē_m at least, surrounding Ē_m), from the top row down.
  static constexpr double kRows[][2] = {{750.0, 500.0}, {500.0, 300.0}, {300.0, 200.0}, {200.0, 150.0}};
  for (const auto& row : kRows)
    if (taskLux >= row[0]) return row[1];
  return taskLux;
}

const char* roomSurfaceName(RoomSurface s) {
  switch (s) {
    case RoomSurface::kWall: return "wall";
    case RoomSurface::kCeiling: return "ceiling";
    case RoomSurface::kFloor: return "floor";
    case RoomSurface::kNone: break;
  }
  return "surface";
}

std::optional<RoomType> parseRoomType(const std::string& key) {
  if (key == "general") return RoomType::kGeneral;
  if (key == "office") return RoomType::kOffice;
  if (key == "education" || key == "school") return RoomType::kEducation;
  if (key == "healthcare") return RoomType::kHealthcare;
  return std::nullopt;
}

const char* roomTypeKey(RoomType t) {
  switch (t) {
    case RoomType::kOffice: return "office";
    case RoomType::kEducation: return "education";
    case RoomType::kHealthcare: return "healthcare";
    case RoomType::kGeneral: break;
  }
  return "general";
}

GridTargets roomSurfaceTargets(RoomType type, RoomSurface surface) {
  const bool demanding = type != RoomType::kGeneral;
  GridTargets t;
  if (surface == RoomSurface::kWall) t.averageLux = demanding ? 75.0 : 50.0;
  if (surface == RoomSurface::kCeiling) t.averageLux = demanding ? 50.0 : 30.0;
  if (t.averageLux) t.uniformity = kRoomSurfaceUniformity;
  return t;
}

}  // namespace candela
