#!/usr/bin/env bash
# Runs `meshbridge check --json` and `meshbridge repair` over every mesh (.obj .off .ply .stl, any
# case) found recursively in the given directories and prints a markdown table: faces, singular
# edges and vertices found, whether the repair holds every invariant (the repaired file, checked
# again, has no singular edge or vertex and the faces repair reported), and the time taken.
# Builds the command-line tool in build/release if it is not there. Exit status: 0 if every
# file was read and repaired with its invariants holding, 1 if any file failed, 2 on usage error.
# Usage: bash scripts/corpus_report.sh [DIR...]   (default: tests/data/realworld)
#        MESHBRIDGE=/path/to/meshbridge bash scripts/corpus_report.sh ...   (use that binary, no build)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dirs=("$@")
[ ${#dirs[@]} -gt 0 ] || dirs=("$root/tests/data/realworld")
for d in "${dirs[@]}"; do
  [ -d "$d" ] || { echo "corpus_report: $d is not a directory" >&2; exit 2; }
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

tool="${MESHBRIDGE:-$root/build/release/cli/meshbridge}"
if [ -z "${MESHBRIDGE:-}" ]; then
  jobs="$(nproc 2>/dev/null || echo 2)"
  # Keep an existing build's options (demo.sh also builds the plugin there); configure only once.
  {
    if [ ! -f "$root/build/release/CMakeCache.txt" ]; then
      cmake -S "$root" -B "$root/build/release" -DCMAKE_BUILD_TYPE=Release \
        -DMESHBRIDGE_BUILD_TESTS=OFF
    fi
    cmake --build "$root/build/release" --target meshbridge --parallel "$jobs"
  } >"$work/build.log" 2>&1 || {
    cat "$work/build.log" >&2
    echo "corpus_report: building meshbridge failed" >&2
    exit 2
  }
fi
[ -x "$tool" ] || { echo "corpus_report: no meshbridge binary at $tool (set MESHBRIDGE)" >&2; exit 2; }

# json_number FILE KEY.PATH: the value at KEY.PATH of the JSON report in FILE
# (docs/report-schema.md), parsed by Debian's python3.
json_number() {
  /usr/bin/python3 -c 'import json, sys
value = json.load(open(sys.argv[1]))
for key in sys.argv[2].split("."):
    value = value[key]
print(value)' "$1" "$2"
}
now() { date +%s.%N; }
seconds() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", b - a }'; }
# One line of a message, with the characters that would break a markdown table replaced.
cell() { head -n 1 "$1" | sed -e 's/^meshbridge: error: //' -e 's/|/\\|/g' | cut -c1-160; }

files=()
while IFS= read -r -d '' f; do
  files+=("$f")
done < <(find "${dirs[@]}" -type f \( -iname '*.obj' -o -iname '*.off' -o -iname '*.ply' \
  -o -iname '*.stl' \) -print0 | sort -z)
if [ ${#files[@]} -eq 0 ]; then
  echo "corpus_report: no .obj/.off/.ply/.stl files in ${dirs[*]}" >&2
  exit 1
fi

echo "| file | faces | singular edges | singular vertices | boundary edges | repaired, invariants hold | check s | repair s |"
echo "|---|---:|---:|---:|---:|---|---:|---:|"
failed=0
total_start="$(now)"
for f in "${files[@]}"; do
  name="$(printf '%s' "${f#"$root"/}" | sed 's/|/\\|/g')"
  before="$work/before.json"
  after="$work/after.json"
  report="$work/report.json"
  out="$work/repaired.obj"
  rm -f "$before" "$after" "$report" "$out"

  start="$(now)"
  status=0
  "$tool" check "$f" --json >"$before" 2>"$work/err" || status=$?
  check_time="$(seconds "$start" "$(now)")"
  if [ "$status" -gt 1 ]; then
    echo "| $name | - | - | - | - | FAIL: $(cell "$work/err") | $check_time | - |"
    failed=$((failed + 1))
    continue
  fi
  faces="$(json_number "$before" faces)"
  singular_edges="$(json_number "$before" singular_edges)"
  singular_vertices="$(json_number "$before" singular_vertices)"
  boundary_edges="$(json_number "$before" boundary_edges)"

  start="$(now)"
  status=0
  "$tool" repair "$f" "$out" --report "$report" >/dev/null 2>"$work/err" || status=$?
  repair_time="$(seconds "$start" "$(now)")"
  row="| $name | $faces | $singular_edges | $singular_vertices | $boundary_edges"
  if [ "$status" -ne 0 ]; then
    echo "$row | FAIL: repair: $(cell "$work/err") | $check_time | $repair_time |"
    failed=$((failed + 1))
    continue
  fi
  status=0
  "$tool" check "$out" --json >"$after" 2>"$work/err" || status=$?
  problems=()
  if [ "$status" -gt 1 ]; then
    problems+=("repaired file unreadable: $(cell "$work/err")")
  else
    faces_in="$(json_number "$report" faces_in)"
    faces_out="$(json_number "$report" faces_out)"
    set_aside="$(json_number "$report" faces_set_aside)"
    added="$(json_number "$report" faces_added_by_split)"
    [ "$faces_in" = "$faces" ] || problems+=("repair read $faces_in faces, check $faces")
    [ $((faces_out + set_aside)) -eq $((faces_in + added)) ] ||
      problems+=("faces out $faces_out + set aside $set_aside != in $faces_in + split $added")
    [ "$(json_number "$after" faces)" = "$faces_out" ] ||
      problems+=("repaired file has $(json_number "$after" faces) faces, not $faces_out")
    [ "$(json_number "$after" singular_edges)" = 0 ] ||
      problems+=("$(json_number "$after" singular_edges) singular edges left")
    [ "$(json_number "$after" singular_vertices)" = 0 ] ||
      problems+=("$(json_number "$after" singular_vertices) singular vertices left")
  fi
  if [ ${#problems[@]} -eq 0 ]; then
    split="$(json_number "$report" vertices_split)"
    components="$(json_number "$report" after.components)"
    echo "$row | yes ($faces_out faces, $split vertices split, $components components) | $check_time | $repair_time |"
  else
    echo "$row | FAIL: $(IFS=';'; echo "${problems[*]}" | sed 's/|/\\|/g') | $check_time | $repair_time |"
    failed=$((failed + 1))
  fi
done
echo
echo "${#files[@]} files, $((${#files[@]} - failed)) repaired with every invariant holding, $failed failed ($(seconds "$total_start" "$(now)") s)"
[ "$failed" -eq 0 ]
