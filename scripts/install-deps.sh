#!/usr/bin/env bash
# Installs the Debian packages brdftab needs, if missing. Idempotent; silent when
# everything is already there.
set -euo pipefail
packages=(cmake g++ make ccache git libeigen3-dev libboost-dev libboost-math-dev libhdf5-dev doctest-dev libcli11-dev
          nlohmann-json3-dev libbenchmark-dev gnuplot-nox pybind11-dev python3-dev python3-numpy python3-pytest
          python3-h5py python3-xarray python3-h5netcdf python3-netcdf4 netcdf-bin glslang-tools libopenexr-dev
          libvulkan-dev mesa-vulkan-drivers
          pkg-config openmpi-bin libopenmpi-dev python3-venv python3-pip python3-setuptools python3-wheel)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >&2
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
