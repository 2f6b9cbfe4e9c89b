#!/usr/bin/env bash
# Usage: cli_test.sh CASE MESHBRIDGE_BINARY MODELS_DIR
set -uo pipefail
case_name=$1
mb=$2
models=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}
# expect_exit CODE COMMAND...: runs COMMAND, checks its exit code; output in $work/out, $work/err.
expect_exit() {
  local want=$1
  shift
  "$@" >"$work/out" 2>"$work/err"
  local got=$?
  [ "$got" -eq "$want" ] || fail "'$*' exited $got, expected $want; stderr: $(cat "$work/err")"
}
expect_in() {  # expect_in FILE TEXT
  grep -qF -- "$2" "$1" || fail "'$2' not in $(basename "$1"): $(head -c 600 "$1")"
}
json_field() {  # json_field FILE KEY -> first number after "KEY":
  grep -o "\"$2\":[0-9-]*" "$1" | head -1 | cut -d: -f2
}

case "$case_name" in
check_exit_codes)
  expect_exit 0 "$mb" check "$models/icosphere.obj"
  expect_in "$work/out" "watertight yes"
  for m in twocubes hourglass bowtie book_of_three t_junction_rib plate_box_rib prisms24 moebius cube_with_hole; do
    expect_exit 1 "$mb" check "$models/$m.obj"
  done
  expect_exit 1 "$mb" check "$models/twocubes.obj"
  expect_in "$work/out" "singular edges: 1"
  expect_exit 2 "$mb" check "$work/missing.obj"
  expect_in "$work/err" "cannot open"
  expect_exit 2 "$mb" check
  expect_in "$work/err" "usage: meshbridge check FILE"
  expect_exit 2 "$mb" frobnicate
  expect_exit 0 "$mb" --help
  ;;
check_json)
  expect_exit 1 "$mb" check "$models/prisms24.obj" --json
  [ "$(json_field "$work/out" singular_edge_count)" = 79 ] || fail "prisms24 singular edges"
  [ "$(json_field "$work/out" faces)" = 120 ] || fail "prisms24 faces"
  [ "$(json_field "$work/out" duplicate_faces)" = "" ] || true
  expect_exit 1 "$mb" check "$models/hourglass.obj" --json
  expect_in "$work/out" '"pinch_vertices":[0]'
  ;;
compare_twocubes)
  expect_exit 0 "$mb" compare "$models/twocubes.obj"
  grep -E '^vertices +38 +16$' "$work/out" >/dev/null || fail "vertices row: $(cat "$work/out")"
  grep -E '^boundary edges +30 +0$' "$work/out" >/dev/null || fail "boundary row"
  grep -E '^components +10 +2$' "$work/out" >/dev/null || fail "components row"
  grep -E '^faces kept +24 +24$' "$work/out" >/dev/null || fail "faces row"
  expect_exit 0 "$mb" compare "$models/twocubes.obj" --json
  expect_in "$work/out" '"vertices_created":38'
  ;;
repair_canonical)
  # model faces vertices-after components-after
  while read -r m faces vertices components; do
    expect_exit 0 "$mb" repair "$models/$m.obj" "$work/$m.obj" --report "$work/$m.json"
    [ "$(json_field "$work/$m.json" faces_out)" = "$faces" ] || fail "$m faces_out"
    [ "$(json_field "$work/$m.json" vertices_out)" = "$vertices" ] || fail "$m vertices_out"
    [ "$(json_field "$work/$m.json" components_after)" = "$components" ] || fail "$m components"
    "$mb" check "$work/$m.obj" --json >"$work/after.json"
    [ "$(json_field "$work/after.json" singular_edge_count)" = 0 ] || fail "$m singular edges left"
    [ "$(json_field "$work/after.json" singular_vertex_count)" = 0 ] || fail "$m singular vertices left"
    [ "$(json_field "$work/after.json" faces)" = "$faces" ] || fail "$m faces on reload"
  done <<'TABLE'
twocubes 24 16 2
hourglass 8 8 2
bowtie 2 6 2
book_of_three 3 7 2
t_junction_rib 24 25 2
plate_box_rib 72 40 2
prisms24 120 144 24
icosphere 80 42 1
TABLE
  expect_exit 0 "$mb" check "$work/twocubes.obj"  # two closed cubes: no defect left
  expect_exit 0 "$mb" repair "$models/moebius.obj" "$work/m.obj" --cut-nonorientable --report "$work/m.json"
  [ "$(json_field "$work/m.json" nonorientable_components)" = 1 ] || fail "moebius non-orientable"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --pairing combinatorial --no-stitch --no-orient
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --pairing sideways
  expect_in "$work/err" "--pairing must be geometric or combinatorial"
  ;;
