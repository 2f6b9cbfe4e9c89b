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
is_png() {  # is_png FILE: starts with the 8-byte PNG signature
  [ "$(od -An -tx1 -N8 "$1" 2>/dev/null | tr -d ' \n')" = 89504e470d0a1a0a ]
}
png_size() {  # png_size FILE -> "WIDTHxHEIGHT" from the IHDR chunk (big-endian, bytes 16..23)
  local b
  read -ra b <<<"$(od -An -tu1 -j16 -N8 "$1")"
  echo "$(((b[0] << 24) | (b[1] << 16) | (b[2] << 8) | b[3]))x$(((b[4] << 24) | (b[5] << 16) |
    (b[6] << 8) | b[7]))"
}
pixels() {  # pixels FILE COLOUR -> N from "COLOUR pixels N" in a snapshot's output line
  grep -o "$2 pixels [0-9]*" "$1" | head -1 | cut -d' ' -f3
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
  expect_in "$work/err" "vertex 2 has a non-finite coordinate"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\nf 1 2 3\n' >"$work/repeat.obj"
  expect_exit 1 "$mb" check "$work/repeat.obj"
  expect_in "$work/err" "2 face records: 1 kept, 1 set aside (< 3 distinct corners)"
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
snapshot)
  expect_exit 1 "$mb" snapshot "$models/twocubes.obj" "$work/twocubes.png"
  expect_in "$work/out" "1 singular edges, 2 singular vertices, 0 boundary edges"
  is_png "$work/twocubes.png" || fail "twocubes.png is not a PNG"
  [ "$(png_size "$work/twocubes.png")" = 800x800 ] || fail "size: $(png_size "$work/twocubes.png")"
  [ "$(pixels "$work/out" red)" -gt 0 ] 2>/dev/null || fail "no red pixels: $(cat "$work/out")"
  [ "$(pixels "$work/out" green)" = 0 ] || fail "green pixels on a model without boundary"
  # Nothing on stderr: Qt's chatter is filtered (only "no legend" where no font renders).
  [ -z "$(grep -v "has no legend" "$work/err")" ] || fail "stderr not empty: $(cat "$work/err")"
  expect_exit 0 "$mb" snapshot "$models/icosphere.obj" "$work/ico.png" --size 321 --view x
  is_png "$work/ico.png" || fail "ico.png is not a PNG"
  [ "$(png_size "$work/ico.png")" = 321x321 ] || fail "--size 321: $(png_size "$work/ico.png")"
  [ "$(pixels "$work/out" red)" = 0 ] || fail "red pixels for icosphere: $(cat "$work/out")"
  [ "$(pixels "$work/out" green)" = 0 ] || fail "green pixels for icosphere"
  expect_exit 1 "$mb" snapshot "$models/cube_with_hole.obj" "$work/hole.png" --view=z --size=64
  [ "$(png_size "$work/hole.png")" = 64x64 ] || fail "--size=64: $(png_size "$work/hole.png")"
  [ "$(pixels "$work/out" green)" -gt 0 ] 2>/dev/null || fail "no green pixels for cube_with_hole"
  [ "$(pixels "$work/out" red)" = 0 ] || fail "red pixels for cube_with_hole"
  for view in iso x y z; do
    expect_exit 1 "$mb" snapshot "$models/prisms24.obj" "$work/p-$view.png" --view "$view" --size 99
    [ "$(pixels "$work/out" red)" -gt 0 ] 2>/dev/null || fail "no red pixels in prisms24, $view"
  done
  ls -a "$work" | grep -q tmp && fail "temporary file left behind"
  expect_exit 0 "$mb" --help
  expect_in "$work/out" "snapshot FILE OUT.png"
  ;;
snapshot_errors)
  expect_exit 2 "$mb" snapshot "$work/missing.obj" "$work/a.png"
  expect_in "$work/err" "cannot open"
  [ ! -e "$work/a.png" ] || fail "missing input left an output"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/range.obj"
  echo "previous content" >"$work/keep.png"
  expect_exit 2 "$mb" snapshot "$work/range.obj" "$work/keep.png"
  expect_in "$work/err" "out of range"
  [ "$(cat "$work/keep.png")" = "previous content" ] || fail "output overwritten on bad input"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/nodir/a.png"
  expect_in "$work/err" "nodir/a.png: cannot create a file in its directory"
  [ ! -e "$work/nodir" ] || fail "created a directory"
  mkdir "$work/locked"
  chmod 555 "$work/locked"
  if ! touch "$work/locked/probe" 2>/dev/null; then  # root writes anyway: nothing to test then
    expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/locked/a.png"
    expect_in "$work/err" "a.png: cannot create a file in its directory"
    [ -z "$(ls -A "$work/locked")" ] || fail "file left in the locked directory: $(ls -A "$work/locked")"
  fi
  chmod 755 "$work/locked"
  mkdir "$work/dir.png"  # the PNG is written, but cannot replace a directory: the temporary goes
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/dir.png"
  expect_in "$work/err" "cannot move the written file into place"
  ls -a "$work" | grep -q tmp && fail "temporary file left behind: $(ls -a "$work")"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --size 8
  expect_in "$work/err" "--size expects a whole number of pixels from 16 to 8192"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --view top
  expect_in "$work/err" "--view must be iso, x, y or z"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.jpg"
  expect_in "$work/err" "name it .png"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj"
  expect_in "$work/err" "usage: meshbridge snapshot FILE OUT.png"
  [ ! -e "$work/a.png" ] && [ ! -e "$work/a.jpg" ] || fail "an output was written on a usage error"
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
