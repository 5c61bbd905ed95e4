// Annual climate-based daylight metrics over hourly sensor illuminances: daylight autonomy (DA),
// continuous DA (cDA), useful daylight illuminance (UDI), spatial daylight autonomy (sDA) and
// annual sunlight exposure (ASE) after IES LM-83-12, and annual hours of direct sun.
//
// Pure functions: the caller supplies the year of illuminances (from daylight coefficients or any
// other source); nothing here knows about skies, scenes or weather files.
#pragma once

#include <vector>

namespace candela {

// Thresholds of the annual metrics; every default is the one of the metric's source. Case-file
// keys carry the same names (see docs/annual-metrics.md).
struct AnnualThresholds {
  // DA, cDA and sDA illuminance threshold in lux (IES LM-83-12 2.2.2: 300 lux). It is also the
  // boundary between the UDI "supplementary" and "autonomous" bins.
  double daLux = 300.0;
  // UDI bins (Nabil & Mardaljevic, Lighting Res. Technol. 37(1) 2005 41-59, for the fell-short /
  // useful / exceeded split; Nabil & Mardaljevic, Energy and Buildings 38(7) 2006 905-913, for the
  // split of the useful range into supplementary and autonomous), in lux. Which side each
  // boundary belongs to:
  //   fell short     E <  udiLowLux
  //   supplementary  udiLowLux <= E <  daLux
  //   autonomous     daLux     <= E <= udiHighLux
  //   exceeded       E >  udiHighLux
  // so E = 100 is supplementary, E = 300 autonomous, E = 3000 still autonomous.
  double udiLowLux = 100.0, udiHighLux = 3000.0;
  // sDA temporal threshold: share (0..1) of occupied hours in which a sensor must reach daLux to
  // count (LM-83-12 2.2.3: 50 %; "at least", so a sensor at exactly 50 % passes).
  double sdaFraction = 0.5;
  // ASE: direct-sun illuminance threshold in lux. An hour counts when the direct-sun illuminance
  // is >= aseLux (LM-83-12 2.2.6 defines direct sun as "1,000 lux or more" of direct beam
  // sunlight, no interreflection, blinds open).
  double aseLux = 1000.0;
  // ASE: a sensor counts when it has MORE than aseHours such occupied hours (LM-83-12: "more
  // than 250 hours per year"), so exactly 250 h does not count.
  double aseHours = 250.0;
  // Occupancy, hours of local standard time: [start, end).
  double occupancyStartHour = 8.0, occupancyEndHour = 18.0;
};

// Occupancy per record from EPW hours (hour-ending, 1..24, local standard time: hour 9 covers
// 08:00-09:00). An hour is occupied when its middle (hourEnding - 0.5) lies in
// [startHour, endHour), so 08-18 occupies hour-ending 9..18: 10 h a day, 3650 h in 365 days.
// Returns one 0/1 flag per input hour. Throws std::invalid_argument if endHour < startHour or a
// bound lies outside [0, 24].
std::vector<char> occupiedHours(const std::vector<int>& hourEnding, double startHour, double endHour);

// Per-sensor results. Percentages are of the OCCUPIED hours (0 when there are none).
struct SensorAnnualMetrics {
  double da = 0;                // % of occupied hours with E >= daLux
  double cda = 0;               // cDA (Rogers 2006): mean over occupied hours of min(E/daLux, 1), in %
  double udiFellShort = 0;      // % of occupied hours in each UDI bin (the four sum to 100)
  double udiSupplementary = 0;
  double udiAutonomous = 0;
  double udiExceeded = 0;
  int aseHours = 0;   // occupied hours with direct-sun illuminance >= aseLux (blinds open)
  int sunHours = 0;   // hours of the whole year (occupied or not) with direct sun > 0 lux on the sensor
  bool sdaPass = false;      // E >= daLux in at least sdaFraction of the occupied hours
  bool aseExceeded = false;  // aseHours > AnnualThresholds::aseHours
};

// Grid summary with the names summary.json / summary.csv carry.
struct GridAnnualSummary {
  double DA300 = 0, cDA300 = 0;                 // grid means of the sensors' da / cda, %
  double UDI_fell_short = 0, UDI_supplementary = 0, UDI_autonomous = 0, UDI_exceeded = 0;  // grid means, %
  double sDA300_50 = 0;    // % of sensors with sdaPass (LM-83 sDA300/50%)
  double ASE1000_250 = 0;  // % of sensors with aseExceeded (LM-83 ASE1000,250h)
  double sunHoursMean = 0; // mean over sensors of sunHours, h
  int sensors = 0;
  int occupiedHours = 0;
};

// Operable blinds of LM-83-12 2.2.6 for one window group serving the whole grid: in an occupied
// hour the blinds are closed when MORE than `fraction` of the sensors receive direct sun
// (direct-sun illuminance >= aseLux, lux). Unoccupied hours are reported open (0).
// `directSun` is sensor-major: sensor s at hour h is directSun[s * nHours + h], lux, direct beam
// sunlight only (zero bounces, blinds open). Returns one 0/1 flag per hour.
// Throws std::invalid_argument on a null array, negative counts or occupied.size() != nHours.
std::vector<char> blindsClosedHours(const float* directSun, int nSensors, int nHours,
                                    const std::vector<char>& occupied, double aseLux = 1000.0,
                                    double fraction = 0.02);

// The same rule for a grid whose hours arrive in blocks of sensors (study/annual_study.cpp keeps
// one block in memory): countSunlitSensors adds, for every hour, the sensors of the block with
// direct sun >= aseLux to `sunlit` (nHours counts, zero before the first block);
// blindsClosedFromCounts then applies the rule to the grid's nSensors. blindsClosedHours is the
// two in one call. Throws std::invalid_argument on a null array, negative counts or sizes that
// are not nHours.
void countSunlitSensors(const float* directSun, int nSensors, int nHours, double aseLux, std::vector<int>& sunlit);
std::vector<char> blindsClosedFromCounts(const std::vector<int>& sunlit, int nSensors,
                                         const std::vector<char>& occupied, double fraction = 0.02);

// Per-sensor metrics in one pass per sensor. All arrays sensor-major, lux:
//   total[s * nHours + h]       illuminance with blinds open (all light: sun, sky, interreflection)
//   directSun[s * nHours + h]   direct beam sunlight only, no interreflection, blinds open; used
//                               for ASE and sun hours. May be null: aseHours = sunHours = 0.
//   shadedTotal[s * nHours + h] illuminance with blinds closed; with `blindsClosed` (one flag per
//                               hour) it replaces `total` in the closed hours for DA, cDA, UDI and
//                               sDA. Ignored unless both are given. ASE always uses directSun.
// `occupied` has one flag per hour. Throws std::invalid_argument on a null `total`, negative
// counts or a flag vector whose size is not nHours.
std::vector<SensorAnnualMetrics> sensorAnnualMetrics(const float* total, const float* directSun,
                                                     int nSensors, int nHours,
                                                     const std::vector<char>& occupied,
                                                     const AnnualThresholds& t,
                                                     const float* shadedTotal = nullptr,
                                                     const std::vector<char>* blindsClosed = nullptr);

// Grid summary: means of the per-sensor percentages and sun hours, shares of passing sensors.
// Sensors are taken as standing for equal areas (a regular grid), as LM-83's "percent of analysis
// points". `occupiedHours` is copied into the summary (count of occupied flags). An empty grid
// gives zeros.
GridAnnualSummary summarizeAnnual(const std::vector<SensorAnnualMetrics>& sensors, int occupiedHours);

// Number of set flags, for GridAnnualSummary::occupiedHours.
int countHours(const std::vector<char>& flags);

}  // namespace candela
