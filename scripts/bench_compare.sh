#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Two builds of the CLI side by side (a change against its baseline): `check FILE` and
# `repair FILE OUT.ply` for each FILE with each binary, each its own process, ROUNDS rounds
# (default 5), the order of the runs shuffled in each round; the best wall and the best CPU time
# (user + sys) of each, and the ratio new / base.
#
# Usage: scripts/bench_compare.sh BASE_MESHBRIDGE NEW_MESHBRIDGE FILE...
# Environment: ROUNDS.
set -euo pipefail

base="${1:?usage: scripts/bench_compare.sh BASE NEW FILE...}"
new="${2:?usage: scripts/bench_compare.sh BASE NEW FILE...}"
shift 2
[ $# -gt 0 ] || { echo "bench_compare: no FILE" >&2; exit 2; }
rounds="${ROUNDS:-5}"
tmp="$(mktemp -d /tmp/meshbridge_bench_compare.XXXXXX)"
trap 'rm -rf "$tmp"' EXIT

for round in $(seq "$rounds"); do
  jobs=()
  for file in "$@"; do
    for build in base new; do
      for what in check repair; do
        jobs+=("$build:$what:$file")
      done
    done
  done
  for job in $(printf '%s\n' "${jobs[@]}" | shuf); do
    build="${job%%:*}"
    rest="${job#*:}"
    what="${rest%%:*}"
    file="${rest#*:}"
    tool="$base"
    [ "$build" = new ] && tool="$new"
    if [ "$what" = check ]; then
      cmd=("$tool" check "$file")
    else
      cmd=("$tool" repair "$file" "$tmp/out.ply")
    fi
    # check exits 1 on a defective file: that is its answer, not a failure.
    /usr/bin/time -f "%e %U %S" -o "$tmp/time" "${cmd[@]}" >/dev/null 2>&1 || [ $? -eq 1 ]
    read -r wall user sys < <(tail -n 1 "$tmp/time")
    awk -v b="$build" -v w="$what" -v f="$(basename "$file")" -v t="$wall" -v u="$user" \
      -v s="$sys" 'BEGIN { print b, w, f, t, u + s }' >>"$tmp/raw"
  done
done
echo "| command | file | base wall s | new wall s | new/base wall | base CPU s | new CPU s | new/base CPU |"
echo "|---|---|---|---|---|---|---|---|"
awk '
  {
    key = $2 " " $3
    if (!(key in seen)) { seen[key] = 1; order[++n] = key }
    w = $1 " " key
    if (!(w in wall) || $4 < wall[w]) wall[w] = $4
    if (!(w in cpu) || $5 < cpu[w]) cpu[w] = $5
  }
  END {
    for (i = 1; i <= n; ++i) {
      k = order[i]; split(k, p, " ")
      printf "| %s | %s | %.2f | %.2f | %.3f | %.2f | %.2f | %.3f |\n", p[1], p[2],
             wall["base " k], wall["new " k], wall["new " k] / wall["base " k],
             cpu["base " k], cpu["new " k], cpu["new " k] / cpu["base " k]
    }
  }' "$tmp/raw"
echo "($rounds rounds, runs shuffled in each; $(nproc) CPUs)"
