#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds (once) the real pymeshlab module inside the sid root of scripts/setup_sid_root.sh, against
# the MeshLab 2025.07 Debian sid ships, and prints where it is inside the root (the folder to put
# on PYTHONPATH) as its last line.
#
# PyMeshLab is not in Debian and this machine reaches no Python package index; on a machine with
# internet access `pip install pymeshlab==2025.7.post1` gives the same module (float64 arrays, 14
# more plugins). Here its sources (PyMeshLab-2025.7.post1-src.tar.gz, GPL-3.0, never copied into
# this repository) are unpacked into the root at build time and only its bindings are compiled
# (tests/meshlab2025/pymeshlab/CMakeLists.txt: about 140 s on 2 cores). The result,
# ROOT/opt/pymeshlab/pymeshlab/, is reused while the tarball, that CMakeLists, MeshLabSDK.cmake,
# this script's recipe and the installed meshlab package stay the same (a few ms).
#
# Usage: scripts/build_pymeshlab.sh ROOT
# Environment: MESHBRIDGE_THIRD_PARTY (folder holding the tarball; default ../shared/third_party
#              beside the repository), MESHBRIDGE_JOBS (parallel jobs, default nproc).
set -euo pipefail

die() { echo "build_pymeshlab: ERROR: $*" >&2; exit 1; }
log() { echo "build_pymeshlab: $*" >&2; }
[ $# -eq 1 ] || die "usage: $0 ROOT"
root=$(cd "$1" && pwd) || die "no root $1"
[ -s "$root/.meshbridge/sdk-dir" ] || die "$root is not a finished sid root (run scripts/setup_sid_root.sh)"
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
recipe=1
version=2025.7.post1
sha256=313087c0508c1355d6da2cda4d97f011b7b64c04cc07e013f57aac4f57e584be
third_party=${MESHBRIDGE_THIRD_PARTY:-$repo/../shared/third_party}
tarball="$third_party/PyMeshLab-$version-src.tar.gz"
[ -f "$tarball" ] || die "no $tarball: PyMeshLab $version's sources (set MESHBRIDGE_THIRD_PARTY to \
the folder holding it; elsewhere: git clone --branch v$version https://github.com/cnr-isti-vclab/PyMeshLab \
and tar it as PyMeshLab-$version-src.tar.gz with a top folder PyMeshLab-$version)"

prefix=/opt/pymeshlab            # inside the root
cmakelists="$repo/tests/meshlab2025/pymeshlab/CMakeLists.txt"
key=$( { echo "recipe $recipe"; sha256sum "$tarball" | cut -d' ' -f1; sha256sum "$cmakelists" \
  "$repo/plugin/cmake/MeshLabSDK.cmake" | cut -d' ' -f1; cat "$root/.meshbridge/meshlab-version"; } \
  | sha256sum | cut -d' ' -f1)

# One build at a time per root (in_sid_root.sh takes the root's own lock for the build itself).
exec 8>"$root.pymeshlab.lock"
flock 8
if [ "$(cat "$root$prefix/.meshbridge-key" 2>/dev/null)" = "$key" ] && [ -d "$root$prefix/pymeshlab" ]; then
  log "pymeshlab $version ready (cached): $root$prefix/pymeshlab"
  echo "$prefix"
  exit 0
fi

actual=$(sha256sum "$tarball" | cut -d' ' -f1)
[ "$actual" = "$sha256" ] || die "$tarball has sha256 $actual, expected $sha256"
log "building pymeshlab $version in $root (about 140 s on 2 cores)"
t0=$(date +%s)
rm -rf "$root$prefix" "$root/opt/pymeshlab-src" "$root/opt/pymeshlab-build"
mkdir -p "$root/opt/pymeshlab-src"
tar -xzf "$tarball" -C "$root/opt/pymeshlab-src"
src="/opt/pymeshlab-src/PyMeshLab-$version"
[ -f "$root$src/src/pymeshlab/main.cpp" ] || die "the tarball has no PyMeshLab-$version/src/pymeshlab/main.cpp"
sdk=$(cat "$root/.meshbridge/sdk-dir")
MESHBRIDGE_JOBS=${MESHBRIDGE_JOBS:-$(nproc 2>/dev/null || echo 2)} \
  bash "$repo/scripts/in_sid_root.sh" "$root" /bin/sh -c '
  set -e
  cmake -S "$1" -B /opt/pymeshlab-build -DCMAKE_BUILD_TYPE=Release -DPYMESHLAB_SOURCE_DIR="$2" \
    -DMESHLAB_SDK_DIR="$3" -DCMAKE_INSTALL_PREFIX="$4" >/opt/pymeshlab-configure.log 2>&1 \
    || { cat /opt/pymeshlab-configure.log; exit 1; }
  grep -E "MeshLab plugin ABI|pymeshlab " /opt/pymeshlab-configure.log || true
  cmake --build /opt/pymeshlab-build --parallel "$MESHBRIDGE_JOBS"
  cmake --install /opt/pymeshlab-build >/dev/null
  cd / && PYTHONPATH="$4" PYTHONDONTWRITEBYTECODE=1 QT_QPA_PLATFORM=offscreen python3 -c "import pymeshlab as p; \
print(\"build_pymeshlab: import pymeshlab:\", p.pmeshlab.__version__, len(p.filter_list()), \
\"filters\")" 1>&2
' sh "$(dirname "$cmakelists")" "$src" "$sdk" "$prefix" >&2 || die "pymeshlab build failed"
rm -rf "$root/opt/pymeshlab-src" "$root/opt/pymeshlab-build"
echo "$key" >"$root$prefix/.meshbridge-key"
log "pymeshlab $version built in $(($(date +%s) - t0)) s: $root$prefix/pymeshlab"
echo "$prefix"
