#!/usr/bin/env bash
# Installs the Debian packages mpmcut needs, only those that are missing.
# Nothing is downloaded at build time; everything comes from Debian's archive.
set -euo pipefail
packages=(
  g++ cmake ninja-build make pkg-config
  libeigen3-dev libtomlplusplus-dev libcli11-dev libfmt-dev libpng-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libomp-dev
  libnlopt-dev openmpi-bin libopenmpi-dev
  python3-matplotlib python3-meshio python3-numpy
  pybind11-dev python3-pytest
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
