#!/usr/bin/env bash
# usage: peak_memory.sh FACTOR CANDELA ARGS...
# The resource estimate against a measured peak: runs `CANDELA ARGS... --max-memory 1K` (refused,
# the message carries the case's estimate "the case about N MiB in all"), then `CANDELA ARGS...`
# under /usr/bin/time for its peak resident set, and checks estimate/peak within [1/FACTOR, FACTOR].
set -u
factor=$1; shift
if [ ! -x /usr/bin/time ]; then echo "no /usr/bin/time (Debian package time): skipped"; exit 77; fi
msg=$("$@" --max-memory 1K 2>&1 >/dev/null)
est=$(echo "$msg" | sed -n 's/.*the case about \([0-9.]*\) \([KMG]\)iB in all.*/\1 \2/p')
[ -n "$est" ] || { echo "no estimate in: $msg"; exit 1; }
peak_kib=$(/usr/bin/time -f "%M" "$@" 2>&1 >/dev/null | tail -1)
awk -v e="$est" -v p="$peak_kib" -v f="$factor" 'BEGIN {
  split(e, a, " "); m = (a[2] == "G") ? 1048576 : (a[2] == "M") ? 1024 : 1;
  est = a[1] * m; ratio = est / p;
  printf "estimate %.0f KiB, measured peak %d KiB, ratio %.2f (allowed 1/%s..%s)\n", est, p, ratio, f, f;
  exit !(ratio <= f && ratio >= 1 / f) }'
