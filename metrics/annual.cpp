#include "metrics/annual.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace candela {
namespace {

void checkCounts(int nSensors, int nHours, const std::vector<char>& occupied) {
  if (nSensors < 0 || nHours < 0)
    throw std::invalid_argument("annual metrics: negative sensor or hour count");
  if (occupied.size() != static_cast<std::size_t>(nHours))
    throw std::invalid_argument("annual metrics: " + std::to_string(occupied.size()) +
                                " occupancy flags for " + std::to_string(nHours) + " hours");
}

double percentOf(int count, int total) { return total > 0 ? 100.0 * count / total : 0.0; }

}  // namespace

std::vector<char> occupiedHours(const std::vector<int>& hourEnding, double startHour, double endHour) {
  if (!(startHour >= 0.0 && endHour <= 24.0 && startHour <= endHour))
    throw std::invalid_argument("occupancy hours must satisfy 0 <= start <= end <= 24, got " +
                                std::to_string(startHour) + " to " + std::to_string(endHour));
  std::vector<char> occupied(hourEnding.size(), 0);
  for (std::size_t i = 0; i < hourEnding.size(); ++i) {
    // EPW values are sums over the hour ending at `hourEnding`; its middle stands for the hour.
    const double middle = hourEnding[i] - 0.5;
    occupied[i] = (middle >= startHour && middle < endHour) ? 1 : 0;
  }
  return occupied;
}

int countHours(const std::vector<char>& flags) {
  return static_cast<int>(std::count_if(flags.begin(), flags.end(), [](char f) { return f != 0; }));
}

void countSunlitSensors(const float* directSun, int nSensors, int nHours, double aseLux, std::vector<int>& sunlit) {
  if (nSensors < 0 || nHours < 0) throw std::invalid_argument("annual metrics: negative sensor or hour count");
  if (sunlit.size() != static_cast<std::size_t>(nHours))
    throw std::invalid_argument("countSunlitSensors: " + std::to_string(sunlit.size()) + " counts for " +
                                std::to_string(nHours) + " hours");
  if (directSun == nullptr && nSensors > 0 && nHours > 0)
    throw std::invalid_argument("countSunlitSensors: no direct-sun illuminances");
  // Count the sunlit sensors of every hour sensor by sensor, so that the sensor-major array is
  // read contiguously (an hour-by-hour pass would stride by nHours floats).
  const float threshold = static_cast<float>(aseLux);
  for (int s = 0; s < nSensors; ++s) {
    const float* row = directSun + static_cast<std::size_t>(s) * nHours;
    for (int h = 0; h < nHours; ++h) sunlit[h] += row[h] >= threshold ? 1 : 0;
  }
}

std::vector<char> blindsClosedFromCounts(const std::vector<int>& sunlit, int nSensors,
                                         const std::vector<char>& occupied, double fraction) {
  const int nHours = static_cast<int>(sunlit.size());
  checkCounts(nSensors, nHours, occupied);
  // LM-83-12 2.2.6: blinds close when MORE than 2 % of the analysis points receive direct sun.
  const double limit = fraction * nSensors;
  std::vector<char> closed(static_cast<std::size_t>(nHours), 0);
  for (int h = 0; h < nHours; ++h) closed[h] = (occupied[h] && sunlit[h] > limit) ? 1 : 0;
  return closed;
}

std::vector<char> blindsClosedHours(const float* directSun, int nSensors, int nHours,
                                    const std::vector<char>& occupied, double aseLux, double fraction) {
  checkCounts(nSensors, nHours, occupied);
  std::vector<int> sunlit(static_cast<std::size_t>(nHours), 0);
  countSunlitSensors(directSun, nSensors, nHours, aseLux, sunlit);
  return blindsClosedFromCounts(sunlit, nSensors, occupied, fraction);
}

