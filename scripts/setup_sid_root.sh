#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes (once) and prints a minimal Debian sid root with MeshLab 2025.07 and what it takes to build
# and test the MeshBridge plugin against it, from a Debian bookworm host. Idempotent: a finished
# root is reused as it is; a root left half-made by an interrupted run is made again.
#
#  1. debootstrap --variant=minbase sid ROOT (the host gets debootstrap from apt if missing);
#  2. apt inside: sid main + deb-src, Acquire::Check-Valid-Until "false" (the archive's Release
#     file may be past its Valid-Until), no recommends, no docs/man pages/locales;
#  3. installs meshlab, g++, cmake, make, Qt5 (qtbase5-dev, libqt5opengl5-dev: sid's MeshLab
#     2025.07 is a Qt5 build), Eigen, GLEW and OpenMesh's runtime, the libraries MeshLab's own
#     plugins need (muparser, qhull_r, lib3ds, openctm), and for the real-GUI test Xvfb, xdotool,
#     x11-utils, ImageMagick, Mesa's software GL and a font, for the real pymeshlab module
#     python3-dev, pybind11-dev, numpy and pytest (and CLI11 for the CLI beside it); OpenMesh's headers and CMake
#     files come from `apt-get download libopenmesh-dev` unpacked with dpkg-deb, because the
#     package itself drags in OpenSceneGraph and GDAL (~400 MB) that nothing here uses;
#  4. MeshLab's plugin headers: `apt-get source --tar-only meshlab` (the .dsc is not always on
#     the archive, so the full source fetch can fail), unpacked to ROOT/opt/meshlab-sdk/<dir>;
#  5. apt's caches are emptied (package files and lists).
#
# ROOT defaults to /var/cache/meshbridge/sid-root: outside the work tree, so a fresh clone (CI)
# on the same machine reuses it. Needs root (debootstrap, chroot). Prints ROOT as its last line;
# ROOT/.meshbridge/sdk-dir holds the SDK path inside the root.
#
# Usage: scripts/setup_sid_root.sh [ROOT]
# Environment: MESHBRIDGE_SID_ROOT (ROOT), MESHBRIDGE_SID_MIRROR (default
#              http://deb.debian.org/debian).
set -euo pipefail

