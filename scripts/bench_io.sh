#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The whole-process benchmark (issue 13, DESIGN.md section 9 "whole process, file to file"):
# every tool reads (and writes) the same file as its own process, side by side in one run:
#
#   floor              mmap + one pass (text: every number through std::from_chars)
#   MeshBridge parse   read_soup alone (meshbridge-parse-bench parse: built with the CLI's
#                      operator new, so it allocates as `meshbridge check` does)
#   OpenMesh read      stock OpenMesh::IO::read_mesh into a PolyMesh
#   meshbridge check   the CLI: read + detect + print
#   OpenMesh r+w       read_mesh + write_mesh (binary PLY/STL)
#   meshbridge repair  the CLI: read + repair + write (binary PLY/STL by default)
#   meshlabserver      MeshLab 2020.09 load + save (under xvfb-run; only meshlabserver is timed)
#
# on a 3D checkerboard of 1.05M triangles, a clean torus of 1.05M and the 5M checkerboard, each
# as .obj .off .ply .stl. Every row runs ROUNDS times (default 3) interleaved with the others;
# the table keeps the best wall time, the best CPU time (user + sys) and the largest peak RSS.
# MeshBridge uses every CPU it may (at most 8) by default; parse, check and repair also run with
# MESHBRIDGE_THREADS=1 (one thread, both cores free) and pinned to one core (taskset -c 0).
# Ratios are to OpenMesh read (check, parse) and OpenMesh read + write (repair, meshlabserver).
# Also prints the in-process split (meshbridge-parse-bench split: parse vs floor alternating 9
# times, then detect, repair, write, best of 3).
#
# Usage: scripts/bench_io.sh BUILD_DIR OUT.md [--quick]   (BUILD_DIR has cli/meshbridge,
#        bench/meshbridge-io-bench and bench/meshbridge-parse-bench; --quick: 1M files only, PLY
#        and STL, one round)
# Environment: ROUNDS, DATA_DIR (default /tmp/meshbridge_bench_io), FORMATS, MODELS.
set -euo pipefail

build="${1:?usage: scripts/bench_io.sh BUILD_DIR OUT.md [--quick]}"
out="${2:?usage: scripts/bench_io.sh BUILD_DIR OUT.md [--quick]}"
quick="${3:-}"
meshbridge="$build/cli/meshbridge"
iobench="$build/bench/meshbridge-io-bench"
parsebench="$build/bench/meshbridge-parse-bench"
data="${DATA_DIR:-/tmp/meshbridge_bench_io}"
rounds="${ROUNDS:-3}"
formats="${FORMATS:-obj off ply stl}"
models="${MODELS:-checkerboard_1m torus_1m checkerboard_5m}"
if [ "$quick" = "--quick" ]; then
  rounds=1
  formats="ply stl"
  models="checkerboard_1m torus_1m"
fi
for tool in "$meshbridge" "$iobench" "$parsebench" /usr/bin/time; do
  [ -x "$tool" ] || { echo "bench_io: missing $tool" >&2; exit 1; }
done
have_meshlab=0
if command -v meshlabserver >/dev/null && command -v xvfb-run >/dev/null; then
  have_meshlab=1
fi
mkdir -p "$data"
if [ ! -f "$data/checkerboard_5m.stl" ]; then
  echo "bench_io: writing the benchmark files to $data" >&2
  "$iobench" make "$data" >&2
fi
tmp="$(mktemp -d /tmp/meshbridge_bench_io_run.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT

