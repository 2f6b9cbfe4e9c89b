#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# MeshBridge's "Repair Singular Defects (Bridged Half-Edge)" against MeshLab 2020.09's own
# "Repair non Manifold Edges" filters, through Debian's real meshlabserver with the freshly
# built plugin (private root, see scripts/meshlab_private_root.sh), on the same inputs in the
# same script. Prints a markdown table.
#
# For every input, each method runs REPS times as its own meshlabserver process (load the OFF,
# apply the filter script, save a PLY), timed by wall clock; the median minus the median of the
# baseline (same load and save, empty filter script) is the filter's own cost. Then one more
# run of each method, untimed, appends MeshLab's own checks in the same script ("Compute
# Topological Measures", "Select non Manifold Edges ", "Select non Manifold Vertices", as
# tests/meshlab/check_manifold.mlx does) and saves an ASCII PLY with the selection flags:
# faces and vertices after, MeshLab's non-manifold edge and vertex counts, and what its two
# selection filters select.
#
# Methods:
#   baseline          load + save only (empty filter list)
#   meshbridge        resources/scripts/repair.mlx (our filter, default parameters)
#   ml_remove         "Repair non Manifold Edges by removing faces"
#   ml_remove+vsplit  the same, then "Repair non Manifold Vertices by splitting" (what a MeshLab
#                     user runs next: removing faces leaves non-manifold vertices)
#   ml_split          "Repair non Manifold Edges by splitting vertices" (MeshLab 2020.09 throws
#                     vcg::MissingComponentException on every input; see the note printed below)
#
# Usage: scripts/meshlab_compare.sh [MODEL.off ...]
#   Without models: the bundled 24-prism model, then 3D checkerboards of unit cubes: n^3 cells,
#   cell (i,j,k) filled iff i+j+k is even, 12 outward triangles per cube, vertices welded on the
#   integer lattice, so every inner lattice edge is shared by two diagonal cubes (4 faces: a
#   singular edge) and every inner lattice point is a singular vertex; for n in SIZES.
# Environment: REPS (default 7), SIZES (default "10 20 30 40"), PLUGIN (default
#   build/release/plugin/libfilter_meshbridge.so, built if missing), WORK (default
#   build/release/meshlab-compare), METHODS (default: all above), MEM_LIMIT_MB (virtual memory
#   cap of each meshlabserver run, default 4096).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
caller_dir="$PWD"
die() { echo "meshlab_compare: $*" >&2; exit 1; }
reps="${REPS:-7}"
sizes="${SIZES:-10 20 30 40}"
plugin="${PLUGIN:-$repo/build/release/plugin/libfilter_meshbridge.so}"
work="${WORK:-$repo/build/release/meshlab-compare}"
methods="${METHODS:-baseline meshbridge ml_remove ml_remove+vsplit ml_split}"
root="$work/root"

