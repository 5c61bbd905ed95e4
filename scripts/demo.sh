#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build in Release, run the demo case.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
scripts/build.sh
echo "== candela points: illuminance under a 1.2 m x 0.6 m panel in a small room (cases/small-room)" >&2
build/cli/candela points cases/small-room/room.rad --points cases/small-room/sensors.pts