# run NAME CMD...: appends "NAME wall cpu rss_kb" to $tmp/raw (a failed run is recorded as such).
run() {
  local name="$1"
  shift
  local status=0
  sync  # the previous run's written file is flushed outside this run's timing
  /usr/bin/time -o "$tmp/time" -f "%e %U %S %M" "$@" >/dev/null 2>"$tmp/err" || status=$?
  # Exit 1 of `meshbridge check` means "repair would change it", a successful run.
  if [ "$status" -le 1 ] && [ -s "$tmp/time" ]; then
    read -r wall user sys rss < <(tail -n 1 "$tmp/time")
    echo "$name $wall $(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }') $rss" >>"$tmp/raw"
  else
    echo "$name failed" >>"$tmp/raw"
    echo "bench_io: $name failed: $(tail -n 2 "$tmp/err" | tr '\n' ' ')" >&2
  fi
}
# The X server is started outside the timing: only meshlabserver is measured.
run_meshlab() {
  local name="$1" in="$2" target="$3"
  sync
  xvfb-run -a /usr/bin/time -o "$tmp/time" -f "%e %U %S %M" meshlabserver -i "$in" -o "$target" \
    >"$tmp/err" 2>&1 || { echo "$name failed" >>"$tmp/raw"; return; }
  read -r wall user sys rss < <(tail -n 1 "$tmp/time")
  echo "$name $wall $(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }') $rss" >>"$tmp/raw"
}

: >"$tmp/raw"
: >"$tmp/split"
for model in $models; do
  for fmt in $formats; do
    f="$data/$model.$fmt"
    [ -f "$f" ] || continue
    echo "bench_io: $model.$fmt" >&2
    for ((r = 0; r < rounds; ++r)); do
      run "$model.$fmt floor" "$parsebench" floor "$f"
      run "$model.$fmt parse" "$parsebench" parse "$f"
      run "$model.$fmt parse_1thread" env MESHBRIDGE_THREADS=1 "$parsebench" parse "$f"
      run "$model.$fmt openmesh_read" "$iobench" openmesh-read "$f"
      # A process that follows a large one pays more for its fresh pages on this kind of
      # machine: the variants after OpenMesh take turns being first (rotated by round).
      for ((v = 0; v < 3; ++v)); do
        case $(((v + r) % 3)) in
          0) run "$model.$fmt check" "$meshbridge" check "$f" ;;
          1) run "$model.$fmt check_1thread" env MESHBRIDGE_THREADS=1 "$meshbridge" check "$f" ;;
          2) run "$model.$fmt check_1core" taskset -c 0 "$meshbridge" check "$f" ;;
        esac
      done
      run "$model.$fmt openmesh_rw" "$iobench" openmesh-readwrite "$f" "$tmp/om.$fmt"
      for ((v = 0; v < 3; ++v)); do
        case $(((v + r) % 3)) in
          0) run "$model.$fmt repair" "$meshbridge" repair "$f" "$tmp/mb.$fmt" ;;
          1) run "$model.$fmt repair_1thread" env MESHBRIDGE_THREADS=1 "$meshbridge" repair "$f" \
            "$tmp/mb.$fmt" ;;
          2) run "$model.$fmt repair_1core" taskset -c 0 "$meshbridge" repair "$f" "$tmp/mb.$fmt" ;;
        esac
      done
      if [ "$have_meshlab" = 1 ] && [ "$model" != checkerboard_5m ]; then
        run_meshlab "$model.$fmt meshlab" "$f" "$tmp/ml.$fmt"
      fi
      rm -f "$tmp/om.$fmt" "$tmp/mb.$fmt" "$tmp/ml.$fmt"
    done
    "$parsebench" split "$f" 3 >>"$tmp/split" 2>&1 || echo "split $f failed" >>"$tmp/split"
  done
done

