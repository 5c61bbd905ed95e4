#!/usr/bin/env python3
"""Writes a SYNTHETIC EnergyPlus weather file for candela's tests (not measured data).

Site: Golden, Colorado (39.74 N, 105.18 W, UTC-7, 1829 m), year 2026, 8760 hours.
Sun: Spencer (1971) declination and equation of time at the middle of each hour-ending record.
Clear-sky direct normal: Meinel & Meinel (1976) DNI = E0 * 0.7^(AM^0.678), AM = Kasten-Young.
Weather: a deterministic cloudiness c in [0, 1] per day (LCG), DNI * (1 - c),
DHI = (0.08 + 0.35 c) * E0 * cos Z * 0.7^(AM^0.678)^0.5 (a plausible, not physical, split).
Illuminances use constant efficacies (110 lm/W global, 100 direct, 120 diffuse).
Usage: python3 make_synthetic_epw.py > synthetic_golden_2026.epw
"""
import math
import sys

LAT, LON, TZ, ELEV = 39.74, -105.18, -7.0, 1829.0
YEAR = 2026
DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
FLAGS = "?9?9?9?9E0?9?9?9?9?9?9?9?9?9?9?9?9?9?9?9*9*9?9?9?9"


def sun(doy, local_hour):
    g = 2 * math.pi * (doy - 1) / 365.0
    decl = (0.006918 - 0.399912 * math.cos(g) + 0.070257 * math.sin(g) - 0.006758 * math.cos(2 * g)
            + 0.000907 * math.sin(2 * g) - 0.002697 * math.cos(3 * g) + 0.00148 * math.sin(3 * g))
    eot_min = 229.18 * (0.000075 + 0.001868 * math.cos(g) - 0.032077 * math.sin(g)
                        - 0.014615 * math.cos(2 * g) - 0.040849 * math.sin(2 * g))
    solar_time = local_hour + (4.0 * (LON - 15.0 * TZ) + eot_min) / 60.0
    ha = math.radians(15.0 * (solar_time - 12.0))
    lat = math.radians(LAT)
    cosz = math.sin(lat) * math.sin(decl) + math.cos(lat) * math.cos(decl) * math.cos(ha)
    e0 = 1367.0 * (1.00011 + 0.034221 * math.cos(g) + 0.00128 * math.sin(g)
                   + 0.000719 * math.cos(2 * g) + 0.000077 * math.sin(2 * g))
    return cosz, e0


def main():
    out = sys.stdout
    out.write("LOCATION,Golden SYNTHETIC,CO,USA,SYNTHETIC candela test data,000000,%.2f,%.2f,%.1f,%.1f\n"
              % (LAT, LON, TZ, ELEV))
    out.write("DESIGN CONDITIONS,0\n")
    out.write("TYPICAL/EXTREME PERIODS,0\n")
    out.write("GROUND TEMPERATURES,0\n")
    out.write("HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0\n")
    out.write("COMMENTS 1,SYNTHETIC weather made for candela tests by tests/data/epw/make_synthetic_epw.py;"
              " clear-sky model with deterministic clouds - not measured data\n")
    out.write("COMMENTS 2,Do not use for design\n")
    out.write("DATA PERIODS,1,1,Data,Thursday, 1/ 1,12/31\n")
    seed = 12345
    doy = 0
    for month in range(1, 13):
        for day in range(1, DAYS[month - 1] + 1):
            doy += 1
            seed = (1103515245 * seed + 12345) % 2147483648
            cloud = (seed / 2147483648.0) ** 2  # mostly clear days
            for hour in range(1, 25):
                cosz, e0 = sun(doy, hour - 0.5)
                season = math.cos(2 * math.pi * (doy - 200) / 365.0)
                t = 10.0 + 12.0 * season + 6.0 * math.sin(2 * math.pi * (hour - 9) / 24.0)
                td = t - 8.0 - 4.0 * cloud
                if cosz > 0.01:
                    zdeg = math.degrees(math.acos(cosz))
                    am = 1.0 / (cosz + 0.50572 * (96.07995 - zdeg) ** -1.6364)
                    trans = 0.7 ** (am ** 0.678)
                    dni = e0 * trans * (1.0 - cloud)
                    dhi = (0.08 + 0.35 * cloud) * e0 * cosz * math.sqrt(trans)
                    ghi = dni * cosz + dhi
                    etr_h = e0 * cosz
                else:
                    dni = dhi = ghi = etr_h = 0.0
                fields = [YEAR, month, day, hour, 60, FLAGS, "%.1f" % t, "%.1f" % td, 50, 82000,
                          "%d" % round(etr_h), "%d" % round(e0 if cosz > 0.01 else 0), 300,
                          "%d" % round(ghi), "%d" % round(dni), "%d" % round(dhi),
                          "%d" % round(110 * ghi), "%d" % round(100 * dni), "%d" % round(120 * dhi), 0,
                          180, 2.0, round(10 * cloud), round(8 * cloud), 9999, 77777, 9, 999999999, 1.0,
                          0.1, 0, 88, 0.2, 0, 0.0]
                assert len(fields) == 35
                out.write(",".join(str(f) for f in fields) + "\n")


if __name__ == "__main__":
    main()
