#!/usr/bin/env bash
# Installs the Debian packages MeshBridge needs. Idempotent: installs only what is missing.
# Usage: scripts/install_deps.sh [extra-package ...]
set -euo pipefail

packages=(build-essential cmake pkg-config libopenmesh-dev libgtest-dev googletest qtbase5-dev libcli11-dev nlohmann-json3-dev
  # the Python module and its tests (python/, tests/python/): pybind11, numpy, Dask, Open3D, pytest
  python3-dev pybind11-dev python3-numpy python3-pytest python3-dask python3-distributed
  python3-open3d python3-venv python3-pip python3-setuptools python3-wheel
  prusa-slicer admesh jq  # the slicer judge (tests/printer)
  clang-format  # the test command checks every C++ file's formatting (.clang-format)
  lib3mf-dev  # 3MF read and write (core)
  libpugixml-dev libzip-dev libdeflate-dev  # 3MF meshes read apart from lib3mf (core, faster)
  libisal-dev  # 3MF model parts inflated in chunks as they are read (core, optional, faster)
  libcgal-dev libgmp-dev libmpfr-dev  # hole filling (core: CGAL PMP triangulate_hole, header-only)
  "$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
