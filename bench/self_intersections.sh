#!/usr/bin/env bash
# Self-intersection detection against CGAL's does_self_intersect, whole processes, on a clean
# torus (faces shuffled): best of RUNS for each of
#   CGAL         meshbridge-self-intersections-bench cgal FILE (CGAL's OFF read + test; CGAL is
#                sequential here: its parallel mode needs TBB's headers, not installed)
#   ours 1 / 2   meshbridge check --self-intersections FILE with MESHBRIDGE_THREADS=1 / default
#   check 1 / 2  meshbridge check FILE (without it), the same threads
# and prints the ratios. Usage: bench/self_intersections.sh BUILD_DIR WORK_DIR [FACES...]
# (default FACES: 1053696). Every run's output is checked: CGAL must say "no", check exit 0.
set -euo pipefail
build="$1"
work="$2"
shift 2
sizes=("${@:-1053696}")
runs="${RUNS:-5}"
bench="$build/bench/meshbridge-self-intersections-bench"
mb="$build/cli/meshbridge"
mkdir -p "$work"

best() {  # best wall time of $runs runs of "$@" (seconds); fails if a run fails
  local best_time="" start end t
  for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    "$@" >"$work/last.out" 2>&1 || { cat "$work/last.out" >&2; return 1; }
    end=$(date +%s.%N)
    t=$(echo "$end - $start" | bc -l)
    if [ -z "$best_time" ] || [ "$(echo "$t < $best_time" | bc -l)" = 1 ]; then best_time=$t; fi
  done
  printf '%.3f' "$best_time"
}

echo "| faces | CGAL does_self_intersect s | ours 1 thread s | ours default s | check 1 thread s | check default s | ours/CGAL 1 thread | ours/CGAL default | added to check (1 thread) | added to check (default) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for faces in "${sizes[@]}"; do
  file="$work/torus_$faces.off"
  [ -f "$file" ] || "$bench" make "$faces" 1 "$file" >/dev/null
  cgal=$(best "$bench" cgal "$file")
  grep -q "does_self_intersect: no" "$work/last.out"
  ours1=$(best env MESHBRIDGE_THREADS=1 "$mb" check --self-intersections "$file")
  grep -q "self-intersecting face pairs: 0" "$work/last.out"
  ours2=$(best "$mb" check --self-intersections "$file")
  check1=$(best env MESHBRIDGE_THREADS=1 "$mb" check "$file")
  check2=$(best "$mb" check "$file")
  r() { echo "scale=2; $1 / $2" | bc -l; }
  echo "| $faces | $cgal | $ours1 | $ours2 | $check1 | $check2 | $(r "$ours1" "$cgal") | $(r "$ours2" "$cgal") | $(r "$ours1 - $check1" "$check1") | $(r "$ours2 - $check2" "$check2") |"
done
