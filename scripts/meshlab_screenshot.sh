#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# README screenshots of the real MeshLab GUI (Debian's /usr/bin/meshlab, 2020.09) taken the way a
# user works, by the same driver as the real-GUI tests (tests/meshlab/gui_detect.sh): MeshLab
# starts with default settings on a bundled model, Detect runs from Filters' search (Ctrl+F) with
# its default parameters, the model is turned by a mouse drag in the 3D view, and the screen is
# grabbed. No project file, no render setting changed: what the picture shows is what a user
# sees right after Detect (singular edges red, boundary edges green, the log's summary line).
#
# MeshLab runs from a private root (scripts/meshlab_private_root.sh make-gui: every plugin of
# Debian's MeshLab plus the freshly built one), nothing is installed system-wide. The model is
# opened from a neutral folder (/tmp/meshbridge-demo), so the pictures show no path of this
# machine.
#
# Usage: scripts/meshlab_screenshot.sh [OUT_DIR] [MODEL[:DX:DY] ...]
#   OUT_DIR defaults to docs/images; models default to t_junction_rib:150:-120 and
#   prisms24:120:-160 (bundled resources/models/<name>.off, or a path to an .off/.ply/.stl file;
#   DX, DY: the mouse drag that turns the model, in pixels). Writes OUT_DIR/meshlab_<name>.png
#   and prints the red and green pixels of each 3D view.
# Environment: PLUGIN (default build/release/plugin/libfilter_meshbridge.so, built if missing),
#   SIZE (screen, default 1400x1100).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
caller_dir="$PWD"
cd "$repo"
die() { echo "meshlab_screenshot: $*" >&2; exit 1; }
from_caller() { case "$1" in /*) echo "$1" ;; *) echo "$caller_dir/$1" ;; esac; }

out_dir="docs/images"
[ $# -gt 0 ] && out_dir=$(from_caller "$1")
[ $# -gt 0 ] && shift
models=("$@")
[ ${#models[@]} -gt 0 ] || models=(t_junction_rib:150:-120 prisms24:120:-160)
plugin="${PLUGIN:-$repo/build/release/plugin/libfilter_meshbridge.so}"
base="$repo/build/release/meshlab-screenshot"
demo=/tmp/meshbridge-demo

bash scripts/install_deps.sh meshlab xvfb xdotool x11-utils imagemagick
sdk="$(bash scripts/setup_meshlab_sdk.sh | tail -n 1)"
# The pixel counter of the same build as the plugin (<build>/plugin/lib... -> <build>/tests/...).
count_pixels="$(dirname "$(dirname "$plugin")")/tests/meshlab/meshbridge_count_pixels"
if [ ! -f "$plugin" ] || [ ! -x "$count_pixels" ]; then
  echo "meshlab_screenshot: building the plugin and the pixel counter"
  cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=ON \
    -DMESHBRIDGE_BUILD_PLUGIN=ON -DMESHLAB_SDK_DIR="$sdk" >/dev/null
  cmake --build build/release --parallel "$(nproc 2>/dev/null || echo 2)" \
    --target filter_meshbridge meshbridge_count_pixels >/dev/null
fi
[ -f "$plugin" ] || die "no plugin $plugin"
mkdir -p "$base" "$out_dir" "$demo"
out_dir="$(cd "$out_dir" && pwd)"
gui_bin=$(bash scripts/meshlab_private_root.sh make-gui "$base/gui-root" "$plugin")

for spec in "${models[@]}"; do
  IFS=: read -r model dx dy <<<"$spec"
  case "$model" in
    */* | *.*) src=$(from_caller "$model") ;;
    *) src="resources/models/$model.off" ;;
  esac
  [ -f "$src" ] || die "no model $src"
  name=$(basename "${src%.*}")
  cp -f "$src" "$demo/"
  shot="$base/$name"
  rm -rf "$shot"
  echo "== $name: meshlab $(basename "$src"), Detect, drag ${dx:-0},${dy:-0}"
  DRAG="${dx:-0} ${dy:-0}" COUNT_PIXELS="$count_pixels" \
    bash tests/meshlab/gui_detect.sh "$gui_bin" "$demo/$(basename "$src")" "$shot" >"$shot.txt" \
    || die "the GUI session failed for $name (see $shot/session.txt)"
  grep -E "^(red|green)=" "$shot.txt" | tr '\n' ' '
  echo
  png="$out_dir/meshlab_$name.png"
  # A palette PNG: small enough to commit.
  /usr/bin/convert "$shot/screen.png" -colors 256 -define png:compression-level=9 -strip "$png"
  echo "   $png ($(du -k "$png" | cut -f1) KB)"
done
