#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# MeshLab's own "Repair non Manifold Edges" (both methods) and "Repair non Manifold Vertices"
# against MeshBridge's Repair, through the real pymeshlab in the sid root, on the bundled models
# and the real-world files: faces kept, components, boundary edges, non-manifold elements left,
# time (scripts/pymeshlab_compare.py; the table in README and docs/meshlab.md comes from it).
# Uses the sid root, pymeshlab and the plugin of scripts/test_meshlab2025.sh (run that first).
#
# Usage: bash scripts/pymeshlab_compare.sh [FILE...]   (default: resources/models/*.obj and
#        tests/data/realworld*/*, the copies of ../shared/data/realworld*)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo"
root=$(bash scripts/setup_sid_root.sh | tail -n 1)
pymeshlab=$(bash scripts/build_pymeshlab.sh "$root" | tail -n 1)
build="$repo/build/meshlab2025"
[ -f "$build/CMakeCache.txt" ] || { echo "pymeshlab_compare: run scripts/test_meshlab2025.sh first" >&2; exit 1; }
if [ $# -gt 0 ]; then
  files=()
  for f in "$@"; do files+=("$(cd "$(dirname "$f")" && pwd)/$(basename "$f")"); done
else
  files=("$repo"/resources/models/*.obj)
  for f in "$repo"/tests/data/realworld*/*; do
    case "$f" in *.md | *.tsv) ;; *) files+=("$f") ;; esac
  done
fi
bash scripts/in_sid_root.sh "$root" /bin/sh -c '
  set -e
  build=$1 pymeshlab=$2 script=$3
  shift 3
  cmake --build "$build" --target filter_meshbridge >/dev/null
  plugin="$build/plugin/libfilter_meshbridge.so"
  cd /tmp && env PYTHONPATH="$pymeshlab:$build/meshbridge/python" MESHBRIDGE_PLUGIN="$plugin" QT_QPA_PLATFORM=offscreen \
    python3 "$script" "$@"
' sh "$build" "$pymeshlab" "$repo/scripts/pymeshlab_compare.py" "${files[@]}"
