#!/usr/bin/env bash
# Radiance's three-phase annual reference for cases/sidelit-bsdf (docs/bsdf.md, "Reference:
# Radiance"; issue 38). NEVER run by CI: it needs a Radiance build from its public source.
#
#   scripts/radiance_3phase.sh RADIANCE_BIN RADIANCE_LIB WORKDIR BLINDS_XML
#
# The clear state is Radiance's `glass` of transmissivity 0.96 as a Klems file
# (scripts/klems_xml.py glass 0.96), the blinds state BLINDS_XML (blinds30.xml). Weather: the EPW
# of cases/sidelit-annual. Prints DA300 and sDA300/50 % of each state over the occupied hours
# 08-18 (hour-ending 9..18, docs/annual-metrics.md), and ASE1000,250h from the direct sun through
# the clear glass (blinds open), one exact sun per hour (gendaylit's position and radiance).
set -euo pipefail
[ $# -eq 4 ] || { echo "usage: $0 RADIANCE_BIN RADIANCE_LIB WORKDIR BLINDS_XML" >&2; exit 2; }
RBIN=$(cd "$1" && pwd); RLIB=$(cd "$2" && pwd); mkdir -p "$3"; W=$(cd "$3" && pwd); BLINDS=$(realpath "$4")
REPO=$(cd "$(dirname "$0")/.." && pwd); C=$REPO/cases/sidelit-bsdf
export PATH="$RBIN:$PATH" RAYPATH=".:$RLIB"
cd "$W"

python3 "$REPO/scripts/klems_xml.py" glass 0.96 > glass96.xml
python3 - > wp.pts <<'EOF'
for j in range(10):
    for i in range(6):
        print(f"{0.75 + 0.5 * i:.2f} {0.75 + 0.5 * j:.2f} 0.8 0 0 1")
EOF
grep -v 'window_pane' "$C/room.rad" > room_nowin.rad
WIN="0.2 0 0.9  0.2 0 2.7  3.8 0 2.7  3.8 0 0.9"   # normal +y, into the room
# View matrix: sensors -> the window from inside (rays arrive at a receiver's front side).
printf '%s\n' "#@rfluxmtx h=kf u=Z" "void glow window_glow 0 0 4 1 1 1 0" \
  "window_glow polygon window_v 0 0 12 $WIN" > win_v.rad
# Daylight matrix: the window -> sky (rays leave a sender's back side, so the same orientation).
printf '%s\n' "#@rfluxmtx h=kf u=Z" "void glow window_d_mat 0 0 4 1 1 1 0" \
  "window_d_mat polygon window_d 0 0 12 $WIN" > win_d.rad
printf '%s\n' "#@rfluxmtx h=u u=Y" "void glow groundglow 0 0 4 1 1 1 0" \
  "groundglow source ground 0 0 4 0 0 -1 180" "#@rfluxmtx h=r1 u=Y" \
  "void glow skyglow 0 0 4 1 1 1 0" "skyglow source skydome 0 0 4 0 0 1 180" > skyrecv.rad
t() { /usr/bin/time -f "$1 %U+%S CPU s" -a -o times.log "${@:2}"; }
: > times.log
t V rfluxmtx -I+ -ab 12 -ad 16384 -lw 1e-5 -lr -24 - win_v.rad room_nowin.rad < wp.pts > V.mtx
t D rfluxmtx -c 20000 -ab 0 -lw 1e-4 win_d.rad skyrecv.rad room_nowin.rad > D.mtx
epw2wea "$REPO/tests/data/epw/synthetic_golden_2026.epw" golden.wea
t sky gendaymtx -m 1 golden.wea > sky.mtx
# Check against a point-in-time rtrace: the overcast sky of sky-overcast.rad as a sky vector.
gensky -ang 40 20 -c -B 55.866 -g 0.2 | genskyvec -m 1 > overcast.vec
for x in glass96.xml "$BLINDS"; do
  n=$(basename "$x" .xml)
  t "dctimestep-$n" dctimestep V.mtx "$x" D.mtx sky.mtx > "ann-$n.rgb"
  rmtxop -fa -c 47.435 119.93 11.635 "ann-$n.rgb" | sed -n '/^FORMAT/,$p' | tail -n +3 > "ann-$n.lux"
  dctimestep V.mtx "$x" D.mtx overcast.vec | rmtxop -fa -c 47.435 119.93 11.635 - |
    sed -n '/^FORMAT/,$p' | tail -n +3 > "overcast-$n.lux"
  echo "$n under the overcast sky of sky-overcast.rad: workplane mean $(total -m "overcast-$n.lux") lx"
done
# ASE: one sun per hour with direct light (gendaylit -W: position and radiance), clear glass.
python3 - <<'EOF'
import subprocess
wea = [l.split() for l in open("golden.wea") if l[0].isdigit()]
with open("suns.rad", "w") as out, open("suns.idx", "w") as idx, open("suns.mod", "w") as mods:
    for h, (m, d, t, dn, dh) in enumerate(wea):
        if float(dn) <= 0:
            continue
        r = subprocess.run(["gendaylit", m, d, t, "-a", "39.74", "-o", "105.18", "-m", "105", "-W", dn, dh],
                           capture_output=True, text=True).stdout.split()
        try:
            rad = float(r[r.index("light") + 5])
            dx, dy, dz = r[r.index("source") + 5:r.index("source") + 8]
        except ValueError:
            continue
        if float(dz) <= 0 or rad <= 0:
            continue
        out.write(f"void light sol{h} 0 0 3 1 1 1\nsol{h} source sun{h} 0 0 4 {dx} {dy} {dz} 0.533\n")
        idx.write(f"{h} {rad}\n")
        mods.write(f"sol{h}\n")
EOF
echo 'void glass window 0 0 3 0.96 0.96 0.96' > clear.rad
oconv clear.rad "$C/room.rad" suns.rad > ase.oct
t ase rcontrib -I+ -h -ab 0 -dc 1 -dt 0 -ds 0 -faa -M suns.mod ase.oct < wp.pts > ase.coef
python3 - glass96 "$(basename "$BLINDS" .xml)" <<'EOF'
import sys
wea = [l.split() for l in open("golden.wea") if l[0].isdigit()]
occ = [8 <= float(w[2]) < 18 for w in wea]
nocc = sum(occ)
for n in sys.argv[1:]:
    rows = [[float(v) for v in l.split()] for l in open(f"ann-{n}.lux")]
    da = [100 * sum(1 for h, e in enumerate(r) if occ[h] and e >= 300) / nocc for r in rows]
    sda = 100 * sum(1 for d in da if d >= 50) / len(da)
    print(f"{n}: {len(rows)} sensors, {nocc} occupied hours: DA300 {sum(da) / len(da):.2f} %, sDA300/50 {sda:.2f} %")
idx = [l.split() for l in open("suns.idx")]
hours = [int(h) for h, _ in idx]
R = [float(r) for _, r in idx]
ase_h = []
for l in open("ase.coef"):
    v = [float(x) for x in l.split()]
    e = [179 * (.265 * v[3 * k] + .670 * v[3 * k + 1] + .065 * v[3 * k + 2]) * R[k] for k in range(len(R))]
    ase_h.append(sum(1 for k, x in enumerate(e) if occ[hours[k]] and x >= 1000))
print(f"ASE1000,250h (clear glass, {len(R)} suns): {100 * sum(1 for a in ase_h if a > 250) / len(ase_h):.2f} % of "
      f"sensors; occupied hours >= 1000 lx a sensor: mean {sum(ase_h) / len(ase_h):.1f}, max {max(ase_h)}")
EOF
cat times.log
