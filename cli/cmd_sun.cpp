// candela sun: solar position (NREL SPA) and the day's sunrise/sunset at a site and time.
#include "cli/commands.h"

#include "base/error.h"
#include "photometry/site.h"
#include "photometry/sun_spa.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace candela::cli {

namespace {

struct SunOptions {
  std::string lat, lon, time;
  double elevationM = 0.0;
  double pressureMbar = 1013.25;
  double temperatureC = 15.0;
  std::optional<double> deltaTSec;
  double timezoneHours = 0.0;
};

int runSun(const SunOptions& o) {
  SpaInput in;
  in.latitudeDeg = parseLatitudeDeg(o.lat, FileLoc{"--lat"});
  in.longitudeDeg = parseLongitudeDeg(o.lon, FileLoc{"--lon"});
  const LocalTime t = parseLocalTime(o.time, FileLoc{"--time"});
  // An offset written in --time is the time zone of that clock reading; else --timezone.
  in.timezoneHours = t.utcOffsetHours.value_or(o.timezoneHours);
  if (!(std::abs(in.timezoneHours) <= 18.0)) throw InputError(FileLoc{"--timezone"}, "must be in [-18, 18] hours");
  in.year = t.year;
  in.month = t.month;
  in.day = t.day;
  in.hourOfDay = t.hourOfDay();
  in.elevationM = o.elevationM;
  in.pressureMbar = o.pressureMbar;
  in.temperatureC = o.temperatureC;
  in.deltaTSec = o.deltaTSec.value_or(estimateDeltaTSec(t.year + (t.dayOfYear() - 0.5) / 365.25));
  SpaResult r;
  try {
    r = computeSunPosition(in);
  } catch (const InputError& e) {
    throw InputError(FileLoc{"candela sun"}, e.message());
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "zenith_deg %.5f\n", r.zenithDeg);
  std::cout << buf;
  std::snprintf(buf, sizeof buf, "azimuth_deg %.5f\n", r.azimuthDeg);
  std::cout << buf;
  std::snprintf(buf, sizeof buf, "altitude_deg %.5f\n", r.altitudeDeg);
  std::cout << buf;
  std::cout << "sunrise " << formatHours(r.sunriseHour) << "\n";
  std::cout << "sunset " << formatHours(r.sunsetHour) << "\n";
  std::cout << "transit " << formatHours(r.transitHour) << "\n";
  return 0;
}

}  // namespace

void addSunCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<SunOptions>();
  auto* cmd = app.add_subcommand("sun", "solar position (NREL SPA), sunrise and sunset at a site");
  cmd->add_option("--lat", opts->lat, "latitude, deg north (decimal or DMS, e.g. 37d52'N)")->required();
  cmd->add_option("--lon", opts->lon, "longitude, deg east (decimal or DMS, e.g. 122d16'W)")->required();
  cmd->add_option("--time", opts->time, "local standard time YYYY-MM-DDTHH:MM[:SS][+HH:MM]")->required();
  // Ranges: the places where people build (the Dead Sea shore to the highest summits, with room
  // for aircraft), the pressures and temperatures of the lower atmosphere, and Delta T over the
  // SPA's years (Reda & Andreas 2008, table 1: -8000 to 8000 s).
  cmd->add_option("--elevation", opts->elevationM, "site elevation, m (default 0)")->check(CLI::Range(-500.0, 12000.0));
  cmd->add_option("--pressure", opts->pressureMbar, "mean air pressure, mbar (default 1013.25; 0: no refraction)")
      ->check(CLI::Range(0.0, 1100.0));
  cmd->add_option("--temperature", opts->temperatureC, "mean air temperature, deg C (default 15)")
      ->check(CLI::Range(-90.0, 60.0));
  cmd->add_option("--delta-t", opts->deltaTSec, "TT - UT1, s (default: Espenak-Meeus estimate for the year)")
      ->check(CLI::Range(-8000.0, 8000.0));
  cmd->add_option("--timezone", opts->timezoneHours, "hours from UTC when --time has no offset (default 0)")
      ->check(CLI::Range(-18.0, 18.0));
  cmd->callback([opts, &action] { action = [opts] { return runSun(*opts); }; });
}

}  // namespace candela::cli