std::vector<SensorAnnualMetrics> sensorAnnualMetrics(const float* total, const float* directSun,
                                                     int nSensors, int nHours,
                                                     const std::vector<char>& occupied,
                                                     const AnnualThresholds& t,
                                                     const float* shadedTotal,
                                                     const std::vector<char>* blindsClosed) {
  checkCounts(nSensors, nHours, occupied);
  if (total == nullptr && nSensors > 0 && nHours > 0)
    throw std::invalid_argument("sensorAnnualMetrics: no illuminances");
  const bool useBlinds = shadedTotal != nullptr && blindsClosed != nullptr;
  if (useBlinds && blindsClosed->size() != static_cast<std::size_t>(nHours))
    throw std::invalid_argument("sensorAnnualMetrics: " + std::to_string(blindsClosed->size()) +
                                " blind flags for " + std::to_string(nHours) + " hours");

  const int nOccupied = countHours(occupied);
  const double daLux = t.daLux, lowLux = t.udiLowLux, highLux = t.udiHighLux;
  const float aseLux = static_cast<float>(t.aseLux);
  const char* occ = occupied.data();
  const char* closed = useBlinds ? blindsClosed->data() : nullptr;

  std::vector<SensorAnnualMetrics> out(static_cast<std::size_t>(nSensors));
  for (int s = 0; s < nSensors; ++s) {
    const std::size_t base = static_cast<std::size_t>(s) * nHours;
    const float* open = total + base;
    const float* shaded = useBlinds ? shadedTotal + base : nullptr;
    int daCount = 0, fellShort = 0, supplementary = 0, autonomous = 0, exceeded = 0;
    double cdaCredit = 0.0;
    for (int h = 0; h < nHours; ++h) {
      if (!occ[h]) continue;
      const double e = (closed != nullptr && closed[h]) ? shaded[h] : open[h];
      if (e >= daLux) {
        ++daCount;
        cdaCredit += 1.0;
      } else if (e > 0.0) {
        // Rogers (2006) continuous DA: partial credit E/threshold below the threshold.
        cdaCredit += e / daLux;
      }
      if (e < lowLux) ++fellShort;
      else if (e < daLux) ++supplementary;
      else if (e <= highLux) ++autonomous;
      else ++exceeded;
    }
    int aseCount = 0, sunCount = 0;
    if (directSun != nullptr) {
      const float* direct = directSun + base;
      for (int h = 0; h < nHours; ++h) {
        const float d = direct[h];
        sunCount += d > 0.0f ? 1 : 0;
        aseCount += (occ[h] && d >= aseLux) ? 1 : 0;
      }
    }
    SensorAnnualMetrics& m = out[s];
    m.da = percentOf(daCount, nOccupied);
    m.cda = nOccupied > 0 ? 100.0 * cdaCredit / nOccupied : 0.0;
    m.udiFellShort = percentOf(fellShort, nOccupied);
    m.udiSupplementary = percentOf(supplementary, nOccupied);
    m.udiAutonomous = percentOf(autonomous, nOccupied);
    m.udiExceeded = percentOf(exceeded, nOccupied);
    m.aseHours = aseCount;
    m.sunHours = sunCount;
    // Compare counts, not rounded percentages: 1825 of 3650 h is exactly 50 % and passes.
    m.sdaPass = nOccupied > 0 && daCount >= t.sdaFraction * nOccupied;
    m.aseExceeded = aseCount > t.aseHours;
  }
  return out;
}

GridAnnualSummary summarizeAnnual(const std::vector<SensorAnnualMetrics>& sensors, int occupiedHours) {
  GridAnnualSummary g;
  g.sensors = static_cast<int>(sensors.size());
  g.occupiedHours = occupiedHours;
  if (sensors.empty()) return g;
  int sdaCount = 0, aseCount = 0;
  double sunSum = 0.0;
  for (const SensorAnnualMetrics& m : sensors) {
    g.DA300 += m.da;
    g.cDA300 += m.cda;
    g.UDI_fell_short += m.udiFellShort;
    g.UDI_supplementary += m.udiSupplementary;
    g.UDI_autonomous += m.udiAutonomous;
    g.UDI_exceeded += m.udiExceeded;
    sunSum += m.sunHours;
    sdaCount += m.sdaPass ? 1 : 0;
    aseCount += m.aseExceeded ? 1 : 0;
  }
  const double n = static_cast<double>(sensors.size());
  g.DA300 /= n;
  g.cDA300 /= n;
  g.UDI_fell_short /= n;
  g.UDI_supplementary /= n;
  g.UDI_autonomous /= n;
  g.UDI_exceeded /= n;
  g.sunHoursMean = sunSum / n;
  g.sDA300_50 = 100.0 * sdaCount / n;
  g.ASE1000_250 = 100.0 * aseCount / n;
  return g;
}

}  // namespace candela
