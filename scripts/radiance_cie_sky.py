#!/usr/bin/env python3
"""radiance_cie_sky.py ALT AZ E_DH E_DN RHO CALFILE > sky.rad

A Radiance description of candela's `[sky] type = "cie-clear"` (ISO 15469 / CIE S 011 type 12,
photometry/sky_cie.cpp) for a point-in-time comparison with Radiance (docs/performance.md, "Time
to accuracy against Radiance"; never run by CI). ALT, AZ: the sun's altitude and azimuth (deg,
azimuth clockwise from north, model north = true north); E_DH: the sky's diffuse horizontal
illuminance (lux); E_DN: the sun's direct normal illuminance (lux; 0 for none); RHO: the ground's
reflectance. As engine/daylight.cpp builds it: the sky's zenith luminance scaled so that it gives
E_DH on a horizontal plane (integrated here numerically), the sun a 0.533 deg disk of luminance
E_DN / Omega, the ground uniform at RHO (E_DH + E_sun,h) / pi below the horizon. Radiance values
are luminance / 179 (W/sr/m2 of white light). Writes the function file CALFILE beside."""
import math
import sys

alt, az, edh, edn, rho = map(float, sys.argv[1:6])
calfile = sys.argv[6]
a, b, c, d, e = -1.0, -0.32, 10.0, -3.0, 0.45
ca = math.cos(math.radians(alt))
S = (math.sin(math.radians(az)) * ca, math.cos(math.radians(az)) * ca, math.sin(math.radians(alt)))
Zs = math.radians(90.0 - alt)


def f(chi):
    return 1 + c * (math.exp(d * chi) - math.exp(d * math.pi / 2)) + e * math.cos(chi) ** 2


def phi(cz):
    return 1 + a * math.exp(b / cz) if cz > 0.01 else 1.0


# Horizontal illuminance of the sky of relative luminance f(chi) phi(Z) / (f(Zs) phi(0)):
# midpoint rule, uniform in sin(altitude) and azimuth (equal solid angle cells).
N = 1200
tot = 0.0
for i in range(N):
    s = (i + 0.5) / N
    ch = math.sqrt(1 - s * s)
    for j in range(N):
        p = (j + 0.5) / N * 2 * math.pi
        cg = max(-1.0, min(1.0, ch * math.sin(p) * S[0] + ch * math.cos(p) * S[1] + s * S[2]))
        tot += f(math.acos(cg)) * phi(s) * s
tot *= 2 * math.pi / (N * N) / (f(Zs) * phi(1.0))
Lz = edh / tot
half = math.radians(0.533 / 2)
omega = 2 * math.pi * (1 - math.cos(half))
Lsun = edn / omega
Esun_h = Lsun * math.pi * math.sin(half) ** 2 * math.sin(math.radians(alt)) if alt > 0 else 0.0
Lg = rho * (edh + Esun_h) / math.pi
K = 179.0

with open(calfile, "w") as out:
    out.write("{ ISO 15469 type 12 sky (candela's cie-clear) written by scripts/radiance_cie_sky.py:\n"
              "  A1 zenith, A2 ground (W/sr/m2), A3..A5 the sun's direction, A6 f(Zs) phi(0) }\n"
              "cosg = Dx*A3 + Dy*A4 + Dz*A5;\n"
              "chi = Acos(if(cosg - 1, 1, if(-1 - cosg, -1, cosg)));\n"
              "fchi = 1 + 10*(exp(-3*chi) - exp(-3*PI/2)) + .45*cosg*cosg;\n"
              "phiz = if(Dz - .01, 1 - exp(-.32/Dz), 1);\n"
              "skyf = if(Dz, A1*fchi*phiz/A6, A2);\n")
print(f"# candela cie-clear: sun altitude {alt} azimuth {az}; {edh} lx diffuse horizontal, {edn} lx direct normal,"
      f" ground reflectance {rho}")
print(f"# zenith {Lz:.4f} cd/m2, ground {Lg:.4f} cd/m2, sun {Lsun:.6g} cd/m2")
print(f"void brightfunc skyfunc\n2 skyf {calfile}\n0\n6 {Lz / K:.9g} {Lg / K:.9g} {S[0]:.9f} {S[1]:.9f} {S[2]:.9f}"
      f" {f(Zs) * phi(1.0):.9g}")
print("skyfunc glow skyglow\n0\n0\n4 1 1 1 0")
print("skyglow source sky\n0\n0\n4 0 0 1 180")
print("skyglow source ground\n0\n0\n4 0 0 -1 180")
if edn > 0 and alt > 0:
    print(f"void light solar\n0\n0\n3 {Lsun / K:.9g} {Lsun / K:.9g} {Lsun / K:.9g}")
    print(f"solar source sun\n0\n0\n4 {S[0]:.9f} {S[1]:.9f} {S[2]:.9f} 0.533")
