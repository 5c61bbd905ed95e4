#!/usr/bin/env bash
# Radiance's side of the time-to-accuracy table (docs/performance.md, "Time to accuracy against
# Radiance"; issue 37). NEVER run by CI: it needs a Radiance build from its public source.
#
#   scripts/radiance_t2a.sh RADIANCE_BIN RADIANCE_LIB WORKDIR [case ...]
#
# RADIANCE_BIN holds rtrace, oconv, xform, ies2rad, rcalc, total; RADIANCE_LIB is Radiance's lib
# folder (source.cal); WORKDIR receives the scenes, the points and one file per run:
# <case>-S<k>.lux (one illuminance a line, lux) and <case>-S<k>.cpu (user+sys CPU s of rtrace).
# Cases: office (cases/office, luminaires from ies2rad), sunny (cases/office-daylight/sunny.toml's
# sky as a Radiance description), sphere (integrating sphere, rho 0.5, 64 points).
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 RADIANCE_BIN RADIANCE_LIB WORKDIR [office sunny sphere]" >&2; exit 2; }
RBIN=$(cd "$1" && pwd); RLIB=$(cd "$2" && pwd); mkdir -p "$3"; W=$(cd "$3" && pwd); shift 3
CASES=${*:-office sunny sphere}
REPO=$(cd "$(dirname "$0")/.." && pwd)
export PATH="$RBIN:$PATH" RAYPATH=".:$RLIB"
cd "$W"

# The three settings (all: -I -h, one process, no ambient file; -lr 12 so that -ab is the limit).
S1="-ab 2 -ad 512 -as 128 -aa .2 -ar 64 -lw 2e-3 -lr 12"
S2="-ab 4 -ad 2048 -as 512 -aa .1 -ar 128 -lw 5e-4 -lr 12"
S3="-ab 6 -ad 8192 -as 2048 -aa .05 -ar 256 -lw 1e-4 -lr 12"

# The workplane grids as candela lays them out (docs/case-format.md: the bounding box shrunk by the
# border, n = ceil(L / spacing) cells a side, points at the cell centres), facing up.
grid() {  # x0 y0 x1 y1 border spacing z
  python3 - "$@" <<'EOF'
import math, sys
x0, y0, x1, y1, b, s, z = map(float, sys.argv[1:8])
def axis(a, c):
    a += b; c -= b; n = math.ceil((c - a) / s - 1e-9); w = (c - a) / n
    return [a + (i + 0.5) * w for i in range(n)]
for y in axis(y0, y1):
    for x in axis(x0, x1):
        print(f"{x:.6f} {y:.6f} {z:.6f} 0 0 1")
EOF
}

for c in $CASES; do
  case $c in
  office)
    # 15 panels and 3 downlights as cases/office/case.toml places them: photometric centre at
    # `position`, nadir -Z, C0 along +X (ies2rad's frame), maintenance factor 0.8 as -m.
    cp "$REPO/cases/luminaires/led_panel_600.ies" "$REPO/cases/luminaires/downlight_150.ies" .
    ies2rad -dm -m 0.8 -o panel led_panel_600.ies
    ies2rad -dm -m 0.8 -o downlight downlight_150.ies
    { for r in 0 1 2; do for k in 0 1 2 3 4; do
        echo "!xform -n P_${r}_$k -t $(python3 -c "print(1.2+2.4*$k, 1.1+2.1*$r)") 2.99 panel.rad"; done; done
      for k in 0 1 2; do echo "!xform -n DL_$k -t $(python3 -c "print(2.0+4.0*$k)") 7.4 2.99 downlight.rad"; done
    } > office_lum.rad
    oconv "$REPO/cases/office/office.rad" office_lum.rad > office.oct
    grid 0 0 12 6.35 0.5 0.35 0.8 > office.pts ;;
  sunny)
    # cases/office-daylight/sunny.toml: candela's cie-clear (ISO 15469 type 12) of 12 000 lx, a
    # 0.533 deg sun of 80 000 lx direct normal at the SPA position (`candela sun --lat 37.87
    # --lon -122.27 --time 2026-03-21T12:00 --timezone -8`), a uniform ground rho 0.2.
    python3 "$REPO/scripts/radiance_cie_sky.py" 52.43908 173.38082 12000 80000 0.2 sky.cal > sky.rad
    oconv "$REPO/cases/office/office.rad" sky.rad > sunny.oct
    grid 0 0 12 6.35 0.5 0.5 0.8 > sunny.pts ;;
  sphere)
    # candela validate's integrating sphere (validation/cases_engine.cpp) at rho 0.5, 64 points
    # 1 mm inside the wall facing the centre (a Fibonacci lattice).
    printf '%s\n' "void light lamp 0 0 3 1000 1000 1000" "lamp sphere bulb 0 0 4 0 0 0 0.02" \
      "void plastic wall 0 0 5 .5 .5 .5 0 0" "wall bubble shell 0 0 4 0 0 0 1" > sphere.rad
    oconv sphere.rad > sphere.oct
    python3 -c "
import math
for i in range(64):
    z = 1 - (i + 0.5) / 32; r = math.sqrt(1 - z * z); p = i * math.pi * (3 - math.sqrt(5))
    d = (r * math.cos(p), r * math.sin(p), z)
    print(*(f'{0.999 * a:.6f}' for a in d), *(f'{-a:.6f}' for a in d))" > sphere.pts ;;
  *) echo "unknown case $c" >&2; exit 2 ;;
  esac
  for k in 1 2 3; do
    eval "S=\$S$k"
    # shellcheck disable=SC2086
    /usr/bin/time -f '%U+%S' -o "$c-S$k.time" rtrace -h -I $S "$c.oct" < "$c.pts" > "$c-S$k.rgb"
    rcalc -e '$1=179*(.265*$1+.670*$2+.065*$3)' "$c-S$k.rgb" > "$c-S$k.lux"
    python3 -c "import sys; print(eval(open(sys.argv[1]).read().split()[-1]))" "$c-S$k.time" > "$c-S$k.cpu"
    echo "$c S$k ($S): $(cat "$c-S$k.cpu") CPU s, mean $(total -m "$c-S$k.lux") lx"
  done
done
