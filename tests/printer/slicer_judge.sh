#!/usr/bin/env bash
# A slicer as the judge: PrusaSlicer's `--info` (which runs admesh's repair on load) on every real
# file, original next to the 3MF of MeshBridge's print preset (`repair --print`). Asserts, per
# file: never more open edges after than before, and never manifold -> not manifold; "manifold =
# yes" after whenever MeshBridge closed every boundary; volume within 1e-6 relative of the
# original's where the slicer found the original closed with nothing fixed.
# Prints the table (file, open edges before/after, parts, volume).
# Usage: slicer_judge.sh MESHBRIDGE SOURCE_DIR WORK_DIR
set -euo pipefail
meshbridge=$1 source_dir=$2 work=$3
command -v prusa-slicer >/dev/null || { echo "prusa-slicer is not installed (scripts/install_deps.sh)"; exit 1; }
command -v jq >/dev/null || { echo "jq is not installed (scripts/install_deps.sh)"; exit 1; }
rm -rf "$work" && mkdir -p "$work"

# Every printer file the repository ships (tests/data/realworld*, and the defect models of
# resources/models), the shared real-world sets beside the checkout when present
# (../shared/data/realworld*, each file once by name; beside the main checkout too when
# SOURCE_DIR is a git worktree, or in $MESHBRIDGE_SHARED_DATA), and the printer models Debian's
# prusa-slicer installs. STL, OBJ and 3MF: what PrusaSlicer reads.
shared=("$source_dir/../shared/data")
common=$(git -C "$source_dir" rev-parse --path-format=absolute --git-common-dir 2>/dev/null || true)
[[ -n $common ]] && shared+=("$(dirname "$common")/../shared/data")
[[ -n ${MESHBRIDGE_SHARED_DATA:-} ]] && shared+=("$MESHBRIDGE_SHARED_DATA")
sources=("$source_dir"/tests/data/realworld*/* "$source_dir"/resources/models/*)
for d in "${shared[@]}"; do sources+=("$d"/realworld*/*); done
files=()
declare -A seen=()
for f in "${sources[@]}"; do
  [[ -f $f ]] || continue
  case "${f,,}" in *.stl | *.obj | *.3mf) ;; *) continue ;; esac
  name=$(basename "$f")
  [[ -n ${seen[$name]:-} ]] && continue
  seen[$name]=1
  files+=("$f")
done
while IFS=$'\t' read -r package path license; do
  [[ $package == package ]] && continue
  [[ -e $path ]] || { echo "missing $path: install the Debian package $package"; exit 1; }
  files+=("$path")
done <"$source_dir/tests/printer/debian_models.tsv"

# key = value lines of prusa-slicer --info
# (a file the slicer cannot load gives no lines: its exit status is read as "no fields")
info() {
  local text
  text=$(prusa-slicer --info "$1" 2>/dev/null) || text=""
  sed -n 's/^\([a-z_]*\) = *\(.*\)$/\1=\2/p' <<<"$text"
}
field() { sed -n "s/^$2=//p" <<<"$1" | head -1; }

# Files whose original bounds no solid, so that the original's volume is asserted to be 0 and the
# volume after is not compared with it:
# - chair_model.obj is a zero-thickness sheet: every triangle is written twice, once per
#   orientation, and 4 triangles four times (a doubled patch around vertex 1528, edges with 8
#   sides). admesh pairs each facet with its reversed twin, so the slicer sees 3694 closed parts
#   of volume 0 and no open edge. MeshBridge closes the two layers on each other (14 closed
#   components); where both layers would share an edge, copies of a triangle are glued back to
#   back instead of cut (tests/unit/copies_glue_rule_test.cpp), so it too leaves no open edge.
declare -A zero_volume_before=([chair_model.obj]=1)
# Files where the preset is known to leave the slicer less happy, with the exact open edges it
# reads after (asserted: any other number fails), until the repair handles their kind. None now:
# dart_drchubo_convhull_RWP_merged.stl (a closed hull written twice, with slivers of zero area)
# was one, 1 open edge after, until a quad split at an edge's midpoint on both sides of the
# sheet took, when cut into triangles, the one diagonal the other side had taken
# (triangles_as_written now takes the other diagonal: a flat triangle, every edge with two).
declare -A known_worse=()

