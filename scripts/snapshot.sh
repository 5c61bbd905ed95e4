#!/usr/bin/env bash
# Behaviour snapshot for refactors (DEVELOPERS.md: "Refactors keep behaviour"): runs the demo
# cases, `points` and `validate --quick` at their fixed seeds on 1 and 2 threads with the
# executable in BUILD, into OUT. Compare two snapshots with scripts/snapshot_diff.py.
#
#   scripts/snapshot.sh BUILD_DIR OUT_DIR
# SNAPSHOT_QUICK=1: the same commands at --quality draft on 2 threads only (minutes instead of an
# hour: for a refactor's intermediate steps; the full snapshot still decides).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
exe="$(realpath "$1")/cli/candela"
out="$2"
mkdir -p "$out"
cd "$here"
threads=(1 2)
q=()
if [ "${SNAPSHOT_QUICK:-0}" = 1 ]; then
  threads=(2)
  q=(--quality draft)
fi
for t in "${threads[@]}"; do
  for c in office office-daylight office-annual small-room; do
    "$exe" run "cases/$c/case.toml" --out "$out/run-$c-t$t" --threads "$t" --quiet "${q[@]}"
  done
  "$exe" run cases/office-daylight/sunny.toml --out "$out/run-sunny-t$t" --threads "$t" --quiet "${q[@]}"
  "$exe" render cases/office/case.toml --view desk-fisheye --out "$out/render-office-t$t" --threads "$t" \
    --quiet "${q[@]}"
  for m in path cache; do
    "$exe" points cases/small-room/room.rad --points cases/small-room/sensors.pts --method "$m" --error \
      --threads "$t" >"$out/points-room-$m-t$t.csv"
    "$exe" points --case cases/small-room/case.toml --points cases/small-room/sensors.pts --method "$m" \
      --error --threads "$t" >"$out/points-case-$m-t$t.csv"
  done
  "$exe" points --case cases/office/case.toml --points cases/small-room/sensors.pts --error \
    --threads "$t" >"$out/points-officecase-t$t.csv"
  "$exe" validate --quick --out "$out/validate-t$t" --threads "$t" >"$out/validate-t$t.txt"
done
echo "$out"
