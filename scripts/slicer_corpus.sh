#!/usr/bin/env bash
# PrusaSlicer as the judge over any folders of printer files (STL, OBJ, 3MF, recursively): for
# each file PrusaSlicer can load, its own load of the original (`prusa-slicer --info`, admesh's
# repair on load) next to MeshBridge's 3MF, repaired plainly and with the print preset
# (`repair --print`). Counts the files where the slicer is less happy with the output (more open
# edges, or manifold -> not manifold), and the files manifold for the slicer, per route.
# Usage: scripts/slicer_corpus.sh MESHBRIDGE DIR... (prints the less-happy files, then a summary)
set -euo pipefail
meshbridge=$1
shift
command -v prusa-slicer >/dev/null || { echo "prusa-slicer is not installed (scripts/install_deps.sh)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# (a file the slicer cannot load gives no lines: its exit status is read as "no fields")
info() {
  local text
  text=$(prusa-slicer --info "$1" 2>/dev/null) || text=""
  sed -n 's/^\([a-z_]*\) = *\(.*\)$/\1=\2/p' <<<"$text"
}
field() { sed -n "s/^$2=//p" <<<"$1" | head -1; }
declare -A worse=([plain]=0 [print]=0) manifold=([input]=0 [plain]=0 [print]=0) open=([input]=0 [plain]=0 [print]=0)
files=0 unloadable=0 failed=0
while IFS= read -r -d '' f; do
  before=$(info "$f")
  if [[ -z $(field "$before" number_of_parts) ]]; then unloadable=$((unloadable + 1)); continue; fi
  files=$((files + 1))
  ob=$(field "$before" open_edges); ob=${ob:-0}
  mb=$(field "$before" manifold)
  open[input]=$((open[input] + ob))
  [[ $mb == yes ]] && manifold[input]=$((manifold[input] + 1))
  for route in plain print; do
    flags=()
    [[ $route == print ]] && flags=(--print)
    if ! "$meshbridge" repair "$f" "$work/out.3mf" "${flags[@]}" >/dev/null 2>&1; then
      echo "repair failed ($route): $f"; failed=$((failed + 1)); continue
    fi
    after=$(info "$work/out.3mf")
    oa=$(field "$after" open_edges); oa=${oa:-0}
    ma=$(field "$after" manifold)
    open[$route]=$((open[$route] + oa))
    [[ $ma == yes ]] && manifold[$route]=$((manifold[$route] + 1))
    if ((oa > ob)) || [[ $mb == yes && $ma != yes ]]; then
      worse[$route]=$((worse[$route] + 1))
      echo "less happy ($route): $f: open edges $ob -> $oa, manifold $mb -> $ma"
    fi
  done
done < <(find "$@" -type f \( -iname '*.stl' -o -iname '*.obj' -o -iname '*.3mf' \) -print0 | sort -z)
echo "$files files PrusaSlicer loads ($unloadable it cannot load, $failed repairs failed)"
echo "less happy: plain repair ${worse[plain]}, print preset ${worse[print]}"
echo "manifold for the slicer: input ${manifold[input]}, plain ${manifold[plain]}, print ${manifold[print]}"
echo "open edges: input ${open[input]}, plain ${open[plain]}, print ${open[print]}"
