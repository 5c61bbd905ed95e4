#!/usr/bin/env bash
# usage: run_case.sh EXPECTED_EXIT EXPECTED_SUBSTRING CANDELA CASE.toml [ARGS...]
# Runs `candela run CASE.toml --out DIR ARGS...` into a fresh DIR and checks the exit code and
# that stdout+stderr (and summary.json after a good run) contain the substring. On success all outputs must exist; on failure the
# output folder must not exist at all (a failed run writes nothing) and stderr must be one line.
set -u
want_code=$1; want_text=$2; exe=$3; case_file=$4; shift 4
tmp=$(mktemp -d)
out_dir="$tmp/out"
"$exe" run "$case_file" --out "$out_dir" --quiet "$@" </dev/null >"$tmp/stdout" 2>"$tmp/stderr"
code=$?
status=0
if [ "$code" != "$want_code" ]; then echo "exit code $code, expected $want_code"; status=1; fi
if ! grep -qF -- "$want_text" "$tmp/stdout" "$tmp/stderr" $( [ -f "$out_dir/summary.json" ] && echo "$out_dir/summary.json") $( [ -f "$out_dir/report.html" ] && echo "$out_dir/report.html"); then echo "output lacks: $want_text"; status=1; fi
if [ "$want_code" = 0 ]; then
  for f in summary.csv summary.json report.html; do
    [ -s "$out_dir/$f" ] || { echo "missing output $f"; status=1; }
  done
  ls "$out_dir"/*.tmp* >/dev/null 2>&1 && { echo "temporary files left behind"; status=1; }
else
  [ -e "$out_dir" ] && { echo "failed run wrote into $out_dir:"; ls -la "$out_dir"; status=1; }
  [ "$(wc -l <"$tmp/stderr")" = 1 ] || { echo "stderr is not one line"; status=1; }
fi
if [ $status != 0 ]; then echo "--- stdout"; head -20 "$tmp/stdout"; echo "--- stderr"; cat "$tmp/stderr"; fi
rm -rf "$tmp"
exit $status