if [ -z "${MESHLAB_COMPARE_IN_XVFB:-}" ]; then
  # --- outside Xvfb: dependencies, plugin, private root, inputs; then rerun inside one Xvfb ---
  cd "$repo"
  bash scripts/install_deps.sh meshlab xvfb xauth
  if [ ! -f "$plugin" ]; then
    echo "meshlab_compare: building the plugin" >&2
    sdk="$(bash scripts/setup_meshlab_sdk.sh | tail -n 1)"
    cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=OFF \
      -DMESHBRIDGE_BUILD_PLUGIN=ON -DMESHLAB_SDK_DIR="$sdk" >/dev/null
    cmake --build build/release --parallel "$(nproc 2>/dev/null || echo 2)" --target filter_meshbridge >/dev/null
  fi
  [ -f "$plugin" ] || die "no plugin $plugin"
  mkdir -p "$work/models"
  MESHLAB_PLUGINS="io_base filter_clean filter_select filter_measure" \
    bash scripts/meshlab_private_root.sh make "$root" "$plugin" >/dev/null
  inputs=()
  if [ $# -gt 0 ]; then
    for m in "$@"; do
      case "$m" in /*) ;; *) m="$caller_dir/$m" ;; esac
      [ -f "$m" ] || die "no model $m"
      case "$m" in *.off | *.OFF) ;; *) die "$m: give OFF files (meshlabserver 2020.09 aborts on OBJ input)" ;; esac
      inputs+=("$(cd "$(dirname "$m")" && pwd)/$(basename "$m")")
    done
  else
    inputs+=("$repo/resources/models/prisms24.off")  # the paper's 24-prism model, for the record
    for n in $sizes; do
      out="$work/models/checkerboard_$n.off"
      awk -v n="$n" 'BEGIN {
        # quads of a unit cube as corner offsets (dx dy dz), counter-clockwise seen from outside
        q[0] = "000 001 011 010"; q[1] = "100 110 111 101"; q[2] = "000 100 101 001"
        q[3] = "010 011 111 110"; q[4] = "000 010 110 100"; q[5] = "001 101 111 011"
        m = n + 1; nf = 0
        for (k = 0; k < n; k++) for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
          if ((i + j + k) % 2) continue
          for (s = 0; s < 6; s++) {
            split(q[s], c, " ")
            for (t = 1; t <= 4; t++) {
              id[t] = (i + substr(c[t], 1, 1)) + m * ((j + substr(c[t], 2, 1)) + m * (k + substr(c[t], 3, 1)))
              used[id[t]] = 1
            }
            f[nf++] = id[1] " " id[2] " " id[3]; f[nf++] = id[1] " " id[3] " " id[4]
          }
        }
        nv = 0
        for (p = 0; p < m * m * m; p++) if (p in used) { newid[p] = nv++; }
        print "OFF"; print nv, nf, 0
        for (p = 0; p < m * m * m; p++) if (p in used) print p % m, int(p / m) % m, int(p / (m * m))
        for (x = 0; x < nf; x++) { split(f[x], v, " "); print 3, newid[v[1]], newid[v[2]], newid[v[3]] }
      }' >"$out.tmp"
      mv "$out.tmp" "$out"
      inputs+=("$out")
    done
  fi
  export MESHLAB_COMPARE_IN_XVFB=1 REPS="$reps" WORK="$work" METHODS="$methods"
  exec xvfb-run -a -s "-screen 0 1024x768x24 -nolisten tcp" bash "$repo/scripts/meshlab_compare.sh" "${inputs[@]}"
fi

# --- inside Xvfb: one X server for every run, so its start-up is not in the timings ---------------
export XDG_CONFIG_HOME="$root/config"
server="$root/bin/meshlabserver"
scripts="$work/scripts"
mkdir -p "$scripts" "$work/runs"
mlx() {  # mlx FILE FILTER...: a filter script with those filters, default parameters
  local file=$1 f; shift
  { echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
    for f in "$@"; do echo " <filter name=\"$f\"/>"; done
    echo '</FilterScript>'; } >"$file"
}
mlx "$scripts/baseline.mlx"
cp "$repo/resources/scripts/repair.mlx" "$scripts/meshbridge.mlx"
mlx "$scripts/ml_remove.mlx" "Repair non Manifold Edges by removing faces"
mlx "$scripts/ml_remove+vsplit.mlx" "Repair non Manifold Edges by removing faces" "Repair non Manifold Vertices by splitting"
mlx "$scripts/ml_split.mlx" "Repair non Manifold Edges by splitting vertices"
# MeshLab's own checks (the filter names as in tests/meshlab/check_manifold.mlx; note the
# trailing space in "Select non Manifold Edges ", MeshLab 2020.09's name).
mlx "$scripts/check.mlx" "Compute Topological Measures" "Select non Manifold Edges " "Select non Manifold Vertices"

now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) print ""; else if (NR % 2) print v[(NR + 1) / 2]; else print int((v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
# selected ASCII_PLY: "selected_faces selected_vertices" from the flags (last field, bit 0x20)
selected() {
  awk 'BEGIN { sf = 0; sv = 0 }
    hdr == 0 && /^element vertex/ { nv = $3 } hdr == 0 && /^element face/ { nf = $3 }
    hdr == 0 && /^end_header/ { hdr = 1; next }
    hdr == 1 { r++; if (int($NF / 32) % 2) { if (r <= nv) sv++; else if (r <= nv + nf) sf++ } }
    END { print sf, sv }' "$1"
}
value() { sed -n "s/^$1=//p" "$2" | tail -n 1; }

# run_server LOG ARGS...: one meshlabserver process, capped at MEM_LIMIT_MB of virtual memory
# (ml_split on a 30^3 board grew past 18 GB before std::bad_alloc when uncapped), in a subshell
# whose stderr is dropped (bash's own "Aborted" notice would clutter the output).
run_server() {
  local log=$1; shift
  ( ulimit -v $(( ${MEM_LIMIT_MB:-4096} * 1024 )); exec "$server" "$@" >"$log" 2>&1 ) 2>/dev/null
}
crash_reason() {  # crash_reason LOG: the exception or assertion meshlabserver died of
  sed -n "s/.*throwing an instance of '\([^']*\)'.*/\1/p; s/.*\(Assertion.*\)/\1/p; s/.*\(Problem with filter.*\)/\1/p" \
    "$1" | head -n 1
}

