#!/usr/bin/env bash
# usage: luminaire_ugr_default_out.sh CANDELA GOOD_FILE BAD_FILE
# `candela luminaire GOOD --ugr-table --no-svg` run in an empty folder writes <stem>_ugr.csv and
# <stem>_ugr.svg there and nothing else; the CSV has the header and 19 rooms × (3 + 10) fields,
# every UGR a number. BAD (no luminous area) exits 2 and leaves the folder empty.
set -u
candela=$1 good=$2 bad=$3
dir=$(mktemp -d)
err=$(mktemp)
trap 'rm -rf "$dir" "$err"' EXIT
cd "$dir" || exit 1
status=0
fail() { echo "$1"; status=1; }
out=$("$candela" luminaire "$good" --ugr-table --no-svg 2>"$err")
code=$?
[ "$code" = 0 ] || fail "exit code $code, expected 0"
stem=$(basename "${good%.*}")
csv="${stem}_ugr.csv"
[ -s "$csv" ] || fail "$csv missing"
[ -s "${stem}_ugr.svg" ] || fail "${stem}_ugr.svg missing"
extra=$(ls -A | grep -vx -e "$csv" -e "${stem}_ugr.svg")
[ -z "$extra" ] || fail "also written: $extra"
header="room_x_H,room_y_H,luminaires"
for side in crosswise endwise; do
  for r in 70_50_20 70_30_20 50_50_20 50_30_20 30_30_20; do header="$header,${side}_$r"; done
done
[ "$(head -1 "$csv")" = "$header" ] || fail "header is $(head -1 "$csv")"
[ "$(wc -l <"$csv")" = 20 ] || fail "$(wc -l <"$csv") lines, expected 20"
rooms=$(tail -n +2 "$csv" | cut -d, -f1,2 | tr '\n' ' ')
[ "$rooms" = "2,2 2,3 2,4 2,6 2,8 2,12 4,2 4,3 4,4 4,6 4,8 4,12 8,4 8,6 8,8 8,12 12,4 12,6 12,8 " ] ||
  fail "rooms: $rooms"
bad_rows=$(tail -n +2 "$csv" | awk -F, 'NF != 13 { print; next }
  { for (i = 4; i <= 13; ++i) if ($i !~ /^[0-9]+\.[0-9][0-9]$/) { print; next } }')
[ -z "$bad_rows" ] || fail "rows not 13 fields of numbers: $bad_rows"
grep -qF "Viewed crosswise" <<<"$out" || fail "stdout lacks the table"
rm -f "$csv" "${stem}_ugr.svg"
"$candela" luminaire "$bad" --ugr-table --no-svg >/dev/null 2>"$err"
code=$?
[ "$code" = 2 ] || fail "bad file: exit code $code, expected 2"
[ "$(wc -l <"$err")" = 1 ] || fail "bad file: stderr is not one line"
[ -z "$(ls -A)" ] || fail "bad file: wrote $(ls -A)"
if [ $status != 0 ]; then echo "--- stdout"; head -60 <<<"$out"; echo "--- stderr"; cat "$err"; fi
exit $status
