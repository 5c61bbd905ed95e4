#!/usr/bin/env bash
# Sanitizers and fuzzing (docs/reliability.md, "Fuzzing and sanitizers"). Run by .ci/run after
# scripts/test.sh. One build folder, build-san (clang 14, AddressSanitizer +
# UndefinedBehaviorSanitizer, every finding fatal, libFuzzer's coverage in the readers):
#   tests: the unit-test binaries and the replay of the kept fuzz inputs run under the sanitizers;
#   fuzz:  each reader's libFuzzer target runs for FUZZ_SECONDS, seeded with the project's fixtures.
# Any crash, sanitizer report, uncaught exception other than InputError, input slower than 10 s
# or allocation over 1 GB fails the script. A failing input is copied to tests/fuzz/<reader>/
# (commit it: the normal build's CTest fuzz_replay.<reader> replays it from then on).
#
#   scripts/fuzz.sh [tests|fuzz|all]      (default all)
# Environment: FUZZ_SECONDS (per reader, default 20), FUZZ_JOBS (readers at once, default 2),
# FUZZ_READERS (default every reader), CANDELA_SKIP_FUZZ=1 skips everything (ignored when
# CI=true: CI always runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
stage="${1:-all}"
if [ "${CANDELA_SKIP_FUZZ:-0}" = "1" ]; then
  if [ "${CI:-}" = "true" ]; then
    echo "fuzz.sh: CANDELA_SKIP_FUZZ is ignored on CI" >&2
  else
    echo "fuzz.sh: skipped (CANDELA_SKIP_FUZZ=1)" >&2
    exit 0
  fi
fi
seconds="${FUZZ_SECONDS:-20}"
jobs="${FUZZ_JOBS:-2}"
readers=(${FUZZ_READERS:-rad_reader obj_reader sensor_points ies eulumdat epw case_file part picture data_file font generators bsdf_xml})
# Longest first (study_test, then engine_test's shards), so that no long job starts last.
unit_tests=(study_test engine_test photometry_test base_test metrics_test reports_test)
# The longest binaries run as gtest shards (GTEST_TOTAL_SHARDS), so that the two cores stay busy
# to the end instead of waiting for engine_test alone.
declare -A gtest_shards=([engine_test]=3 [photometry_test]=2)

# Unit tests left out under the sanitizers (docs/reliability.md says why): statistical checks
# that trace millions of rays, 30 s to 5 min each instrumented, which the faster tests of the same
# code paths cover for memory errors and undefined behaviour.
declare -A gtest_exclude=(
  [engine_test]="ErrorBars.IrradianceCache*:ErrorBars.TargetErrorUnderTheCache*:ErrorBars.SmallSkyOpenings*:DaylightCoefficientsVsPointInTime.*:EmbreeAccelerator.MatchesBruteForceOn*"
)

scripts/deps.sh --fuzz
sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -O1"
# One folder for both stages (clang 14 compiles candela about 30 % faster than g++ at these flags,
# and each source once instead of twice): the readers' objects carry libFuzzer's coverage
# (CMakeLists.txt, CANDELA_FUZZ), which the unit tests, linked without libFuzzer, leave unused.
build=build-san
fuzz_build=$build
cmake -S . -B $build -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 -DCMAKE_BUILD_TYPE=None \
  -DCMAKE_CXX_FLAGS="$sanitize -gline-tables-only" -DCANDELA_FUZZ=ON -DCANDELA_BUILD_BENCH=OFF >/dev/null
targets=()
[ "$stage" != fuzz ] && targets+=("${unit_tests[@]}" $(for r in "${readers[@]}"; do echo "fuzz_replay_$r"; done))
[ "$stage" != tests ] && targets+=($(for r in "${readers[@]}"; do echo "fuzz_$r"; done))
t0=$SECONDS
cmake --build $build -j2 --target "${targets[@]}"
echo "== sanitizer build ($build): $((SECONDS - t0)) s" >&2

# halt_on_error: the first report ends the process with a failure (UBSan too: the code is built
# with -fno-sanitize-recover=all). Leak checking stays on.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0

if [ "$stage" != fuzz ]; then
  t0=$SECONDS
  logs="$build/sanitizer-logs"
  mkdir -p "$logs"
  run_unit() {  # binary[:shard/shards] -> log; prints one line with the result and the time
    local t=$SECONDS bin="${1%%:*}" shard="" name="$1"
    [[ "$1" == *:* ]] && shard="${1#*:}" && name="$bin.shard${shard%/*}"
    local filter="${gtest_exclude[$bin]:-}"
    local args=()
    [ -n "$filter" ] && args+=("--gtest_filter=-$filter")
    if [ -n "$shard" ]; then
      export GTEST_SHARD_INDEX="${shard%/*}" GTEST_TOTAL_SHARDS="${shard#*/}"
    fi
    if "$build/tests/$bin" "${args[@]}" >"$logs/$name.log" 2>&1; then
      echo "   $name: ok ($((SECONDS - t)) s)"
    else
      echo "   $name: FAILED ($((SECONDS - t)) s), log: $logs/$name.log"
      tail -n 40 "$logs/$name.log"
      return 1
    fi
  }
  export -f run_unit
  export build logs
  declare -p gtest_exclude >"$logs/exclude.sh"
  echo "== unit tests under ASan+UBSan" >&2
  jobs_list=()
  for u in "${unit_tests[@]}"; do
    n="${gtest_shards[$u]:-1}"
    if [ "$n" -gt 1 ]; then
      for ((k = 0; k < n; k++)); do jobs_list+=("$u:$k/$n"); done
    else
      jobs_list+=("$u")
    fi
  done
  printf '%s\n' "${jobs_list[@]}" |
    xargs -P2 -I{} bash -c 'source "$logs/exclude.sh"; run_unit {}' || status=1
  echo "== sanitizer tests: $((SECONDS - t0)) s" >&2
  # The kept fuzz inputs under the sanitizers (known open findings left out, as in CTest).
  t0=$SECONDS
  ctest --test-dir $build -L fuzz --output-on-failure -j2 >"$logs/fuzz_replay.log" 2>&1 ||
    { echo "   fuzz_replay: FAILED, log: $logs/fuzz_replay.log"; tail -n 30 "$logs/fuzz_replay.log"; status=1; }
  echo "== fuzz replay under the sanitizers: $((SECONDS - t0)) s" >&2
