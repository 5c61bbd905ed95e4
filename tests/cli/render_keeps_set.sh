#!/usr/bin/env bash
# usage: render_keeps_set.sh CANDELA CASE VIEW
# A render whose third picture cannot be replaced (a folder stands at its name) exits 2 with one
# line and leaves the first two pictures of the previous render byte for byte: the three are one
# set, never a mix of old and new (docs/reliability.md).
set -u
exe=$1; case_file=$2; view=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" render "$case_file" --view "$view" --out "$tmp/out" --quality draft --threads 1 >/dev/null 2>&1 || { echo "first render failed"; exit 1; }
sum_before=$(cat "$tmp/out/$view.exr" "$tmp/out/$view.png" | md5sum)
rm "$tmp/out/${view}_preview.png" && mkdir "$tmp/out/${view}_preview.png" && touch "$tmp/out/${view}_preview.png/keep"
"$exe" render "$case_file" --view "$view" --out "$tmp/out" --quality draft --threads 1 --seed 7 >"$tmp/stdout" 2>"$tmp/stderr"
code=$?
status=0
[ "$code" = 2 ] || { echo "exit code $code, expected 2"; status=1; }
[ "$(wc -l <"$tmp/stderr")" = 1 ] || { echo "stderr is not one line:"; cat "$tmp/stderr"; status=1; }
grep -qF "exists and is not a file; the pictures were not replaced" "$tmp/stderr" || { echo "message:"; cat "$tmp/stderr"; status=1; }
[ "$(cat "$tmp/out/$view.exr" "$tmp/out/$view.png" | md5sum)" = "$sum_before" ] || { echo "the previous pictures were replaced"; status=1; }
ls -a "$tmp/out" | grep -q "^\.$view\." && { echo "temporary folder left behind"; status=1; }
exit $status
