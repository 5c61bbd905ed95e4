#include "metrics/annual_glare.h"

#include <stdexcept>

namespace candela {

namespace {

void checkSizes(std::size_t a, std::size_t b, const char* what) {
  if (a != b) throw std::invalid_argument(std::string(what) + ": one value per hour expected");
}

// Occupied hours and those among them for which `count(dgp)` holds.
template <class Pred>
double shareOf(std::span<const float> dgp, const std::vector<char>& occupied, Pred count) {
  checkSizes(dgp.size(), occupied.size(), "annual glare");
  int n = 0, k = 0;
  for (std::size_t h = 0; h < dgp.size(); ++h) {
    if (!occupied[h]) continue;
    ++n;
    k += count(dgp[h]) ? 1 : 0;
  }
  return n > 0 ? static_cast<double>(k) / n : 0.0;
}

}  // namespace

double shareOfHoursAbove(std::span<const float> dgp, const std::vector<char>& occupied, double threshold) {
  return shareOf(dgp, occupied, [&](float v) { return v > threshold; });
}

En17037Level en17037GlareLevel(double aboveHigh, double aboveMedium, double aboveMinimum,
                               const AnnualGlareThresholds& t) {
  const double s = t.exceedanceShare;
  if (aboveHigh <= s) return En17037Level::kHigh;
  if (aboveMedium <= s) return En17037Level::kMedium;
  if (aboveMinimum <= s) return En17037Level::kMinimum;
  return En17037Level::kNone;
}

ViewGlareMetrics viewGlareMetrics(std::span<const float> dgp, const std::vector<char>& occupied,
                                  const AnnualGlareThresholds& t) {
  checkSizes(dgp.size(), occupied.size(), "annual glare");
  ViewGlareMetrics m;
  for (char o : occupied) m.occupiedHours += o ? 1 : 0;
  m.aboveHigh = shareOfHoursAbove(dgp, occupied, t.high);
  m.aboveMedium = shareOfHoursAbove(dgp, occupied, t.medium);
  m.aboveMinimum = shareOfHoursAbove(dgp, occupied, t.minimum);
  m.aboveDisturbing = shareOfHoursAbove(dgp, occupied, t.disturbingDgp);
  m.glareAutonomy = shareOf(dgp, occupied, [&](float v) { return v < t.autonomyLimit; });
  m.disturbingGlare = m.occupiedHours > 0 && m.aboveDisturbing >= t.disturbingShare;
  m.level = en17037GlareLevel(m.aboveHigh, m.aboveMedium, m.aboveMinimum, t);
  return m;
}

double spatialDisturbingGlare(const std::vector<ViewGlareMetrics>& views) {
  if (views.empty()) return 0.0;
  int k = 0;
  for (const ViewGlareMetrics& v : views) k += v.disturbingGlare ? 1 : 0;
  return static_cast<double>(k) / static_cast<double>(views.size());
}

std::vector<float> combineByHour(std::span<const float> open, std::span<const float> closed,
                                 const std::vector<char>& closedHours) {
  checkSizes(open.size(), closed.size(), "combineByHour (open, closed)");
  checkSizes(open.size(), closedHours.size(), "combineByHour (flags)");
  std::vector<float> out(open.begin(), open.end());
  for (std::size_t h = 0; h < out.size(); ++h)
    if (closedHours[h]) out[h] = closed[h];
  return out;
}

}  // namespace candela