fi

# Seeds for each reader: the project's fixtures (with the third-party files of tests/data/reference)
# and demo cases, and the peer suite when CANDELA_PEER_SUITE names it, copied at run time into
# build-san (never into the repository), plus the
# inputs kept in tests/fuzz/<reader>/.
seed_pattern() {
  case "$1" in
    rad_reader) echo '*.rad' ;; obj_reader) echo '*.[oO][bB][jJ]' ;; sensor_points) echo '*.pts' ;; ies) echo '*.[iI][eE][sS]' ;;
    eulumdat) echo '*.[lL][dD][tT]' ;; epw) echo '*.epw' ;; case_file) echo '*.toml' ;;
    part) echo '*.part' ;;  # none in the fixtures: its seeds are tests/fuzz/part/
    picture) echo '*.hdr' ;; data_file) echo '*.dat' ;; generators) echo '*.rad' ;;
    font) echo '*.fnt' ;;  # none in the fixtures: its seeds are tests/fuzz/font/
    bsdf_xml) echo '*.xml' ;;
  esac
}
fuzz_one() {  # reader -> 0 when the pass found nothing
  local r="$1" dir="$fuzz_build/fuzz/$1"
  rm -rf "$dir/seeds" "$dir/artifacts"
  mkdir -p "$dir/seeds" "$dir/corpus" "$dir/artifacts"
  local n=0 f
  while IFS= read -r -d '' f; do
    # Seeds are cut at 64 KB (libFuzzer's -max_len below): an EPW year is 1.5 MB.
    head -c 65536 "$f" >"$dir/seeds/$n.seed"
    n=$((n + 1))
  done < <(find tests/data cases ${CANDELA_PEER_SUITE:+"$CANDELA_PEER_SUITE"} -type f -name "$(seed_pattern "$r")" -print0 2>/dev/null)
  # Kept inputs of this reader, except the known open findings (tests/fuzz/known_findings.txt).
  local kept=() known=0
  for f in tests/fuzz/"$r"/*; do
    [ -f "$f" ] || continue
    if awk -v p="${f#tests/fuzz/}" '$1 == p { found = 1 } END { exit !found }' tests/fuzz/known_findings.txt; then
      known=$((known + 1))
    else
      kept+=("$f")
    fi
  done
  local t=$SECONDS
  # -timeout: an input slower than 10 s is a hang; -rss_limit_mb / -malloc_limit_mb: more than
  # 1 GB resident or in one allocation is a finding.
  [ ${#kept[@]} = 0 ] || cp "${kept[@]}" "$dir/seeds/"
  if "$fuzz_build/tests/fuzz/fuzz_$r" "$dir/corpus" "$dir/seeds" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=1024 -malloc_limit_mb=1024 \
      -max_len=65536 -print_final_stats=1 -artifact_prefix="$dir/artifacts/" \
      >"$dir/fuzz.log" 2>&1; then
    echo "   $r: ok, $n seeds, $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$dir/fuzz.log" |
      grep -o '[0-9]*$') runs ($((SECONDS - t)) s)"
    return 0
  fi
  if [ $known -gt 0 ] && [ "${FUZZ_STRICT:-0}" != 1 ]; then
    echo "   $r: KNOWN: a finding in a reader with $known open findings (tests/fuzz/known_findings.txt);"
    echo "      not failing the pass (FUZZ_STRICT=1 makes it fail) ($((SECONDS - t)) s), log: $dir/fuzz.log"
  else
    echo "   $r: FINDING ($((SECONDS - t)) s), log: $dir/fuzz.log"
  fi
  grep -E 'ERROR|SUMMARY|==[0-9]+==|terminate|what\(\)|Test unit written' "$dir/fuzz.log" | head -n 20
  mkdir -p "tests/fuzz/$r"
  for f in "$dir"/artifacts/*; do
    [ -f "$f" ] || continue
    cp "$f" "tests/fuzz/$r/"
    echo "   kept as tests/fuzz/$r/$(basename "$f") (commit it); reproduce:"
    echo "     $fuzz_build/tests/fuzz/fuzz_$r tests/fuzz/$r/$(basename "$f")"
  done
  [ $known -gt 0 ] && [ "${FUZZ_STRICT:-0}" != 1 ] && return 0
  return 1
}

if [ "$stage" != tests ]; then
  t0=$SECONDS
  export -f fuzz_one seed_pattern
  export seconds fuzz_build
  echo "== fuzz pass: ${#readers[@]} readers x ${seconds} s, $jobs at a time" >&2
  printf '%s\n' "${readers[@]}" | xargs -P"$jobs" -I{} bash -c 'fuzz_one {}' || status=1
  echo "== fuzz pass: $((SECONDS - t0)) s" >&2
fi

[ $status = 0 ] && echo "fuzz.sh: no findings" >&2 || echo "fuzz.sh: FAILED (see above)" >&2
exit $status
