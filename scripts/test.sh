#!/usr/bin/env bash
# Quick start, command 2: build and run every test (unit tests, command-line tests, quick validation).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
