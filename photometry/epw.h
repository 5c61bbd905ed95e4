// EnergyPlus weather (EPW) reader: the LOCATION header and the hourly records' solar fields.
// Format: EnergyPlus "Auxiliary Programs", chapter "Weather Converter Program", section "EnergyPlus
// Weather File (EPW) Data Dictionary". Eight header lines (LOCATION, DESIGN CONDITIONS,
// TYPICAL/EXTREME PERIODS, GROUND TEMPERATURES, HOLIDAYS/DAYLIGHT SAVINGS, COMMENTS 1,
// COMMENTS 2, DATA PERIODS), then one comma-separated record per hour with 35 fields.
#pragma once

#include "base/error.h"

#include <istream>
#include <string>
#include <vector>

namespace candela {

struct EpwLocation {
  std::string city, region, country, source, wmo;
  double latitudeDeg = 0.0;    // north positive
  double longitudeDeg = 0.0;   // east positive
  double timezoneHours = 0.0;  // standard time minus UTC
  double elevationM = 0.0;
};

// One hour. EPW values are sums over the hour ENDING at `hour` (1..24, local standard time):
// record hour 13 covers 12:00-13:00, so its sun position is usually taken at 12:30.
// Missing values (9999 for irradiation, 999999 for illuminance, 99.9 / 999 for temperatures
// per the dictionary) are stored as NaN.
struct EpwRecord {
  int year = 0, month = 0, day = 0, hour = 0;  // hour 1..24
  int minute = 0;
  double dryBulbC = 0.0;
  double dewPointC = 0.0;
  double globalHorizontalWhm2 = 0.0;   // Wh/m2 over the hour (= mean W/m2)
  double directNormalWhm2 = 0.0;
  double diffuseHorizontalWhm2 = 0.0;
  double globalHorizontalLux = 0.0;    // lux (hour average)
  double directNormalLux = 0.0;
  double diffuseHorizontalLux = 0.0;
  int line = 0;  // 1-based line in the file, for messages
};

struct EpwFile {
  EpwLocation location;
  std::vector<EpwRecord> records;
  // 8760 or 8784 hourly records.
  // Records whose direct normal or diffuse horizontal radiation is missing (a missing mark, an
  // empty field or -999): their sky is dark (docs/daylight.md).
  int missingIrradianceHours = 0;
  // 8760 or 8784 hourly records from 1 January hour 1 (records always run hour by hour).
  bool isFullYear() const {
    return (records.size() == 8760 || records.size() == 8784) && records.front().month == 1 &&
           records.front().day == 1 && records.front().hour == 1;
  }
};

// Throws InputError "file:line: message" for a missing or malformed LOCATION line, a record
// with fewer than 35 fields, a field that is not a number, a month/day/hour out of range, or a
// record that is not the hour after the one before it (a repeat or a gap).
EpwFile readEpw(const std::string& path);
EpwFile parseEpw(std::istream& in, const std::string& fileName);

}  // namespace candela
