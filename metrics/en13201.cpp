#include "metrics/en13201.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>

namespace candela {

std::string RoadClass::name() const {
  const char* letters = family == RoadClassFamily::kM   ? "M"
                        : family == RoadClassFamily::kC ? "C"
                        : family == RoadClassFamily::kP ? "P"
                                                        : "HS";
  return letters + std::to_string(index);
}

std::string AdditionalRoadClass::name() const { return (kind == AdditionalClassKind::kSC ? "SC" : "EV") + std::to_string(index); }

namespace {

// "XYn" with a two-letter prefix `prefix` (upper or lower case) and one digit in [lo, hi].
std::optional<int> twoLetterClass(std::string_view text, const char* prefix, int lo, int hi) {
  if (text.size() != 3 || std::toupper(static_cast<unsigned char>(text[0])) != prefix[0] ||
      std::toupper(static_cast<unsigned char>(text[1])) != prefix[1] || !std::isdigit(static_cast<unsigned char>(text[2])))
    return std::nullopt;
  const int index = text[2] - '0';
  if (index < lo || index > hi) return std::nullopt;
  return index;
}

}  // namespace

std::optional<AdditionalRoadClass> parseAdditionalRoadClass(std::string_view text) {
  if (const std::optional<int> i = twoLetterClass(text, "SC", 1, 9)) return AdditionalRoadClass{AdditionalClassKind::kSC, *i};
  if (const std::optional<int> i = twoLetterClass(text, "EV", 1, 6)) return AdditionalRoadClass{AdditionalClassKind::kEV, *i};
  return std::nullopt;
}

std::optional<RoadClass> parseRoadClass(std::string_view text) {
  if (const std::optional<int> i = twoLetterClass(text, "HS", 1, 3)) return RoadClass{RoadClassFamily::kHS, *i};
  if (text.size() != 2 || !std::isdigit(static_cast<unsigned char>(text[1]))) return std::nullopt;
  const int index = text[1] - '0';
  switch (std::toupper(static_cast<unsigned char>(text[0]))) {
    case 'M':
      if (index >= 1 && index <= 6) return RoadClass{RoadClassFamily::kM, index};
      break;
    case 'C':
      if (index >= 0 && index <= 5) return RoadClass{RoadClassFamily::kC, index};
      break;
    case 'P':
      if (index >= 1 && index <= 6) return RoadClass{RoadClassFamily::kP, index};
      break;
    default: break;
  }
  return std::nullopt;
}

// EN 13201-2:2015 Tables 1, 2 and 3 (docs/road.md).
MClassRequirement mClassRequirement(int index) {
  static constexpr std::array<MClassRequirement, 6> kM = {{
      {2.00, 0.40, 0.70, 10.0, 0.35},  // M1
      {1.50, 0.40, 0.70, 10.0, 0.35},  // M2
      {1.00, 0.40, 0.60, 15.0, 0.30},  // M3
      {0.75, 0.40, 0.60, 15.0, 0.30},  // M4
      {0.50, 0.35, 0.40, 15.0, 0.30},  // M5
      {0.30, 0.35, 0.40, 20.0, 0.30},  // M6
  }};
  return kM.at(static_cast<std::size_t>(index - 1));
}

CClassRequirement cClassRequirement(int index) {
  static constexpr std::array<double, 6> kAverage = {50.0, 30.0, 20.0, 15.0, 10.0, 7.5};  // C0..C5
  return {kAverage.at(static_cast<std::size_t>(index)), 0.40};
}

PClassRequirement pClassRequirement(int index) {
  static constexpr std::array<PClassRequirement, 6> kP = {{
      {15.0, 3.00}, {10.0, 2.00}, {7.50, 1.50}, {5.00, 1.00}, {3.00, 0.60}, {2.00, 0.40},  // P1..P6
  }};
  return kP.at(static_cast<std::size_t>(index - 1));
}

HsClassRequirement hsClassRequirement(int index) {
  static constexpr std::array<double, 3> kAverage = {5.00, 2.50, 1.00};  // HS1..HS3 (HS4: not determined)
  return {kAverage.at(static_cast<std::size_t>(index - 1)), 0.15};
}

double additionalClassMinimumLux(const AdditionalRoadClass& c) {
  static constexpr std::array<double, 9> kSc = {10.0, 7.5, 5.0, 3.0, 2.0, 1.5, 1.0, 0.75, 0.5};  // SC1..SC9
  static constexpr std::array<double, 6> kEv = {50.0, 30.0, 10.0, 7.5, 5.0, 0.5};                // EV1..EV6
  const auto i = static_cast<std::size_t>(c.index - 1);
  return c.kind == AdditionalClassKind::kSC ? kSc.at(i) : kEv.at(i);
}

double thresholdIncrementPct(double veilingCdM2, double averageLuminanceCdM2) {
  if (!(averageLuminanceCdM2 > 0.0)) return veilingCdM2 > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  if (averageLuminanceCdM2 <= 5.0) return 65.0 * veilingCdM2 / std::pow(averageLuminanceCdM2, 0.8);
  return 95.0 * veilingCdM2 / std::pow(averageLuminanceCdM2, 1.05);
}

RoadStats roadStats(const std::vector<double>& values) {
  RoadStats s;
  if (values.empty()) return s;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.average = sum / static_cast<double>(values.size());
  return s;
}

namespace {

RoadCriterion criterion(const char* name, double value, double required, bool atLeast) {
  const bool ok = atLeast ? value >= required : value <= required;
  return {name, value, required, atLeast, ok ? Verdict::kPass : Verdict::kFail};
}

}  // namespace

void judgeRoad(RoadResult& r) {
  r.criteria.clear();
  switch (r.roadClass.family) {
    case RoadClassFamily::kM: {
      if (!r.observers.empty()) {
        r.averageLuminanceCdM2 = r.overallUniformity = r.longitudinalUniformity = std::numeric_limits<double>::infinity();
        r.thresholdIncrementPct = 0.0;
        for (const RoadObserverResult& o : r.observers) {
          r.averageLuminanceCdM2 = std::min(r.averageLuminanceCdM2, o.averageLuminanceCdM2);
          r.overallUniformity = std::min(r.overallUniformity, o.overallUniformity);
          r.longitudinalUniformity = std::min(r.longitudinalUniformity, o.longitudinalUniformity);
          r.thresholdIncrementPct = std::max(r.thresholdIncrementPct, o.thresholdIncrementPct);
        }
      }
      const MClassRequirement q = mClassRequirement(r.roadClass.index);
      r.criteria.push_back(criterion("average_luminance_cd_m2", r.averageLuminanceCdM2, q.averageLuminanceCdM2, true));
      r.criteria.push_back(criterion("overall_uniformity", r.overallUniformity, q.overallUniformity, true));
      r.criteria.push_back(criterion("longitudinal_uniformity", r.longitudinalUniformity, q.longitudinalUniformity, true));
      r.criteria.push_back(criterion("threshold_increment_percent", r.thresholdIncrementPct, q.thresholdIncrementPct, false));
      r.criteria.push_back(criterion("edge_illuminance_ratio", r.edgeIlluminanceRatio, q.edgeIlluminanceRatio, true));
      break;
    }
    case RoadClassFamily::kC: {
      const CClassRequirement q = cClassRequirement(r.roadClass.index);
      r.criteria.push_back(criterion("average_illuminance_lux", r.averageLux, q.averageLux, true));
      r.criteria.push_back(criterion("illuminance_uniformity", r.illuminanceUniformity, q.overallUniformity, true));
      break;
    }
    case RoadClassFamily::kP: {
      const PClassRequirement q = pClassRequirement(r.roadClass.index);
      r.criteria.push_back(criterion("average_illuminance_lux", r.averageLux, q.averageLux, true));
      r.criteria.push_back(criterion("minimum_illuminance_lux", r.minLux, q.minimumLux, true));
      r.criteria.push_back(
          criterion("average_illuminance_ceiling_lux", r.averageLux, kPClassAverageCeiling * q.averageLux, false));
      break;
    }
    case RoadClassFamily::kHS: {
      const HsClassRequirement q = hsClassRequirement(r.roadClass.index);
      r.criteria.push_back(criterion("average_hemispherical_illuminance_lux", r.averageHemisphericalLux, q.averageLux, true));
      r.criteria.push_back(criterion("hemispherical_uniformity", r.hemisphericalUniformity, q.uniformity, true));
      break;
    }
  }
  for (const AdditionalRoadClass& a : r.additional) {
    const bool sc = a.kind == AdditionalClassKind::kSC;
    r.criteria.push_back(criterion(sc ? "minimum_semi_cylindrical_illuminance_lux" : "minimum_vertical_illuminance_lux",
                                   sc ? r.minSemiCylindricalLux : r.minVerticalLux, additionalClassMinimumLux(a), true));
  }
  const bool fail = std::any_of(r.criteria.begin(), r.criteria.end(),
                                [](const RoadCriterion& c) { return c.verdict == Verdict::kFail; });
  r.verdict = fail ? Verdict::kFail : Verdict::kPass;
}

}  // namespace candela