failures=0
printf '| file | open edges before | after | parts before | after | volume before | after | manifold after |\n'
printf '|---|---:|---:|---:|---:|---:|---:|---|\n'
total_before=0 total_after=0 manifold_before=0 manifold_now=0 n=0 unreadable_before=0 known=0
for f in "${files[@]}"; do
  name=$(basename "$f")
  out="$work/${name%.*}.3mf"
  report="$work/${name%.*}.json"
  "$meshbridge" repair "$f" "$out" --print --report "$report" >/dev/null 2>&1 || { echo "FAIL $name: repair failed"; failures=$((failures + 1)); continue; }
  before=$(info "$f") after=$(info "$out")
  if [[ -z $(field "$before" number_of_parts) ]]; then
    # PrusaSlicer cannot load the original (an OBJ polygon of more than 4 corners, say): the
    # preset's 3MF must load, and there is nothing to compare it with.
    printf '| %s | (slicer cannot load) | %s | | %s | | %s | %s |\n' "$name" "$(field "$after" open_edges)" \
      "$(field "$after" number_of_parts)" "$(field "$after" volume)" "$(field "$after" manifold)"
    [[ -n $(field "$after" number_of_parts) ]] || { echo "FAIL $name: the slicer cannot load the preset's 3MF either"; failures=$((failures + 1)); }
    unreadable_before=$((unreadable_before + 1))
    continue
  fi
  ob=$(field "$before" open_edges); ob=${ob:-0}
  oa=$(field "$after" open_edges); oa=${oa:-0}
  fixed_before=$(field "$before" edges_fixed); fixed_before=${fixed_before:-0}
  mb=$(field "$before" manifold) ma=$(field "$after" manifold)
  pb=$(field "$before" number_of_parts) pa=$(field "$after" number_of_parts)
  vb=$(field "$before" volume) va=$(field "$after" volume)
  boundary_after=$(jq -e '.after.boundary_edges' "$report")
  printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" "$ob" "$oa" "$pb" "$pa" "$vb" "$va" "$ma"
  n=$((n + 1)) total_before=$((total_before + ob)) total_after=$((total_after + oa))
  [[ $ma == yes ]] && manifold_now=$((manifold_now + 1))
  [[ $mb == yes ]] && manifold_before=$((manifold_before + 1))
  if [[ -n ${known_worse[$name]:-} ]]; then
    if [[ $oa != "${known_worse[$name]}" ]]; then echo "FAIL $name: $oa open edges after, known: ${known_worse[$name]} (see known_worse)"; failures=$((failures + 1)); fi
    known=$((known + 1))
  else
    if ((oa > ob)); then echo "FAIL $name: $oa open edges after, $ob before"; failures=$((failures + 1)); fi
    if [[ $mb == yes && $ma != yes ]]; then echo "FAIL $name: manifold before, $ma after"; failures=$((failures + 1)); fi
    if [[ $boundary_after == 0 && $ma != yes ]]; then echo "FAIL $name: closed by MeshBridge but the slicer says manifold = $ma"; failures=$((failures + 1)); fi
  fi
  if [[ -n ${zero_volume_before[$name]:-} ]]; then
    if [[ $vb != 0.000000 ]]; then echo "FAIL $name: volume $vb before, expected 0 (a sheet, see zero_volume_before)"; failures=$((failures + 1)); fi
  elif [[ $mb == yes && $fixed_before == 0 ]]; then
    if ! awk -v a="$va" -v b="$vb" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= 1e-6 * m) }'; then
      echo "FAIL $name: volume $va after, $vb before"; failures=$((failures + 1))
    fi
  fi
done
echo "$n files ($known known less happy, see known_worse; and $unreadable_before the slicer cannot load, whose 3MF it loads); open edges $total_before -> $total_after; manifold for the slicer: $manifold_before before, $manifold_now after the print preset"
((failures == 0))
