#!/usr/bin/env bash
# Self-intersection detection against CGAL's does_self_intersect, whole processes, on a clean
# torus (faces shuffled): best of RUNS rounds (each round runs every variant once, in a shuffled
# order) for each of
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

# run VARIANT: one timed run of that variant, its output checked; appends "WALL CPU" to
# $work/VARIANT.times.
run() {
  local cmd
  case "$1" in
    cgal) cmd=("$bench" cgal "$file") ;;
    ours1) cmd=(env MESHBRIDGE_THREADS=1 "$mb" check --self-intersections "$file") ;;
    ours2) cmd=("$mb" check --self-intersections "$file") ;;
    check1) cmd=(env MESHBRIDGE_THREADS=1 "$mb" check "$file") ;;
    check2) cmd=("$mb" check "$file") ;;
  esac
  /usr/bin/time -f "%e %U %S" -o "$work/last.time" "${cmd[@]}" >"$work/last.out" 2>&1 ||
    { cat "$work/last.out" >&2; return 1; }
  case "$1" in
    cgal) grep -q "does_self_intersect: no" "$work/last.out" ;;
    ours*) grep -q "self-intersecting face pairs: 0" "$work/last.out" ;;
  esac
  read -r t user sys <"$work/last.time"
  echo "$t $(echo "$user + $sys" | bc -l)" >>"$work/$1.times"
}
# best VARIANT -> "WALL CPU": the best wall time of its runs and that run's CPU time.
best() {
  sort -g "$work/$1.times" | head -1 | awk '{ printf "%.2f %.2f", $1, $2 }'
}
variants=(cgal ours1 ours2 check1 check2)

echo "Load average at the start: $(cut -d' ' -f1-3 /proc/loadavg); best of $runs rounds, variants shuffled in each (wall s, with that run's CPU s)"
echo
echo "| faces | CGAL does_self_intersect | ours, 1 thread | ours, default threads | check alone, 1 thread | check alone, default | ours/CGAL 1 thread (wall, CPU) | ours/CGAL default (wall, CPU) | added to check, 1 thread (wall, CPU) |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for faces in "${sizes[@]}"; do
  file="$work/torus_$faces.off"
  [ -f "$file" ] || "$bench" make "$faces" 1 "$file" >/dev/null
  rm -f "$work"/*.times
  # Every round runs each variant once, in an order shuffled anew (seeded by the round), so
  # that a slow spell of the shared machine falls on every variant alike.
  for round in $(seq "$runs"); do
    for v in $(printf '%s\n' "${variants[@]}" | shuf --random-source=<(yes "$faces$round")); do
      run "$v"
    done
  done
  read -r cgal cgal_cpu <<<"$(best cgal)"
  read -r ours1 ours1_cpu <<<"$(best ours1)"
  read -r ours2 ours2_cpu <<<"$(best ours2)"
  read -r check1 check1_cpu <<<"$(best check1)"
  read -r check2 check2_cpu <<<"$(best check2)"
  r() { echo "scale=2; $1 / $2" | bc -l | sed 's/^\./0./'; }
  echo "| $faces | $cgal ($cgal_cpu) | $ours1 ($ours1_cpu) | $ours2 ($ours2_cpu) | $check1 ($check1_cpu) | $check2 ($check2_cpu) | $(r "$ours1" "$cgal"), $(r "$ours1_cpu" "$cgal_cpu") | $(r "$ours2" "$cgal"), $(r "$ours2_cpu" "$cgal_cpu") | $(r "($ours1 - $check1)" "$check1"), $(r "($ours1_cpu - $check1_cpu)" "$check1_cpu") |"
done
