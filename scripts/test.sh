#!/usr/bin/env bash
# Quick start, command 2: build and run every test (unit, command-line, validation; then sanitizers and fuzzing).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
# Unit tests under AddressSanitizer and UndefinedBehaviorSanitizer, and a bounded fuzz pass over
# every reader (docs/reliability.md); CANDELA_SKIP_FUZZ=1 skips it locally, never on CI.
scripts/fuzz.sh
