#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs a command inside the sid root made by scripts/setup_sid_root.sh, with /proc mounted and
# the MeshBridge work tree bind-mounted at the same path as on the host (so paths in build files
# and test output are the host's). Unmounts both afterwards, whatever the command did. Holds the
# root's lock meanwhile, so runs (and setup) on one root never overlap.
#
# Usage: scripts/in_sid_root.sh ROOT COMMAND [ARG...]
# The command runs with a clean environment: PATH, HOME=/root, LANG=C.UTF-8, and every
# MESHBRIDGE_* / CTEST_* / CMAKE_BUILD_PARALLEL_LEVEL variable of the caller.
set -euo pipefail

die() { echo "in_sid_root: ERROR: $*" >&2; exit 1; }
[ $# -ge 2 ] || die "usage: $0 ROOT COMMAND [ARG...]"
[ "$(id -u)" -eq 0 ] || die "needs root (chroot, mount)"
root=$(cd "$1" && pwd) || die "no root $1"
shift
[ -s "$root/.meshbridge/recipe" ] || die "$root is not a finished sid root (run scripts/setup_sid_root.sh)"
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

exec 9>"$root.lock"
flock 9

mounted=()
cleanup() {
  local i
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    umount "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" || true
  done
}
trap cleanup EXIT
if ! mountpoint -q "$root/proc"; then
  mount -t proc proc "$root/proc"
  mounted+=("$root/proc")
fi
if ! mountpoint -q "$root$repo"; then
  mkdir -p "$root$repo"
  mount --bind "$repo" "$root$repo"
  mounted+=("$root$repo")
fi

env_args=(PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8)
while IFS='=' read -r name _; do
  case "$name" in
    MESHBRIDGE_* | CTEST_* | CMAKE_BUILD_PARALLEL_LEVEL) env_args+=("$name=${!name}") ;;
  esac
done < <(env)
status=0
chroot "$root" /usr/bin/env -i "${env_args[@]}" "$@" || status=$?
exit "$status"
