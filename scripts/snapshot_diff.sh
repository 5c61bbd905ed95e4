#!/usr/bin/env bash
# Compares two behaviour snapshots (scripts/snapshot.sh) file by file. Fields that record wall
# time, start time or thread counts are masked; everything else must match to the byte.
#
#   scripts/snapshot_diff.sh BEFORE_DIR AFTER_DIR
set -uo pipefail
a="$1"
b="$2"
mask() {
  # Run times, start times, rays/s and thread counts differ between any two runs.
  sed -E -e 's/"(run_time_s|started_at|coefficients_time_s|product_time_s|rays_per_s|threads|time_s)": [^,}]*/"\1": X/g' \
    -e 's/[0-9]+(\.[0-9]+)? s\b/T s/g' -e 's/[0-9]{4}-[0-9]{2}-[0-9]{2} [0-9]{2}:[0-9]{2}/DATE/g' "$1"
}
status=0
while IFS= read -r f; do
  rel="${f#"$a"/}"
  if [[ ! -e "$b/$rel" ]]; then
    echo "missing in after: $rel"
    status=1
  elif ! cmp -s "$f" "$b/$rel"; then
    case "$rel" in
      *.json | *.csv | *.html | *.txt)
        if ! diff -q <(mask "$f") <(mask "$b/$rel") >/dev/null; then
          echo "differs: $rel"
          status=1
        fi
        ;;
      *)
        echo "differs: $rel"
        status=1
        ;;
    esac
  fi
done < <(find "$a" -type f | sort)
while IFS= read -r f; do
  rel="${f#"$b"/}"
  [[ -e "$a/$rel" ]] || { echo "new in after: $rel"; status=1; }
done < <(find "$b" -type f | sort)
exit $status
