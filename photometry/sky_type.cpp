#include "photometry/sky_type.h"

#include <cstdio>

namespace candela {

bool SkyType::hasSun() const {
  return kind == SkyKind::kPerez || kind == SkyKind::kCieClear || (kind == SkyKind::kCieGeneral && cieType >= 7);
}

std::string skyTypeName(const SkyType& type) {
  switch (type.kind) {
    case SkyKind::kNone: return "none";
    case SkyKind::kUniform: return "uniform";
    case SkyKind::kCieOvercast: return "cie-overcast";
    case SkyKind::kCieGeneral: return "cie:" + std::to_string(type.cieType);
    case SkyKind::kCieClear: return "cie-clear";
    case SkyKind::kPerez: return "perez";
    case SkyKind::kAnnual: return "annual";
  }
  return "none";
}

std::optional<SkyType> parseSkyType(const std::string& name, std::string* why) {
  for (SkyKind k : {SkyKind::kNone, SkyKind::kUniform, SkyKind::kCieOvercast, SkyKind::kCieClear, SkyKind::kPerez,
                    SkyKind::kAnnual})
    if (name == skyTypeName({k, 0})) return SkyType{k, 0};
  if (name.rfind("cie:", 0) == 0) {
    int n = 0, used = 0;
    if (std::sscanf(name.c_str() + 4, "%d%n", &n, &used) == 1 && static_cast<std::size_t>(4 + used) == name.size() &&
        n >= 1 && n <= 15)
      return SkyType{SkyKind::kCieGeneral, n};
    if (why) *why = "CIE general sky type must be cie:1 .. cie:15, got '" + name + "'";
    return std::nullopt;
  }
  if (why)
    *why = "unknown sky type '" + name +
           "' (expected uniform, cie-overcast, cie:1..cie:15, cie-clear, perez, annual or none)";
  return std::nullopt;
}

}  // namespace candela
