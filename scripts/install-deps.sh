#!/usr/bin/env bash
# Installs the Debian 12 packages rockfdem builds and runs with, if any is
# missing. Idempotent and silent when everything is already there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libdeal.ii-dev libgmsh-dev libeigen3-dev libvtk9-dev
  libboost-program-options-dev libgtest-dev libtomlplusplus-dev nlohmann-json3-dev
  libnlopt-cxx-dev libopenmpi-dev openmpi-bin
  xvfb xauth clang-format
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo=sudo
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
