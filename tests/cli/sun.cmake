# candela sun: the NREL SPA report's example (Reda & Andreas, NREL/TP-560-34302, Table A5.2).
candela_cli_test(sun_spa_example 0 "zenith_deg 50.1116"
  sun --lat 39.742476 --lon -105.1786 --elevation 1830.14 --time 2003-10-17T12:30:30-07:00
  --pressure 820 --temperature 11 --delta-t 67)
candela_cli_test(sun_spa_example_azimuth 0 "azimuth_deg 194.3402"
  sun --lat 39.742476 --lon -105.1786 --elevation 1830.14 --time 2003-10-17T12:30:30
  --timezone -7 --pressure 820 --temperature 11 --delta-t 67)
candela_cli_test(sun_spa_example_sunrise 0 "sunrise 06:12:4"
  sun --lat 39.742476 --lon -105.1786 --elevation 1830.14 --time 2003-10-17T12:30:30-07:00
  --pressure 820 --temperature 11 --delta-t 67)
candela_cli_test(sun_dms_site 0 "altitude_deg"
  sun --lat 37d52'N --lon 122d16'W --time 2026-03-21T12:00 --timezone -8)
candela_cli_test(sun_bad_latitude 2 "--lat: latitude '95' is outside"
  sun --lat 95 --lon 0 --time 2026-03-21T12:00)
candela_cli_test(sun_bad_time 2 "--time: bad time"
  sun --lat 40 --lon 0 --time 2026-02-30T12:00)

# Values outside the places and atmospheres the SPA models are refused (exit 2), not computed.
candela_cli_test(sun.absurd_elevation 2 "--elevation: Value 1e308 not in range"
                 sun --lat 40 --lon -105 --time 2026-03-21T12:00 --elevation 1e308)