load="$(cut -d' ' -f1-3 /proc/loadavg)"
{
  echo "## Whole process, file to file ($(date -u '+%Y-%m-%d %H:%M UTC'))"
  echo
  echo "Machine: nproc $(nproc), $(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo);" \
    "load average at the end $load (other jobs share the machine: compare the ratios, which are" \
    "measured side by side, not the absolute times). Each row: best of $rounds interleaved" \
    "runs; CPU = user + sys; peak = largest resident set. *1 core* = pinned with taskset -c 0;" \
    "MeshBridge rows without a note use both cores (the default); *MESHBRIDGE_THREADS=1* = one" \
    "thread." \
    "meshlabserver: MeshLab 2020.09 under xvfb-run (X start not timed; not run on 5M)."
  echo
  echo "| file | step | wall s | CPU s | peak MiB | wall / OpenMesh | CPU / OpenMesh | peak / OpenMesh |"
  echo "|---|---|---:|---:|---:|---:|---:|---:|"
  awk '
    $3 != "failed" {
      key = $1 " " $2
      if (!(key in wall) || $3 < wall[key]) wall[key] = $3
      if (!(key in cpu) || $4 < cpu[key]) cpu[key] = $4
      if (!(key in rss) || $5 > rss[key]) rss[key] = $5
      if (!(key in seen)) { seen[key] = 1; order[++n] = key }
    }
    END {
      split("floor parse parse_1thread openmesh_read check check_1thread check_1core openmesh_rw repair repair_1thread repair_1core meshlab", steps, " ")
      names["floor"] = "mmap + from_chars floor"; names["parse"] = "MeshBridge parse (read_soup)"
      names["openmesh_read"] = "OpenMesh read_mesh"; names["check"] = "meshbridge check"
      names["check_1core"] = "meshbridge check, 1 core"; names["openmesh_rw"] = "OpenMesh read + write"
      names["repair"] = "meshbridge repair IN OUT"; names["repair_1core"] = "meshbridge repair, 1 core"
      names["meshlab"] = "meshlabserver load + save"
      names["parse_1thread"] = "MeshBridge parse, MESHBRIDGE_THREADS=1"
      names["check_1thread"] = "meshbridge check, MESHBRIDGE_THREADS=1"
      names["repair_1thread"] = "meshbridge repair, MESHBRIDGE_THREADS=1"
      base["parse_1thread"] = "openmesh_read"; base["check_1thread"] = "openmesh_read"
      base["repair_1thread"] = "openmesh_rw"
      base["floor"] = "openmesh_read"; base["parse"] = "openmesh_read"; base["openmesh_read"] = "openmesh_read"
      base["check"] = "openmesh_read"; base["check_1core"] = "openmesh_read"
      base["openmesh_rw"] = "openmesh_rw"; base["repair"] = "openmesh_rw"
      base["repair_1core"] = "openmesh_rw"; base["meshlab"] = "openmesh_rw"
      for (i = 1; i <= n; ++i) { split(order[i], kf, " "); if (!(kf[1] in files)) { files[kf[1]] = 1; forder[++nf] = kf[1] } }
      for (j = 1; j <= nf; ++j) {
        f = forder[j]
        for (s = 1; s <= 12; ++s) {
          st = steps[s]; key = f " " st; b = f " " base[st]
          if (!(key in wall)) continue
          rw = (b in wall) && wall[b] > 0 ? sprintf("%.2f", wall[key] / wall[b]) : "-"
          rc = (b in cpu) && cpu[b] > 0 ? sprintf("%.2f", cpu[key] / cpu[b]) : "-"
          rm = (b in rss) && rss[b] > 0 ? sprintf("%.2f", rss[key] / rss[b]) : "-"
          printf "| %s | %s | %.2f | %.2f | %.0f | %s | %s | %s |\n", f, names[st], wall[key], cpu[key], rss[key] / 1024, rw, rc, rm
        }
      }
    }' "$tmp/raw"
  echo
  echo "In one process (meshbridge-parse-bench split): parse next to its floor, alternating 9 times"
  echo "(fastest of each, medians in brackets; parse with the default threads, and with one),"
  echo "then the parse / compute / write split of \`repair\`, best of 3 (detect is the report"
  echo "\`check\` prints)."
  echo
  sed 's/^/    /' "$tmp/split"
} >"$out"
cat "$out"