root=${1:-${MESHBRIDGE_SID_ROOT:-/var/cache/meshbridge/sid-root}}
mirror=${MESHBRIDGE_SID_MIRROR:-http://deb.debian.org/debian}
# Bump when the recipe below changes: a root made by another recipe is completed (steps 2-5).
recipe=7
packages=(nlohmann-json3-dev meshlab g++ cmake make qtbase5-dev libqt5opengl5-dev libeigen3-dev libglew-dev
          # Hole filling (CGAL PMP, header-only; the plugin's fill_holes parameter).
          libcgal-dev
          libopenmesh11.0 xz-utils
          # MeshLab's own plugins that Debian's meshlab package does not pull in: without them
          # the GUI opens an "Error while loading plugins" dialog over its main window.
          libmuparser2v5 libqhull-r8.0 lib3ds-1-3 libopenctm1
          # The real-GUI test (tests/meshlab2025/gui): X server, driver, screenshots, fonts.
          xvfb xdotool x11-utils imagemagick libgl1-mesa-dri fonts-dejavu-core
          # The real pymeshlab module (scripts/build_pymeshlab.sh, ~20 MB), the meshbridge Python
          # module and CLI beside it (README's pymeshlab examples, pymeshlab batch vs meshbridge
          # batch), run by pytest.
          python3-dev pybind11-dev python3-numpy python3-pytest libcli11-dev)

log() { echo "setup_sid_root: $*" >&2; }
die() { echo "setup_sid_root: ERROR: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || die "needs root (debootstrap and chroot); run as root or with sudo"
case "$root" in
  /*) ;;
  *) root="$(pwd)/$root" ;;
esac
[ "$root" != / ] || die "refusing ROOT=/"
mkdir -p "$(dirname "$root")"
stamp_dir="$root/.meshbridge"

# One run at a time per root (the test script takes the same lock while it uses the root).
exec 9>"$root.lock"
flock 9

mounted_under() {  # prints the mount points below $1
  awk -v r="$1" '$2 == r || index($2, r "/") == 1 { print $2 }' /proc/self/mounts
}

# --- 1. debootstrap ----------------------------------------------------------------------------
if [ ! -f "$stamp_dir/debootstrap.done" ]; then
  if [ -e "$root" ]; then
    [ -z "$(mounted_under "$root")" ] \
      || die "$root is half-made and has mounts below it: $(mounted_under "$root" | tr '\n' ' ')"
    log "removing the half-made root $root"
    rm -rf --one-file-system "$root"
  fi
  if ! command -v debootstrap >/dev/null; then
    log "installing debootstrap on the host"
    apt-get update -qq || die "apt-get update failed on the host"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends debootstrap >/dev/null \
      || die "cannot install debootstrap on the host"
  fi
  log "debootstrap --variant=minbase sid $root $mirror"
  mkdir -p "$root"
  if ! debootstrap --variant=minbase sid "$root" "$mirror" >"$root.debootstrap.log" 2>&1; then
    tail -n 20 "$root.debootstrap.log" >&2
    die "debootstrap of Debian sid failed (no access to $mirror?); full log: $root.debootstrap.log"
  fi
  mkdir -p "$stamp_dir"
  touch "$stamp_dir/debootstrap.done"
fi

if [ "$(cat "$stamp_dir/recipe" 2>/dev/null)" = "$recipe" ] && [ -s "$stamp_dir/sdk-dir" ]; then
  log "sid root ready (cached): $root"
  echo "$root"
  exit 0
fi

# --- 2. apt configuration ----------------------------------------------------------------------
cat >"$root/etc/apt/sources.list" <<EOF
deb $mirror sid main
deb-src $mirror sid main
EOF
cat >"$root/etc/apt/apt.conf.d/99meshbridge" <<'EOF'
// MeshBridge sid root (scripts/setup_sid_root.sh)
Acquire::Check-Valid-Until "false";
Acquire::Languages "none";
APT::Install-Recommends "false";
APT::Install-Suggests "false";
EOF
cat >"$root/etc/dpkg/dpkg.cfg.d/99meshbridge-nodoc" <<'EOF'
# MeshBridge sid root: no documentation, man pages or translations (copyright files stay)
path-exclude /usr/share/doc/*
path-include /usr/share/doc/*/copyright
path-exclude /usr/share/man/*
path-exclude /usr/share/info/*
path-exclude /usr/share/locale/*
EOF
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true

# --- 3.-5. inside the root ---------------------------------------------------------------------
cleanup() {
  local m
  for m in $(mounted_under "$root" | sort -r); do
    umount "$m" 2>/dev/null || umount -l "$m" || true
  done
}
trap cleanup EXIT
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"

in_root() {
  chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive "$@"
}

log "apt-get update (sid)"
in_root apt-get update -qq || die "apt-get update inside the sid root failed (no access to $mirror?)"
log "installing ${packages[*]}"
in_root apt-get install -y -qq "${packages[@]}" >"$root.install.log" 2>&1 || {
  tail -n 20 "$root.install.log" >&2
  die "apt-get install inside the sid root failed; full log: $root.install.log"
}

# OpenMesh's development files without libopenmesh-dev's OpenSceneGraph/GDAL dependencies. The
# runtime package pins the version; take the -dev of exactly that version.
om_version=$(in_root dpkg-query -W -f='${Version}' libopenmesh11.0)
log "unpacking libopenmesh-dev $om_version (headers, CMake config)"
in_root sh -c "rm -rf /tmp/openmesh-dev && mkdir /tmp/openmesh-dev && cd /tmp/openmesh-dev \
  && apt-get download -qq libopenmesh-dev=$om_version && dpkg-deb -x libopenmesh-dev_*.deb / \
  && rm -rf /tmp/openmesh-dev" || die "cannot fetch libopenmesh-dev $om_version"

log "apt-get source --tar-only meshlab (plugin headers)"
in_root sh -c 'rm -rf /opt/meshlab-sdk && mkdir -p /opt/meshlab-sdk && cd /opt/meshlab-sdk \
  && apt-get source -qq --tar-only meshlab 2>/dev/null && tar -xf meshlab_*.orig.tar.* \
  && rm -f meshlab_*.tar.*' || die "apt-get source --tar-only meshlab failed inside the sid root"
sdk_header=$(cd "$root" && find opt/meshlab-sdk -maxdepth 6 -path '*/src/common/plugins/interfaces/filter_plugin.h' | head -n1)
[ -n "$sdk_header" ] || die "no src/common/plugins/interfaces/filter_plugin.h in MeshLab's source"
sdk_dir="/${sdk_header%/src/common/plugins/interfaces/filter_plugin.h}"

in_root apt-get clean
rm -rf "$root"/var/lib/apt/lists/* "$root"/var/cache/apt/*.bin

meshlab_version=$(in_root dpkg-query -W -f='${Version}' meshlab)
echo "$sdk_dir" >"$stamp_dir/sdk-dir"
echo "$meshlab_version" >"$stamp_dir/meshlab-version"
echo "$recipe" >"$stamp_dir/recipe"
log "sid root ready: $root (meshlab $meshlab_version, headers in $sdk_dir, $(du -sh --one-file-system "$root" | cut -f1))"
echo "$root"
