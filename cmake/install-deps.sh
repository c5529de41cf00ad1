#!/usr/bin/env bash
# Installs the Debian 12 packages ejecta builds against, only those missing.
# Runs apt-get directly as root, through sudo otherwise. See docs/dependencies.md.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libhdf5-dev nlohmann-json3-dev libtomlplusplus-dev libcli11-dev libgtest-dev libbenchmark-dev
  libeigen3-dev libtbb-dev libopenvdb-dev libboost-iostreams-dev libopenvdb-tools
  libembree-dev libosmesa6-dev libpng-dev libfreetype-dev fonts-dejavu-core hdf5-tools
  libopenmpi-dev openmpi-bin
  python3-matplotlib python3-numpy
  python3-h5py python3-openvdb python3-pytest python3-venv python3-pip python3-setuptools
)
# `install-deps.sh fuzz`: clang and its sanitizer and libFuzzer runtimes as well (make fuzz).
if [ "${1:-}" = "fuzz" ]; then packages+=(clang libclang-rt-14-dev); fi
# `install-deps.sh paraview`: ParaView's pvbatch and Python modules with a virtual X server, for
# the test that opens a run's series in ParaView itself (make paraview-deps; ~440 MB).
if [ "${1:-}" = "paraview" ]; then packages+=(paraview python3-paraview xvfb xauth); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "ejecta: installing missing Debian packages: ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
