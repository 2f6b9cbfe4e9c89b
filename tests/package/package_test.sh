#!/usr/bin/env bash
# Usage: package_test.sh BUILD_DIR SOURCE_DIR — installs the build into a temporary prefix and
# builds tests/package against it with find_package(MeshBridge).
set -euo pipefail
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# README's install: every default component, under the prefix only. DESTDIR catches a file
# installed to an absolute path (the MeshLab plugin once was, whatever the prefix).
DESTDIR="$work/dest" cmake --install "$build" --prefix "$work/prefix" >/dev/null
outside=$(cd "$work/dest" && find . -type f ! -path ".$work/prefix/*")
[ -z "$outside" ] || { echo "installed outside the prefix: $outside" >&2; exit 1; }
[ -x "$work/dest$work/prefix/bin/meshbridge" ] || { echo "no bin/meshbridge under the prefix" >&2; exit 1; }
# The pictures module (Qt) is found from the installed executable: ../LIBDIR/meshbridge/.
modules=$(cd "$work/dest$work/prefix" && find . -path "*/meshbridge/meshbridge_pictures.so")
[ -n "$modules" ] || { echo "no meshbridge_pictures.so under the prefix" >&2; exit 1; }
"$work/dest$work/prefix/bin/meshbridge" snapshot "$source/resources/models/twocubes.obj" \
  "$work/twocubes.png" --size 64 >/dev/null && status=0 || status=$?
[ "$status" = 1 ] && [ -s "$work/twocubes.png" ] ||
  { echo "the installed meshbridge cannot draw (exit $status)" >&2; exit 1; }
cmake --install "$build" --prefix "$work/prefix" --component Unspecified >/dev/null
cmake -S "$source/tests/package" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/downstream")
[ "$out" = "6 2" ] || { echo "downstream printed '$out', expected '6 2'" >&2; exit 1; }
echo "find_package(MeshBridge) ok: $out"
