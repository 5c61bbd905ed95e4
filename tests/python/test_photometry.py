"""candela.read_luminaire and candela.sun_position against independent numbers."""
import datetime
import math
import subprocess

import numpy as np
import pytest

import candela


def bilinear_web_flux(planes_deg, polar_deg, cd):
    """The flux (lm) of the bilinear interpolant of an intensity table over (C, gamma), integrated
    exactly: linear in C, the C-integral is the mean of a cell's two planes times ΔC; linear in
    gamma, ∫ (I0 + (I1 - I0) (γ - γ0)/Δγ) sin γ dγ in closed form."""
    c = np.radians(planes_deg)
    g = np.radians(polar_deg)
    total = 0.0
    for i in range(len(c) - 1):
        dc = c[i + 1] - c[i]
        mean = 0.5 * (cd[i] + cd[i + 1])  # intensity over gamma, averaged across the cell in C
        for j in range(len(g) - 1):
            g0, g1 = g[j], g[j + 1]
            dg = g1 - g0
            i0, i1 = mean[j], mean[j + 1]
            s0 = math.cos(g0) - math.cos(g1)                      # ∫ sin γ dγ
            s1 = -dg * math.cos(g1) + math.sin(g1) - math.sin(g0)  # ∫ (γ - γ0) sin γ dγ
            total += dc * (i0 * s0 + (i1 - i0) / dg * s1)
    return total


@pytest.mark.parametrize("name", ["cu-ies/1.IES", "cu-ies/5.IES", "eulumdat-rs/0-0-1.ldt"])
def test_read_luminaire_flux_is_the_integral_of_its_web(reference, name):
    lum = candela.read_luminaire(reference / "photometry" / name)
    assert lum.intensity_cd.shape == (len(lum.plane_angles_deg), len(lum.polar_angles_deg))
    assert lum.plane_angles_deg[0] == 0.0 and lum.plane_angles_deg[-1] == 360.0  # type C, the full circle
    flux = bilinear_web_flux(lum.plane_angles_deg, lum.polar_angles_deg, lum.intensity_cd)
    # Both are exact integrals of one interpolant: only rounding separates them.
    assert lum.total_lumens == pytest.approx(flux, rel=1e-9)
    assert sum(lum.zonal_lumens) == pytest.approx(lum.total_lumens, rel=1e-9)
    assert lum.max_intensity_cd == pytest.approx(lum.intensity_cd.max(), rel=1e-12)


def test_read_luminaire_matches_the_command_line(reference, candela_exe, tmp_path):
    path = reference / "photometry" / "cu-ies" / "1.IES"
    lum = candela.read_luminaire(path)
    # (candela luminaire writes its polar plot into the working folder.)
    text = subprocess.run([candela_exe, "luminaire", str(path)], capture_output=True, text=True, check=True,
                          cwd=tmp_path).stdout
    line = next(l for l in text.splitlines() if l.startswith("Luminous flux:"))
    printed = float(line.split()[2])
    assert lum.total_lumens == pytest.approx(printed, abs=0.05)  # printed to 0.1 lm
    assert lum.input_watts == 69.6 and lum.lamp_lumens is None  # absolute photometry


def test_read_luminaire_error_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.ies"
    bad.write_text("IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 1000 1 2 1 1 2 0 0 0\n1 1 50\n0 90\nx\n100 50\n")
    with pytest.raises(candela.InputError) as e:
        candela.read_luminaire(bad)
    assert e.value.file.endswith("bad.ies")
    assert e.value.line > 0
    assert str(e.value).startswith(f"{e.value.file}:{e.value.line}: ")


def test_sun_position_nrel_spa_test_vector():
    # NREL/TP-560-34302, the report's example: 17 October 2003, 12:30:30 at UTC-7, Golden
    # (39.742476 N, 105.1786 W, 1830.14 m): zenith 50.11162°, azimuth 194.34024°. The report uses
    # 820 mbar and 11 °C; candela's default 1013.25 mbar and 15 °C refract 0.004° more at this
    # altitude (Bennett's formula): 0.01° covers it. Azimuth is not refracted.
    site = candela.Site(39.742476, -105.1786, timezone=-7, elevation=1830.14)
    sun = candela.sun_position(site, "2003-10-17T12:30:30")
    assert sun.zenith_deg == pytest.approx(50.11162, abs=0.01)
    assert sun.azimuth_deg == pytest.approx(194.34024, abs=0.001)
    assert sun.altitude_deg == pytest.approx(90.0 - sun.zenith_deg, abs=1e-12)
    assert sun.sunrise_hour < sun.transit_hour < sun.sunset_hour


def test_sun_position_datetime_and_offset_agree_with_text():
    site = candela.Site(51.5, -0.1, timezone=0.0)
    text = candela.sun_position(site, "2026-06-21T15:00:00+02:00")
    aware = candela.sun_position(site, datetime.datetime(2026, 6, 21, 15, 0, tzinfo=datetime.timezone(datetime.timedelta(hours=2))))
    utc = candela.sun_position(site, "2026-06-21T13:00")
    assert aware == text
    assert utc.azimuth_deg == pytest.approx(text.azimuth_deg, abs=1e-9)
    assert utc.altitude_deg == pytest.approx(text.altitude_deg, abs=1e-9)


def test_sun_position_matches_candela_sun(candela_exe):
    site = candela.Site(37.87, -122.27, timezone=-8)
    sun = candela.sun_position(site, "2026-03-21T10:15")
    out = subprocess.run([candela_exe, "sun", "--lat", "37.87", "--lon", "-122.27", "--timezone", "-8", "--time",
                          "2026-03-21T10:15"], capture_output=True, text=True, check=True).stdout
    printed = dict(line.split() for line in out.splitlines() if line.endswith(tuple("0123456789")) and "_deg" in line)
    assert sun.altitude_deg == pytest.approx(float(printed["altitude_deg"]), abs=5e-6)  # printed to 5 decimals
    assert sun.azimuth_deg == pytest.approx(float(printed["azimuth_deg"]), abs=5e-6)


def test_sun_position_bad_time_is_an_input_error():
    with pytest.raises(candela.InputError) as e:
        candela.sun_position(candela.Site(0, 0), "2026-02-30T12:00")
    assert "2026-02-30" in str(e.value) or "day" in str(e.value)
    with pytest.raises(candela.InputError):
        candela.sun_position(candela.Site(95, 0), "2026-02-03T12:00")
