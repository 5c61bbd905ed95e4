#!/usr/bin/env bash
# Installs the Debian 12 packages candela builds with, only those missing. Needs root (or sudo).
#
#   scripts/deps.sh           the normal build (g++)
#   scripts/deps.sh --fuzz    also clang 14 and its runtimes (libFuzzer, ASan, UBSan) for
#                             scripts/fuzz.sh; the normal build never needs them
set -euo pipefail
packages=(g++ cmake make pkg-config libglm-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  libopenexr-dev libgeographiclib-dev libtomlplusplus-dev libpng-dev libeigen3-dev
  libgtest-dev libbenchmark-dev libembree-dev libexpat1-dev libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3-numpy python3-pytest)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
