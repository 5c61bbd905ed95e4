#!/usr/bin/env bash
# Strong scaling on this machine (docs/distributed.md): the office demo and the annual demo with
# 1 rank x 1 thread, 1 rank x 2 threads, 2 MPI ranks x 1 thread, and 3 shards + merge; wall time,
# peak memory per process, and whether the result files are the one-process bytes.
#
#   scripts/scaling.sh [--quality Q] [--out DIR] [--case NAME]...
#   (default: the cases' quality, out/scaling, the cases office and office-annual)
#
# Writes DIR/scaling.csv and DIR/scaling.md. Run it on an idle machine: it takes about 4 times
# the demos' run time.
set -euo pipefail
cd "$(dirname "$0")/.."
quality=()
out=out/scaling
cases=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quality) quality=(--quality "$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --case) cases+=("$2"); shift 2 ;;
    *) echo "usage: scripts/scaling.sh [--quality Q] [--out DIR] [--case NAME]..." >&2; exit 2 ;;
  esac
done
exe=$PWD/build/cli/candela
mpirun_cmd=(mpirun --allow-run-as-root --oversubscribe)
mkdir -p "$out"
csv=$out/scaling.csv
echo "case,config,wall_s,peak_rss_mib,speedup,efficiency,identical" >"$csv"

# Wall time (s) and the largest peak RSS (MiB) of the processes of one command, from GNU time
# per process (mpirun's own memory is not the ranks').
timed() {  # log-prefix, command...
  local prefix=$1
  shift
  local start end
  rm -f "$prefix".time.*
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$prefix.err"
  end=$(date +%s.%N)
  wall=$(echo "$end - $start" | bc)
  rss=$(cat "$prefix".time.* 2>/dev/null | sort -n | tail -1)
  rss=$(echo "scale=1; ${rss:-0} / 1024" | bc)
}

same() {  # reference folder, folder: result files byte-identical (summaries aside)
  local f
  for f in $(cd "$1" && ls -A); do
    case "$f" in summary.json | summary.csv | report.html) continue ;; esac
    cmp -s "$1/$f" "$2/$f" || { echo no; return; }
  done
  echo yes
}

[ ${#cases[@]} -gt 0 ] || cases=(office office-annual)
for name in "${cases[@]}"; do
  case_file=cases/$name/case.toml
  d=$out/$name
  rm -rf "$d"
  mkdir -p "$d"
  # /usr/bin/time per process: each writes its own file (%M = peak RSS in KiB).
  t() { echo "/usr/bin/time -f %M -o $d/$1.time.\$\$"; }
  timed "$d/1x1" sh -c "$(t 1x1) $exe run $case_file --out $d/r1x1 -q --threads 1 ${quality[*]}"
  base=$wall
  echo "$name,1 rank x 1 thread,$wall,$rss,1.00,1.00,reference" >>"$csv"
  timed "$d/1x2" sh -c "$(t 1x2) $exe run $case_file --out $d/r1x2 -q --threads 2 ${quality[*]}"
  echo "$name,1 rank x 2 threads,$wall,$rss,$(echo "scale=2; $base / $wall" | bc),$(echo "scale=2; $base / $wall / 2" | bc),$(same "$d/r1x1" "$d/r1x2")" >>"$csv"
  timed "$d/2x1" "${mpirun_cmd[@]}" -n 2 sh -c "$(t 2x1) $exe run $case_file --out $d/r2x1 -q --threads 1 ${quality[*]}"
  echo "$name,2 MPI ranks x 1 thread,$wall,$rss,$(echo "scale=2; $base / $wall" | bc),$(echo "scale=2; $base / $wall / 2" | bc),$(same "$d/r1x1" "$d/r2x1")" >>"$csv"
  # Shards one after the other (as a scheduler with one free core would run them), then merge.
  shard_total=0
  shard_max=0
  for i in 0 1 2; do
    timed "$d/shard$i" sh -c "$(t shard$i) $exe run $case_file --shard $i/3 --out $d/part_$i -q --threads 1 ${quality[*]}"
    shard_total=$(echo "$shard_total + $wall" | bc)
    shard_max=$(echo "if ($wall > $shard_max) $wall else $shard_max" | bc)
    echo "$name,shard $i/3 x 1 thread,$wall,$rss,,," >>"$csv"
  done
  timed "$d/merge" sh -c "$(t merge) $exe merge $d/part_0 $d/part_1 $d/part_2 --out $d/merged -q --threads 1"
  echo "$name,merge of 3 parts x 1 thread,$wall,$rss,,,$(same "$d/r1x1" "$d/merged")" >>"$csv"
  parts=$(du -cb "$d"/part_*/fills.bin | tail -1 | cut -f1)
  echo "$name,3 shards: the longest + merge,$(echo "$shard_max + $wall" | bc),,$(echo "scale=2; $base / ($shard_max + $wall)" | bc),$(echo "scale=2; $base / ($shard_max + $wall) / 3" | bc),parts $((parts / 1024)) KiB" >>"$csv"
done

{
  echo "| case | configuration | wall (s) | peak RSS a process (MiB) | speed-up | efficiency | same bytes |"
  echo "|---|---|---:|---:|---:|---:|---|"
  tail -n +2 "$csv" | awk -F, '{printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7}'
} >"$out/scaling.md"
cat "$out/scaling.md"
