#!/usr/bin/env bash
# usage: modelling.sh CANDELA CASE.toml GRID...
# Runs `candela run CASE.toml` and checks, for each GRID (its index in the case, 0-based, and
# its name: "0:seated"), that summary.json's grids[i].modelling holds the averages Ē_z and Ē_h of
# the grid's CSV columns, their ratio, and the verdict of the ratio against 0.30–0.60, and that
# each CSV row's modelling_ratio is its own E_z/E_h.
set -u
exe=$1; case_file=$2; shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" run "$case_file" --out "$tmp/out" --quiet </dev/null >"$tmp/stdout" 2>"$tmp/stderr" ||
  { echo "run failed:"; cat "$tmp/stderr"; exit 1; }
status=0
for g in "$@"; do
  index=${g%%:*}; name=${g#*:}
  # summary.json (nlohmann dump, 2 spaces, sorted keys): the grid's modelling block.
  block=$(awk -v want="$index" '
    /^  "grids": \[/ { in_grids = 1; depth = 0; grid = -1; next }
    in_grids && /^    \{/ { grid++ }
    in_grids && grid == want && /"modelling": \{/ { grab = 1 }
    grab { print }
    grab && /^      \}/ { exit }' "$tmp/out/summary.json")
  value() { printf '%s\n' "$block" | sed -n "s/.*\"$1\": \\([^,]*\\),*$/\\1/p" | head -1; }
  ez=$(value cylindrical_average_lux); eh=$(value horizontal_average_lux); ratio=$(value ratio)
  verdict=$(value verdict | tr -d '"')
  if [ -z "$ez" ] || [ -z "$eh" ] || [ -z "$ratio" ] || [ -z "$verdict" ]; then
    echo "grid $name: no modelling block in summary.json"; status=1; continue
  fi
  csv="$tmp/out/$name.csv"
  check=$(awk -F, -v ez="$ez" -v eh="$eh" -v ratio="$ratio" -v verdict="$verdict" '
    function abs(x) { return x < 0 ? -x : x }
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    {
      z = $col["cylindrical_illuminance_lux"]; h = $col["horizontal_illuminance_lux"]; r = $col["modelling_ratio"]
      sz += z; sh += h; n++
      if (abs(r - z / h) > 1e-7 * r) bad = bad " row " NR ": ratio " r " but " z "/" h
    }
    END {
      if (n == 0) { print "no rows"; exit }
      # The CSV holds 8 significant digits.
      if (abs(sz / n - ez) > 1e-7 * ez) print "Ez " ez " but the CSV averages " sz / n
      if (abs(sh / n - eh) > 1e-7 * eh) print "Eh " eh " but the CSV averages " sh / n
      if (abs(ratio - ez / eh) > 1e-12 * ratio) print "ratio " ratio " but Ez/Eh = " ez / eh
      want = (ratio >= 0.30 && ratio <= 0.60) ? "pass" : "fail"
      if (verdict != want) print "verdict " verdict " for ratio " ratio
      if (!(ratio > 0)) print "ratio " ratio " is not positive"
      if (bad != "") print bad
    }' "$csv")
  if [ -n "$check" ]; then echo "grid $name: $check"; status=1; else echo "grid $name: Ez $ez lx, Eh $eh lx, ratio $ratio, $verdict"; fi
done
exit $status
