#!/usr/bin/env bash
# candela's side of the time-to-accuracy table against Radiance (docs/performance.md, "Time to
# accuracy against Radiance"; issue 37). Not run by CI (minutes of CPU).
#
#   scripts/candela_t2a.sh CANDELA WORKDIR [office sunny sphere] [--refs]
#
# Runs the ladder (draft, normal, high at the defaults, and normal with --target-error 0 and 2)
# and, with --refs, the converged references (path method, seeds 1001 and 1002). Writes
# <case>-<run>.lux (one illuminance a line, in the order of scripts/radiance_t2a.sh's points),
# <case>-<run>.se (standard errors) and <case>-<run>.cpu (user+sys CPU s). The cases are copies
# made in WORKDIR: office = cases/office with its workplane grid only and black luminaire openings
# (opening_reflectance = 0: Radiance's light polygons reflect nothing); sunny =
# cases/office-daylight/sunny.toml; sphere = the integrating sphere of radiance_t2a.sh (points).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 CANDELA WORKDIR [office sunny sphere] [--refs]" >&2; exit 2; }
CANDELA=$(realpath "$1"); mkdir -p "$2"; W=$(cd "$2" && pwd); shift 2
REFS=0; CASES=""
for a in "$@"; do if [ "$a" = --refs ]; then REFS=1; else CASES="$CASES $a"; fi; done
CASES=${CASES:-office sunny sphere}
REPO=$(cd "$(dirname "$0")/.." && pwd)
cd "$W"

cat > office.toml <<EOF
[case]
name = "office workplane, black openings"
[[scene]]
file = "$REPO/cases/office/office.rad"
[[luminaire]]
file = "$REPO/cases/luminaires/led_panel_600.ldt"
position = [1.2, 1.1, 2.99]
maintenance_factor = 0.8
opening_reflectance = 0
array = { rows = 3, columns = 5, spacing = [2.4, 2.1] }
[[luminaire]]
file = "$REPO/cases/luminaires/downlight_150.ies"
position = [2.0, 7.4, 2.99]
maintenance_factor = 0.8
opening_reflectance = 0
array = { rows = 1, columns = 3, spacing = [4.0, 1.0] }
[[grid]]
name = "workplane"
corners = [[0.0, 0.0], [12.0, 6.35]]
height = 0.8
spacing = 0.35
border = 0.5
[settings]
quality = "normal"
seed = 1
EOF
sed "s|\"../office/office.rad\"|\"$REPO/cases/office/office.rad\"|" "$REPO/cases/office-daylight/sunny.toml" |
  grep -v '^dir = ' > sunny.toml
printf '%s\n' "void light lamp 0 0 3 1000 1000 1000" "lamp sphere bulb 0 0 4 0 0 0 0.02" \
  "void plastic wall 0 0 5 .5 .5 .5 0 0" "wall bubble shell 0 0 4 0 0 0 1" > sphere.rad
python3 -c "
import math
for i in range(64):
    z = 1 - (i + 0.5) / 32; r = math.sqrt(1 - z * z); p = i * math.pi * (3 - math.sqrt(5))
    d = (r * math.cos(p), r * math.sin(p), z)
    print(*(f'{0.999 * a:.6f}' for a in d), *(f'{-a:.6f}' for a in d))" > sphere.pts

# one run: case tag, then candela's options
run() {
  local c=$1 tag=$2; shift 2
  if [ "$c" = sphere ]; then
    /usr/bin/time -f '%U+%S' -o "$c-$tag.time" "$CANDELA" points -q --error sphere.rad --points sphere.pts "$@" > "$c-$tag.csv"
    tail -n +2 "$c-$tag.csv" | cut -d, -f7 > "$c-$tag.lux"; tail -n +2 "$c-$tag.csv" | cut -d, -f8 > "$c-$tag.se"
  else
    rm -rf "out-$c-$tag"
    /usr/bin/time -f '%U+%S' -o "$c-$tag.time" "$CANDELA" run -q "$c.toml" --out "out-$c-$tag" "$@" > /dev/null
    # the grid CSV's points in row order (y outer, x inner), as radiance_t2a.sh writes them
    python3 - "out-$c-$tag/workplane.csv" "$c-$tag" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
rows.sort(key=lambda r: (round(float(r["y"]), 4), round(float(r["x"]), 4)))
open(sys.argv[2] + ".lux", "w").write("".join(r["illuminance_lux"] + "\n" for r in rows))
open(sys.argv[2] + ".se", "w").write("".join(r.get("error_lux", "0") + "\n" for r in rows))
EOF
  fi
  python3 -c "import sys; print(round(eval(open(sys.argv[1]).read().split()[-1]), 2))" "$c-$tag.time" > "$c-$tag.cpu"
  echo "$c $tag ($*): $(cat "$c-$tag.cpu") CPU s"
}

for c in $CASES; do
  if [ $REFS = 1 ] && [ "$c" != sphere ]; then
    te=0.15; [ "$c" = sunny ] && te=1
    run "$c" ref1001 --method path --target-error $te --seed 1001
    run "$c" ref1002 --method path --target-error $te --seed 1002
  fi
  run "$c" draft --quality draft
  run "$c" normal --quality normal
  run "$c" high --quality high
  run "$c" normal-te0 --quality normal --target-error 0
  run "$c" normal-te2 --quality normal --target-error 2
done
