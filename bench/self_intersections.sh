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

best() {  # best wall time of $runs runs of "$@" and that run's CPU time (user + sys), "WALL CPU"
  local best_time="" best_cpu="" t cpu
  for _ in $(seq "$runs"); do
    /usr/bin/time -f "%e %U %S" -o "$work/last.time" "$@" >"$work/last.out" 2>&1 ||
      { cat "$work/last.out" >&2; return 1; }
    read -r t user sys <"$work/last.time"
    cpu=$(echo "$user + $sys" | bc -l)
    if [ -z "$best_time" ] || [ "$(echo "$t < $best_time" | bc -l)" = 1 ]; then
      best_time=$t
      best_cpu=$cpu
    fi
  done
  printf '%.2f %.2f' "$best_time" "$best_cpu"
}

echo "Load average at the start: $(cut -d' ' -f1-3 /proc/loadavg); best of $runs runs (wall s, with that run's CPU s)"
echo
echo "| faces | CGAL does_self_intersect | ours, 1 thread | ours, default threads | check alone, 1 thread | check alone, default | ours/CGAL 1 thread (wall, CPU) | ours/CGAL default (wall) | added to check, 1 thread (wall, CPU) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for faces in "${sizes[@]}"; do
  file="$work/torus_$faces.off"
  [ -f "$file" ] || "$bench" make "$faces" 1 "$file" >/dev/null
  read -r cgal cgal_cpu <<<"$(best "$bench" cgal "$file")"
  grep -q "does_self_intersect: no" "$work/last.out"
  read -r ours1 ours1_cpu <<<"$(best env MESHBRIDGE_THREADS=1 "$mb" check --self-intersections "$file")"
  grep -q "self-intersecting face pairs: 0" "$work/last.out"
  read -r ours2 ours2_cpu <<<"$(best "$mb" check --self-intersections "$file")"
  read -r check1 check1_cpu <<<"$(best env MESHBRIDGE_THREADS=1 "$mb" check "$file")"
  read -r check2 check2_cpu <<<"$(best "$mb" check "$file")"
  r() { echo "scale=2; $1 / $2" | bc -l | sed 's/^\./0./'; }
  echo "| $faces | $cgal ($cgal_cpu) | $ours1 ($ours1_cpu) | $ours2 ($ours2_cpu) | $check1 ($check1_cpu) | $check2 ($check2_cpu) | $(r "$ours1" "$cgal"), $(r "$ours1_cpu" "$cgal_cpu") | $(r "$ours2" "$cgal") | $(r "($ours1 - $check1)" "$check1"), $(r "($ours1_cpu - $check1_cpu)" "$check1_cpu") |"
done