table="$work/table.md"
{
  echo "| input | faces in | method | status | wall median (ms) | wall min–max (ms) | filter cost (ms) | cost vs ours | faces after | faces kept | vertices after | MeshLab non-manifold edges after | non-manifold vertices after | faces selected by *Select non Manifold Edges* | vertices selected by *Select non Manifold Vertices* |"
  echo "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} >"$table"

for input in "$@"; do
  name=$(basename "$input" .off)
  dir="$work/runs/$name"
  rm -rf "$dir"; mkdir -p "$dir"
  # faces as MeshLab loads them: polygons are triangulated (n - 2 triangles each)
  faces_in=$(awk '/^[ \t]*(#|$)/ { next } h == 0 { h = 1; if ($1 ~ /^OFF/ && NF > 1) { nv = $2; nf = $3; h = 2 } next }
    h == 1 { nv = $1; nf = $2; h = 2; next }
    h == 2 { if (r < nv) { r++; next } if (f < nf) { t += $1 - 2; f++ } } END { print t }' "$input")
  echo "== $name: $faces_in faces" >&2
  # Timed runs, round robin (rep 1 of every method, then rep 2, ...), so that drifting load on
  # the machine spreads over all methods alike. A method that crashes is not run again.
  for method in $methods; do echo "status=ok" >"$dir/$method.txt"; : >"$dir/$method.times"; done
  for rep in $(seq 1 "$reps"); do
    for method in $methods; do
      [ "$(value status "$dir/$method.txt")" = ok ] || continue
      rc=0
      t0=$(now_ms)
      run_server "$dir/$method.log" -i "$input" -o "$dir/$method.ply" -s "$scripts/$method.mlx" || rc=$?
      t1=$(now_ms)
      if [ "$rc" -ne 0 ]; then
        why=$(crash_reason "$dir/$method.log")
        echo "status=crashes (exit $rc${why:+, $why}, after $((t1 - t0)) ms)" >>"$dir/$method.txt"
        continue
      fi
      echo "$((t1 - t0))" >>"$dir/$method.times"
    done
  done
  # One untimed run per method with MeshLab's own checks appended in the same script.
  for method in $methods; do
    res="$dir/$method.txt"
    if [ "$(value status "$res")" = ok ]; then
      echo "median=$(median <"$dir/$method.times")" >>"$res"
      echo "range=$(sort -n "$dir/$method.times" | head -n 1)–$(sort -n "$dir/$method.times" | tail -n 1)" >>"$res"
      rc=0
      log="$dir/$method.check.log"
      run_server "$log" -i "$input" -o "$dir/$method.check.ply" -m vf ff sa \
        -s "$scripts/$method.mlx" -s "$scripts/check.mlx" || rc=$?
      if [ "$rc" -ne 0 ]; then
        echo "status=checks crash (exit $rc, $(crash_reason "$log"))" >>"$res"
      else
        grep -m1 "saved as" "$log" | sed -n 's/.*(\([0-9]*\) vn \([0-9]*\) fn).*/vn=\1\nfn=\2/p' >>"$res"
        # "Compute Topological Measures" logs these only when they are not zero.
        nme=$(sed -n 's/.*Mesh has \([0-9]*\) non two manifold edges.*/\1/p' "$log" | head -n 1)
        nmv=$(sed -n 's/.*Mesh has \([0-9]*\) non two manifold vertices.*/\1/p' "$log" | head -n 1)
        echo "nm_edges=${nme:-0}" >>"$res"
        echo "nm_vertices=${nmv:-0}" >>"$res"
        read -r sf sv < <(selected "$dir/$method.check.ply")
        echo "sel_faces=$sf" >>"$res"
        echo "sel_vertices=$sv" >>"$res"
        rm -f "$dir/$method.check.ply"
      fi
    fi
    echo "   $method: $(grep -v '^status=ok$' "$res" | tr '\n' ' ')" >&2
  done
  base=$(value median "$dir/baseline.txt")
  ours_cost=""
  if [ -n "$base" ] && [ -n "$(value median "$dir/meshbridge.txt")" ]; then
    ours_cost=$(( $(value median "$dir/meshbridge.txt") - base ))
  fi
  for method in $methods; do
    res="$dir/$method.txt"
    st=$(value status "$res")
    med=$(value median "$res"); fn=$(value fn "$res"); vn=$(value vn "$res")
    cost=""; ratio=""; kept=""
    if [ -n "$med" ] && [ -n "$base" ] && [ "$method" != baseline ]; then
      cost=$((med - base))
      if [ "$method" = meshbridge ]; then
        ratio="1"
      elif [ -n "$ours_cost" ]; then
        # a ratio of two differences within the noise means nothing: only when both exceed 10 ms
        ratio=$(awk -v a="$cost" -v b="$ours_cost" 'BEGIN { if (a > 10 && b > 10) printf "%.2f", a / b; else print "(noise)" }')
      fi
    fi
    [ -n "$fn" ] && kept=$(awk -v a="$fn" -v b="$faces_in" 'BEGIN { printf "%.1f%%", 100 * a / b }')
    [ "$method" = baseline ] && cost="(load+save)"
    printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' \
      "$name" "$faces_in" "$method" "${st//|/\\|}" "${med:--}" "$(value range "$res")" "${cost:--}" "${ratio:--}" \
      "${fn:--}" "${kept:--}" "${vn:--}" "$(value nm_edges "$res")" "$(value nm_vertices "$res")" \
      "$(value sel_faces "$res")" "$(value sel_vertices "$res")" >>"$table"
  done
done

cat "$table"
cat <<EOF

Wall clock of one meshlabserver process (load OFF, run the script, save PLY), median (and range)
of $reps runs, methods interleaved, all under one Xvfb server; filter cost = median minus the
baseline's median (same load and save, empty script); "cost vs ours" = that method's filter
cost / MeshBridge's. The "baseline" rows describe the input as loaded. Counts after come from one
more run of the same script followed, in the same meshlabserver call, by MeshLab's own Compute
Topological Measures (non-manifold edges and vertices) and Select non Manifold Edges / Vertices
(selection flags read back from an ASCII PLY). Logs and outputs: $work/runs/.
ml_split ("Repair non Manifold Edges by splitting vertices"): MeshLab 2020.09's
vcg::tri::Clean::SplitManifoldComponents copies each edge-manifold component into a local
temporary CMeshO and then calls UpdateTopology::VertexFace on it without enabling that mesh's
optional VF adjacency, so it throws vcg::MissingComponentException (RequireVFAdjacency) on every
input; no -m mask or preceding filter can reach that local mesh (MeshLab issue #822). On large
inputs its component copying runs out of memory (std::bad_alloc) before it gets that far.
EOF
