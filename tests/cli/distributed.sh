#!/usr/bin/env bash
# usage: distributed.sh MODE N CANDELA CASE.toml REFERENCE [ARGS...]
#   reference  candela run CASE into REFERENCE, one process on 2 threads (the tests below compare
#              with it; CTest runs it once per case as a fixture)
#   mpi N      candela run under `mpirun -n N` (1 thread a rank) against REFERENCE
#   shards N   candela run --shard i/N for every i, then candela merge, against REFERENCE
#   points N   candela points --case CASE under mpirun -n N against one process (the points of
#              REFERENCE's workplane.csv, on stdin)
#   render N   candela render CASE --view (its first view) under mpirun -n N against one process
#   refused N  mpirun -n N candela ARGS (a command that does not share its work): exit 2, one message
#   kill N     mpirun -n N; rank 1 is killed (SIGKILL) while tracing: the run must fail, promptly,
#              and write nothing
# Result files must be byte-identical; summary.json, summary.csv and report.html may differ only
# in the fields that record run time, threads and ranks (docs/distributed.md).
set -u
mode=$1 n=$2 exe=$3 case_file=$4 reference=$5
shift 5
mpirun_cmd=(mpirun -n "$n" --allow-run-as-root --oversubscribe)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A summary or report with the fields of time, threads and ranks blanked out.
normalise() {
  sed -E -e 's/("(run_time_s|coefficients_time_s|product_time_s|started_at|threads|ranks|sky vectors time|rays for the coefficients)": )[^,]*(,?)$/\1X\3/' \
    -e 's/(threads|ranks|sky vectors time|rays for the coefficients)=[^;"]*/\1=X/g' \
    -e 's/^([^,]*,[^,]*,(.*,)?)[0-9.]+(,"quality=)/\1X\3/' -e 's/,[0-9.e+-]+,[0-9.e+-]+$/,X,X/' "$1"
}

compare_folders() {  # one-process result, distributed result
  local a=$1 b=$2
  [ -d "$a" ] || fail "no reference folder $a"
  [ -d "$b" ] || fail "no result folder $b"
  diff <(cd "$a" && ls -A | sort) <(cd "$b" && ls -A | sort) || fail "the folders hold different files"
  local f
  for f in $(cd "$a" && ls -A); do
    case "$f" in
      summary.json | summary.csv) diff <(normalise "$a/$f") <(normalise "$b/$f") || fail "$f differs beyond time, threads and ranks" ;;
      report.html) ;;  # carries the same settings table as summary.json, and the run's times
      *) cmp "$a/$f" "$b/$f" || fail "$f differs" ;;
    esac
  done
}

