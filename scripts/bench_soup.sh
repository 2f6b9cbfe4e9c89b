#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Per-face-vertex soups against the indexed file (DESIGN 8a, soups; issue "No new defects"):
# `meshbridge check` and `meshbridge repair` on the 1M checkerboard written as an indexed OBJ
# (in file order and with its faces shuffled) and as a per-face-vertex OBJ (the same two orders),
# each its own process, side by side in one run: ROUNDS rounds (default 5), the order of the eight
# runs shuffled in each; the best wall and the best CPU time (user + sys) of each, their ratios
# to the indexed file's, and each soup's ratio to the indexed file in the same face order (a
# shuffled face order costs every stage after reading, indexed or not).
#
# Usage: scripts/bench_soup.sh BUILD_DIR   (BUILD_DIR has cli/meshbridge and
#        bench/meshbridge-io-bench)
# Environment: ROUNDS, DATA_DIR (default /tmp/meshbridge_bench_soup).
set -euo pipefail

build="${1:?usage: scripts/bench_soup.sh BUILD_DIR}"
meshbridge="$build/cli/meshbridge"
iobench="$build/bench/meshbridge-io-bench"
data="${DATA_DIR:-/tmp/meshbridge_bench_soup}"
rounds="${ROUNDS:-5}"
for tool in "$meshbridge" "$iobench" /usr/bin/time; do
  [ -x "$tool" ] || { echo "bench_soup: missing $tool" >&2; exit 1; }
done
mkdir -p "$data"
[ -f "$data/checkerboard_1m_soup_shuffled.obj" ] || "$iobench" make-soup "$data" >&2
if [ ! -f "$data/checkerboard_1m_shuffled.obj" ]; then  # the indexed file, faces shuffled
  { grep -v '^f ' "$data/checkerboard_1m.obj"
    grep '^f ' "$data/checkerboard_1m.obj" | shuf --random-source=<(yes 1); } \
    >"$data/checkerboard_1m_shuffled.obj"
fi
tmp="$(mktemp -d /tmp/meshbridge_bench_soup_run.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT

files="checkerboard_1m checkerboard_1m_shuffled checkerboard_1m_soup checkerboard_1m_soup_shuffled"
for round in $(seq "$rounds"); do
  for job in $(for f in $files; do echo "check:$f"; echo "repair:$f"; done | shuf); do
    what="${job%%:*}"
    file="${job#*:}"
    if [ "$what" = check ]; then
      cmd=("$meshbridge" check "$data/$file.obj")
    else
      cmd=("$meshbridge" repair "$data/$file.obj" "$tmp/out.ply")
    fi
    # check exits 1 on a defective file: that is its answer, not a failure.
    /usr/bin/time -f "%e %U %S" -o "$tmp/time" "${cmd[@]}" >/dev/null 2>&1 || [ $? -eq 1 ]
    read -r wall user sys < <(tail -n 1 "$tmp/time")
    awk -v w="$what" -v f="$file" -v t="$wall" -v u="$user" -v s="$sys" \
      'BEGIN { print w, f, t, u + s }' >>"$tmp/raw"
  done
done
echo "| command | file | best wall s | best CPU s | wall / indexed | CPU / indexed | wall (CPU) / indexed in the same order |"
echo "|---|---|---|---|---|---|---|"
for what in check repair; do
  awk -v what="$what" -v files="$files" '
    $1 == what {
      if (!($2 in wall) || $3 < wall[$2]) wall[$2] = $3
      if (!($2 in cpu) || $4 < cpu[$2]) cpu[$2] = $4
    }
    END {
      n = split(files, f, " ")
      for (i = 1; i <= n; ++i) {
        same = f[i] ~ /shuffled/ ? f[2] : f[1]  # the indexed file in the same face order
        printf "| %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f (%.2f) |\n", what, f[i], wall[f[i]],
               cpu[f[i]], wall[f[i]] / wall[f[1]], cpu[f[i]] / cpu[f[1]],
               wall[f[i]] / wall[same], cpu[f[i]] / cpu[same]
      }
    }' "$tmp/raw"
done
echo "($rounds rounds, runs shuffled in each; $(nproc) CPUs)"
