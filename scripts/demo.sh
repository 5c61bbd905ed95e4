#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build in Release, run the demo case.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
echo "== candela run: the open-plan office demo (cases/office): grids, metrics and an HTML report" >&2
build/cli/candela run cases/office/case.toml --out out/office
echo "== report: out/office/report.html (summary: out/office/summary.csv)" >&2
