// Sky types by name, as case files and the command line write them. Parsed once into a SkyType;
// everything downstream (the daylight of a scene, makeSky, reports) takes the parsed value.
#pragma once

#include <optional>
#include <string>

namespace candela {

enum class SkyKind { kNone, kUniform, kCieOvercast, kCieGeneral, kCieClear, kPerez, kAnnual };

struct SkyType {
  SkyKind kind = SkyKind::kNone;
  int cieType = 0;  // 1..15 for kCieGeneral (CIE S 011/E:2003, ISO 15469 general sky)
  bool operator==(const SkyType&) const = default;

  // ISO 15469 types 7–15 are partly cloudy to clear skies with a visible sun; perez always
  // carries the measured beam; uniform and overcast have none.
  bool hasSun() const;
  // Whether the sky's luminance depends on the sun's position.
  bool dependsOnSun() const { return hasSun() || kind == SkyKind::kCieGeneral; }
};

// "none", "uniform", "cie-overcast", "cie:N", "cie-clear", "perez", "annual".
std::string skyTypeName(const SkyType& type);

// Parses a name written as skyTypeName writes it. Without a match: nothing, and `why` (when
// given) says what is wrong in a sentence that names the text.
std::optional<SkyType> parseSkyType(const std::string& name, std::string* why = nullptr);

}  // namespace candela
