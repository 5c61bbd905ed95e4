#!/usr/bin/env bash
# Screenshot an HTML report in headless Chromium for the manual visual check (docs/reports.md).
#
#   scripts/screenshot_report.sh [REPORT.html] [OUT.png] [WIDTHxHEIGHT]
#
# Without REPORT.html, writes the reports tests' sample report (build dir: $BUILD_DIR, default
# build) and shoots that. Needs Debian's chromium (apt-get install chromium).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
report="${1:-}"
out="${2:-/tmp/candela_report.png}"
size="${3:-1200x1600}"
if [[ -z "$report" ]]; then
  build="${BUILD_DIR:-$here/build}"
  report="/tmp/candela_sample_report.html"
  cmake --build "$build" --target reports_test -j2 >/dev/null
  CANDELA_SAMPLE_REPORT="$report" "$build/tests/reports_test" --gtest_filter=HtmlReport.WritesSampleForScreenshot >/dev/null
fi
[[ -f "$report" ]] || { echo "no report at $report" >&2; exit 2; }
browser="$(command -v chromium || command -v chromium-browser || true)"
[[ -n "$browser" ]] || { echo "chromium not found (apt-get install chromium)" >&2; exit 2; }
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
# No network at all: the report must render from the file alone.
"$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --user-data-dir="$profile" --hide-scrollbars --window-size="${size/x/,}" \
  --screenshot="$out" "file://$(realpath "$report")" >/dev/null 2>&1
echo "$out"
