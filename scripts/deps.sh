#!/usr/bin/env bash
# Installs the Debian 12 packages candela builds with, only those missing. Needs root (or sudo).
set -euo pipefail
packages=(g++ cmake make pkg-config libglm-dev libtbb-dev libcli11-dev nlohmann-json3-dev
  libopenexr-dev libgeographiclib-dev libtomlplusplus-dev libpng-dev libeigen3-dev
  libgtest-dev libbenchmark-dev libembree-dev)
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