case "$mode" in
  reference)
    rm -rf "$reference"
    "$exe" run "$case_file" --out "$reference" --quiet --threads 2 "$@" </dev/null || fail "one-process run failed"
    ;;
  mpi)
    "${mpirun_cmd[@]}" "$exe" run "$case_file" --out "$tmp/mpi" --quiet --threads 1 "$@" </dev/null ||
      fail "mpirun -n $n failed"
    compare_folders "$reference" "$tmp/mpi"
    grep -q "\"ranks\": \"$n MPI ranks\"" "$tmp/mpi/summary.json" || fail "summary.json does not name the ranks"
    ;;
  shards)
    parts=()
    for ((i = 0; i < n; i++)); do
      "$exe" run "$case_file" --shard "$i/$n" --out "$tmp/part_$i" --quiet --threads 1 "$@" </dev/null ||
        fail "shard $i/$n failed"
      parts+=("$tmp/part_$i")
    done
    # An incomplete set is refused with one line naming the missing shard, and writes nothing.
    "$exe" merge "${parts[@]:1}" --out "$tmp/bad" --quiet 2>"$tmp/err" && fail "merge accepted an incomplete set"
    grep -q "shard 0/$n missing" "$tmp/err" || { cat "$tmp/err"; fail "merge did not name the missing shard"; }
    [ "$(wc -l <"$tmp/err")" = 1 ] || fail "merge's error is not one line"
    [ -e "$tmp/bad" ] && fail "a refused merge wrote $tmp/bad"
    "$exe" merge "${parts[@]}" --out "$tmp/merged" --quiet </dev/null || fail "merge failed"
    compare_folders "$reference" "$tmp/merged"
    ;;
  points)
    # The case's workplane points as a points list (x y z dx dy dz), from the one-process run.
    tail -n +2 "$reference/workplane.csv" | awk -F, '{print $1, $2, $3, $4, $5, $6}' >"$tmp/points.txt"
    "$exe" points --case "$case_file" --quiet --error --threads 2 "$@" <"$tmp/points.txt" >"$tmp/one.csv" ||
      fail "one-process points failed"
    "${mpirun_cmd[@]}" "$exe" points --case "$case_file" --quiet --error --threads 1 "$@" <"$tmp/points.txt" \
      >"$tmp/mpi.csv" || fail "mpirun points failed"
    [ "$(wc -l <"$tmp/one.csv")" -gt 10 ] || fail "too few points"
    cmp "$tmp/one.csv" "$tmp/mpi.csv" || fail "points under mpirun differ"
    ;;
  render)
    # One view of the case (its first [[view]]); the images must be the one-process bytes.
    view=$(sed -n 's/^name *= *"\(.*\)"/\1/p' <(sed -n '/^\[\[view\]\]/,/^$/p' "$case_file") | head -1)
    [ -n "$view" ] || fail "the case has no [[view]]"
    "$exe" render "$case_file" --view "$view" --out "$tmp/one" --quiet --threads 2 "$@" </dev/null ||
      fail "one-process render failed"
    "${mpirun_cmd[@]}" "$exe" render "$case_file" --view "$view" --out "$tmp/mpi" --quiet --threads 1 "$@" \
      </dev/null || fail "mpirun render failed"
    [ -n "$(ls -A "$tmp/one")" ] || fail "render wrote nothing"
    compare_folders "$tmp/one" "$tmp/mpi"
    ;;
  refused)
    # A command that does not share its work (ARGS: the command and its options): exit 2, and
    # candela's message once (rank 0's; mpirun adds its own banner).
    "${mpirun_cmd[@]}" "$exe" "$@" </dev/null >"$tmp/out" 2>"$tmp/err"
    code=$?
    [ "$code" = 2 ] || fail "exit code $code, expected 2"
    [ "$(grep -c "candela $1 is one process" "$tmp/err")" = 1 ] || { cat "$tmp/err"; fail "the refusal is not said once"; }
    [ -s "$tmp/out" ] && fail "stdout not empty"
    ;;
  kill)
    "${mpirun_cmd[@]}" "$exe" run "$case_file" --out "$tmp/out" --quiet --threads 1 "$@" </dev/null \
      >"$tmp/log" 2>&1 &
    job=$!
    victim=""
    for ((k = 0; k < 300; k++)); do  # rank 1's process, once it has started
      [ -n "$victim" ] && break
      sleep 0.1
      for p in $(pgrep -f -- "$case_file"); do
        [ "$(readlink -f "/proc/$p/exe")" = "$(readlink -f "$exe")" ] || continue
        tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=1" && victim=$p
      done
    done
    [ -n "$victim" ] || fail "rank 1 never started"
    sleep 2
    kill -9 "$victim"
    start=$(date +%s)
    # The job must end by itself, promptly: give it 60 s, then call it a hang.
    for ((k = 0; k < 600; k++)); do kill -0 "$job" 2>/dev/null || break; sleep 0.1; done
    kill -0 "$job" 2>/dev/null && { kill -9 "$job"; fail "the job did not end within 60 s of a rank's death"; }
    wait "$job"
    code=$?
    echo "mpirun exited with $code, $(($(date +%s) - start)) s after rank 1 was killed"
    [ "$code" != 0 ] || fail "the run succeeded although a rank died"
    [ -e "$tmp/out" ] && fail "a failed run wrote $tmp/out"
    left=$(ls -A "$tmp" | grep -vx log)
    [ -z "$left" ] || fail "a failed run left temporaries: $left"
    ;;
  *) fail "unknown mode $mode" ;;
esac
echo "ok"
