#!/usr/bin/env python3
"""klems_xml.py lambertian TAU > lambert.xml
klems_xml.py glass TN > glass.xml

LBNL BSDF files (WINDOW 6 XML schema, Klems full basis, 145 x 145) for the Radiance reference runs
of docs/bsdf.md ("Reference: Radiance"; issue 38); the files they write are not committed.
"Transmission Front" and "Transmission Back" alike, no reflection.

lambertian: an ideal Lambertian transmitter, every BTDF entry TAU / pi. Its hemispherical
transmittance is TAU for every incident direction, so a window of it seen from inside has the
uniform luminance TAU E_v / pi, E_v the illuminance on its outside face.

glass: Radiance's `glass` of transmissivity TN (n = 1.52; the angular transmittance of
Radiance's src/rt/glass.c: Fresnel for both polarisations, the internal absorption TN^(1/cos
theta_t), multiple reflections) as the Klems file of clear glass: the straight-through patch
(the same index) gets T(theta_i) / Lambda_i, Lambda_i the patch's projected solid angle,
T at the patch's centre angle; every other entry 0."""
import math
import sys

mode = sys.argv[1]
tau = float(sys.argv[2])
if mode not in ("lambertian", "glass"):
    sys.exit("usage: klems_xml.py lambertian TAU | glass TN")
# The Klems full basis: (centre theta, number of phi divisions, lower, upper theta), degrees.
rings = [(0, 1, 0, 5), (10, 8, 5, 15), (20, 16, 15, 25), (30, 20, 25, 35), (40, 24, 35, 45),
         (50, 24, 45, 55), (60, 24, 55, 65), (70, 16, 65, 75), (82.5, 12, 75, 90)]
n = sum(r[1] for r in rings)
assert n == 145
out = sys.stdout
out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
out.write('<WindowElement xmlns="http://windows.lbl.gov" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">\n')
out.write("<WindowElementType>System</WindowElementType>\n<FileType>BSDF</FileType>\n<Optical>\n<Layer>\n")
out.write("\t<Material>\n\t\t<Name>%s %g</Name>\n\t\t<Manufacturer>none</Manufacturer>\n"
          "\t\t<DeviceType>Other</DeviceType>\n\t\t<Thickness unit=\"meter\">0</Thickness>\n\t</Material>\n" % (mode, tau))
out.write("\t<DataDefinition>\n\t\t<IncidentDataStructure>Columns</IncidentDataStructure>\n\t\t<AngleBasis>\n"
          "\t\t\t<AngleBasisName>LBNL/Klems Full</AngleBasisName>\n")
for th, nphi, lo, hi in rings:
    out.write("\t\t\t<AngleBasisBlock>\n\t\t\t\t<Theta>%g</Theta>\n\t\t\t\t<nPhis>%d</nPhis>\n\t\t\t\t<ThetaBounds>\n"
              "\t\t\t\t\t<LowerTheta>%g</LowerTheta>\n\t\t\t\t\t<UpperTheta>%g</UpperTheta>\n\t\t\t\t</ThetaBounds>\n"
              "\t\t\t</AngleBasisBlock>\n" % (th, nphi, lo, hi))
out.write("\t\t</AngleBasis>\n\t</DataDefinition>\n")
def glass_t(theta_deg, tn, n_glass=1.52):
    c1 = math.cos(math.radians(theta_deg))
    c2 = math.sqrt((1 - 1 / n_glass ** 2) + c1 * c1 / n_glass ** 2)
    d = tn ** (1 / c2)
    r1e = ((c1 - n_glass * c2) / (c1 + n_glass * c2)) ** 2
    r1m = ((1 / c1 - n_glass / c2) / (1 / c1 + n_glass / c2)) ** 2
    return 0.5 * (1 - r1e) ** 2 * d / (1 - r1e * r1e * d * d) + 0.5 * (1 - r1m) ** 2 * d / (1 - r1m * r1m * d * d)


patches = []  # (centre theta, projected solid angle)
for th, nphi, lo, hi in rings:
    lam = math.pi * (math.sin(math.radians(hi)) ** 2 - math.sin(math.radians(lo)) ** 2) / nphi
    patches += [(th, lam)] * nphi
if mode == "lambertian":
    v = "%.6e" % (tau / math.pi)
    rows = [" ".join([v] * n)] * n
else:
    rows = []
    for i, (th, lam) in enumerate(patches):
        rows.append(" ".join("%.6e" % (glass_t(th, tau) / lam) if j == i else "0" for j in range(n)))
for direction in ("Transmission Front", "Transmission Back"):
    out.write("\t<WavelengthData>\n\t\t<LayerNumber>System</LayerNumber>\n\t\t<Wavelength unit=\"Integral\">Visible</Wavelength>\n"
              "\t\t<SourceSpectrum>CIE Illuminant D65 1nm.ssp</SourceSpectrum>\n"
              "\t\t<DetectorSpectrum>ASTM E308 1931 Y.dsp</DetectorSpectrum>\n\t\t<WavelengthDataBlock>\n"
              "\t\t\t<WavelengthDataDirection>%s</WavelengthDataDirection>\n"
              "\t\t\t<ColumnAngleBasis>LBNL/Klems Full</ColumnAngleBasis>\n\t\t\t<RowAngleBasis>LBNL/Klems Full</RowAngleBasis>\n"
              "\t\t\t<ScatteringDataType>BTDF</ScatteringDataType>\n\t\t\t<ScatteringData>\n" % direction)
    for row in rows:
        out.write(row + "\n")
    out.write("\t\t\t</ScatteringData>\n\t\t</WavelengthDataBlock>\n\t</WavelengthData>\n")
out.write("</Layer>\n</Optical>\n</WindowElement>\n")