repair_formats)
  for ext in obj off ply; do
    expect_exit 0 "$mb" repair "$models/prisms24.obj" "$work/p.$ext"
    expect_exit 0 "$mb" check "$work/p.$ext" --json
    [ "$(json_field "$work/out" faces)" = 120 ] || fail "$ext faces"
    [ "$(json_field "$work/out" vertices)" = 144 ] || fail "$ext vertices"
    [ "$(json_field "$work/out" components)" = 24 ] || fail "$ext components"
  done
  ;;
stl_warning)
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.stl"
  expect_in "$work/err" "STL has no shared vertices"
  expect_exit 1 "$mb" check "$work/c.stl"   # welded back: the singular edge returns
  expect_in "$work/out" "singular edges: 1"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/s.stl" --separate 1e-4
  expect_in "$work/out" "separated 4 split vertex copies"
  expect_exit 0 "$mb" check "$work/s.stl"
  expect_in "$work/out" "watertight yes"
  ;;
bad_input)
  : >"$work/empty.obj"
  expect_exit 2 "$mb" check "$work/empty.obj"
  expect_in "$work/err" "file is empty"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/range.obj"
  expect_exit 2 "$mb" check "$work/range.obj"
  expect_in "$work/err" "vertex index 8 is out of range (the soup has 3 vertices)"
  printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$work/nan.obj"
  expect_exit 2 "$mb" check "$work/nan.obj"
  expect_in "$work/err" "declares 3 vertices but OpenMesh's reader read 2"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\nf 1 2 3\n' >"$work/repeat.obj"
  expect_exit 1 "$mb" check "$work/repeat.obj"
  expect_in "$work/err" "1 face record(s) with fewer than 3 distinct vertices were dropped"
  printf 'garbage\n' >"$work/garbage.obj"
  expect_exit 2 "$mb" check "$work/garbage.obj"
  expect_in "$work/err" "no polygons"
  printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' >"$work/range.off"
  expect_exit 2 "$mb" check "$work/range.off"
  expect_in "$work/err" "vertex index 5 is out of range"
  printf 'OFF\n300000000 1 0\n0 0 0\n' >"$work/huge.off"
  expect_exit 2 "$mb" check "$work/huge.off"
  expect_in "$work/err" "declares 300000000 vertices"
  printf 'solid x\n' >"$work/x.dxf"
  expect_exit 2 "$mb" check "$work/x.dxf"
  expect_in "$work/err" "unknown format"
  expect_exit 2 "$mb" check "$work"
  expect_in "$work/err" "is a directory"
  ;;
atomic_output)
  echo "previous content" >"$work/keep.obj"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/bad.obj"
  expect_exit 2 "$mb" repair "$work/bad.obj" "$work/keep.obj"
  [ "$(cat "$work/keep.obj")" = "previous content" ] || fail "output overwritten on error"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/nodir/out.obj"
  [ ! -e "$work/nodir" ] || fail "created a directory"
  ls -a "$work" | grep -q tmp && fail "temporary file left behind"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/keep.obj"
  expect_in "$work/keep.obj" "v "
  ;;
batch)
  mkdir -p "$work/in/sub"
  cp "$models/twocubes.obj" "$models/twocubes.off" "$work/in/"
  cp "$models/prisms24.obj" "$work/in/sub/"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --format ply
  expect_in "$work/out" "3 file(s), 3 repaired, 0 failed"
  expect_in "$work/out" "| sub/prisms24.obj | 120 | 79 | 38 | 120 | 24 | yes |"
  expect_in "$work/err" "[3/3]"
  [ -f "$work/res/twocubes.ply" ] && [ -f "$work/res/twocubes-off.ply" ] && [ -f "$work/res/sub/prisms24.ply" ] \
    || fail "batch outputs missing: $(ls -R "$work/res")"
  printf 'v 0 0 0\nf 1 2 3\n' >"$work/in/broken.obj"
  expect_exit 2 "$mb" batch "$work/in" "$work/res2" --json --quiet
  expect_in "$work/out" '"file":"broken.obj"'
  expect_in "$work/out" 'out of range'
  [ ! -s "$work/err" ] || fail "--quiet printed progress"
  ;;
*)
  echo "unknown case $case_name" >&2
  exit 2
  ;;
esac

if [ "$failures" -ne 0 ]; then
  echo "$case_name: $failures failure(s)" >&2
  exit 1
fi
echo "$case_name: ok"
