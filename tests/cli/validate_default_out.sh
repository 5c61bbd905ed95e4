#!/usr/bin/env bash
# usage: validate_default_out.sh CANDELA
# `candela validate` (every case, default quality) run in an empty folder passes, and writes
# validation.csv and validation.html into validation-results/ there, and nothing else.
set -u
candela=$1
dir=$(mktemp -d)
err=$(mktemp)
trap 'rm -rf "$dir" "$err"' EXIT
cd "$dir" || exit 1
out=$("$candela" validate 2>"$err")
code=$?
status=0
[ "$code" = 0 ] || { echo "exit code $code, expected 0"; status=1; }
grep -qF "0 failed" <<<"$out" || { echo "output lacks: 0 failed"; status=1; }
for f in validation.csv validation.html; do
  [ -s "validation-results/$f" ] || { echo "validation-results/$f missing"; status=1; }
done
extra=$(ls -A | grep -vx validation-results)
[ -z "$extra" ] || { echo "written outside validation-results/: $extra"; status=1; }
if [ $status != 0 ]; then echo "--- stdout"; head -40 <<<"$out"; echo "--- stderr"; cat "$err"; fi
exit $status
