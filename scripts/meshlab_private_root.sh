#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs Debian's meshlabserver (MeshLab 2020.09) with a freshly built plugin, without installing
# anything system-wide.
#
# meshlabserver looks for its plugins relative to its own binary:
#   <root>/bin/meshlabserver -> <root>/lib/<multiarch>/meshlab/plugins/
# so this script makes a private root with a copy of the binary, links libmeshlab-common.so and
# the wanted built-in plugins beside it, adds our plugin(s), and runs it under `xvfb-run -a`
# (meshlabserver needs an X display for its GL context; QT_QPA_PLATFORM=offscreen fails).
#
# Usage:
#   scripts/meshlab_private_root.sh make ROOT PLUGIN.so...      make/refresh ROOT, print it
#   scripts/meshlab_private_root.sh run ROOT [meshlabserver args...]
#   scripts/meshlab_private_root.sh list ROOT                   print the filters it loads
#   scripts/meshlab_private_root.sh make-gui ROOT PLUGIN.so...  the same for the GUI: a copy of
#       MESHLAB_GUI_BIN (default /usr/bin/meshlab) and EVERY plugin of Debian's MeshLab, as a
#       user has them, plus ours; prints ROOT/bin/meshlab
#
# Environment:
#   MESHLAB_LIB_DIR       Debian's MeshLab library folder (default /usr/lib/<multiarch>/meshlab)
#   MESHLAB_BIN           the meshlabserver to copy (default /usr/bin/meshlabserver)
#   MESHLAB_PLUGINS       built-in plugins to link (default: io_base filter_clean filter_select
#                         filter_measure filter_meshing)
set -euo pipefail

die() { echo "meshlab_private_root: $*" >&2; exit 1; }

multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch 2>/dev/null || true)
multiarch=${multiarch:-x86_64-linux-gnu}
lib_dir=${MESHLAB_LIB_DIR:-/usr/lib/${multiarch}/meshlab}
bin=${MESHLAB_BIN:-/usr/bin/meshlabserver}
builtin_plugins=${MESHLAB_PLUGINS:-io_base filter_clean filter_select filter_measure filter_meshing}
# libmeshlab-common resolves <root>/bin/../lib/<multiarch>/meshlab (MESHLAB_LIB_INSTALL_DIR).
rel_lib="lib/${multiarch}/meshlab"

make_root() {
  local root=$1; shift
  [ $# -gt 0 ] || die "make: no plugin given"
  [ -x "$bin" ] || die "no $bin: install Debian's meshlab (scripts/setup_meshlab_sdk.sh)"
  [ -f "$lib_dir/libmeshlab-common.so" ] || die "no $lib_dir/libmeshlab-common.so"
  mkdir -p "$root/bin" "$root/$rel_lib/plugins" "$root/config"
  root=$(cd "$root" && pwd)
  # A copy, not a link: Qt's applicationDirPath() resolves symlinks to /usr/bin.
  if ! cmp -s "$bin" "$root/bin/meshlabserver"; then
    cp -f "$bin" "$root/bin/meshlabserver"
  fi
  ln -sfn "$lib_dir/libmeshlab-common.so" "$root/$rel_lib/libmeshlab-common.so"
  # Start from a clean plugin folder: stale plugins would be loaded too.
  find "$root/$rel_lib/plugins" -mindepth 1 -maxdepth 1 -name '*.so' -delete
  local p
  for p in $builtin_plugins; do
    [ -f "$lib_dir/plugins/lib${p}.so" ] || die "no built-in plugin $lib_dir/plugins/lib${p}.so"
    ln -sfn "$lib_dir/plugins/lib${p}.so" "$root/$rel_lib/plugins/lib${p}.so"
  done
  for p in "$@"; do
    [ -f "$p" ] || die "no plugin $p (build it first: cmake --build <build> --target filter_meshbridge)"
    ln -sfn "$(cd "$(dirname "$p")" && pwd)/$(basename "$p")" "$root/$rel_lib/plugins/$(basename "$p")"
  done
  echo "$root"
}

make_gui_root() {
  local root=$1; shift
  local gui=${MESHLAB_GUI_BIN:-/usr/bin/meshlab} p
  [ -x "$gui" ] || die "no $gui: install Debian's meshlab"
  [ $# -gt 0 ] || die "make-gui: no plugin given"
  mkdir -p "$root/bin" "$root/$rel_lib/plugins"
  root=$(cd "$root" && pwd)
  cmp -s "$gui" "$root/bin/meshlab" || cp -f "$gui" "$root/bin/meshlab"
  for p in "$lib_dir"/*.so*; do
    [ -e "$p" ] && ln -sfn "$p" "$root/$rel_lib/$(basename "$p")"
  done
  find "$root/$rel_lib/plugins" -mindepth 1 -maxdepth 1 -name '*.so' -delete
  for p in "$lib_dir"/plugins/*.so; do
    ln -sfn "$p" "$root/$rel_lib/plugins/$(basename "$p")"
  done
  for p in "$@"; do
    [ -f "$p" ] || die "no plugin $p"
    ln -sfn "$(cd "$(dirname "$p")" && pwd)/$(basename "$p")" "$root/$rel_lib/plugins/$(basename "$p")"
  done
  echo "$root/bin/meshlab"
}

run_server() {
  local root=$1; shift
  [ -x "$root/bin/meshlabserver" ] || die "no $root/bin/meshlabserver: run '$0 make' first"
  command -v xvfb-run >/dev/null || die "no xvfb-run: install xvfb and xauth"
  # Keep MeshLab's settings inside the root, not in the user's ~/.config.
  export XDG_CONFIG_HOME="$root/config"
  # xvfb-run -a picks a free display, but two runs starting together can pick the same one:
  # retry when Xvfb itself fails to start (exit status 1 with its own message).
  local attempt status err
  err=$(mktemp)
  for attempt in 1 2 3 4 5; do
    status=0
    xvfb-run -a -s "-screen 0 1024x768x24 -nolisten tcp" "$root/bin/meshlabserver" "$@" 2>"$err" || status=$?
    if [ "$status" -ne 0 ] && grep -q "Xvfb failed to start\|Server is already active" "$err"; then
      sleep "$attempt"
      continue
    fi
    break
  done
  cat "$err" >&2
  rm -f "$err"
  return "$status"
}

cmd=${1:-}
[ $# -ge 2 ] || { sed -n '3,22p' "$0" >&2; exit 2; }
shift
case "$cmd" in
  make) make_root "$@" ;;
  make-gui) make_gui_root "$@" ;;
  run) run_server "$@" ;;
  list)
    # `meshlabserver -d <file>` dumps every loaded filter as "\section f<i> <name> " (doxygen).
    root=$1
    dump=$(mktemp)
    run_server "$root" -d "$dump" >/dev/null
    sed -n 's/^\\section f[0-9]* \(.*\) $/\1/p' "$dump"
    rm -f "$dump"
    ;;
  *) die "unknown command '$cmd' (make, run or list)" ;;
esac
