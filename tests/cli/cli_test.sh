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
json_tool="$(dirname "$0")/report_json.py"
# json_field FILE KEY.PATH -> the value at KEY.PATH (e.g. after.components); the whole output is
# parsed and validated against docs/report-schema.json first, so invalid JSON fails the test.
json_field() {
  /usr/bin/python3 "$json_tool" get "$1" "$2" || fail "JSON in $(basename "$1") rejected (above)"
}
# json_line_field FILE N KEY.PATH -> the same on line N (0-based) of JSON Lines output.
json_line_field() {
  /usr/bin/python3 "$json_tool" get-line "$1" "$2" "$3" || fail "JSON line $2 of $(basename "$1") rejected"
}
# json_lines FILE -> number of lines, every one parsed and validated.
json_lines() {
  /usr/bin/python3 "$json_tool" validate-lines "$1" || fail "JSON Lines in $(basename "$1") rejected"
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

# write_crossing_obj FILE: two unit cubes as quads, the second moved by (0.5, 0.5, 0.5): its three
# low faces cross the first one's three high faces, two each.
write_crossing_obj() {
  cat >"$1" <<'OBJ'
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
v 0 0 1
v 1 0 1
v 0 1 1
v 1 1 1
v 0.5 0.5 0.5
v 1.5 0.5 0.5
v 0.5 1.5 0.5
v 1.5 1.5 0.5
v 0.5 0.5 1.5
v 1.5 0.5 1.5
v 0.5 1.5 1.5
v 1.5 1.5 1.5
f 1 3 4 2
f 5 6 8 7
f 1 2 6 5
f 3 7 8 4
f 1 5 7 3
f 2 4 8 6
f 9 11 12 10
f 13 14 16 15
f 9 10 14 13
f 11 15 16 12
f 9 13 15 11
f 10 12 16 14
OBJ
}
# violet_in FILE [GEOMETRY] -> pixels of FILE (or of that part) with blue - green >= 100: what
# snapshot counts as violet (self-intersecting faces), since nothing else it draws has blue above
# green (grey has R = G = B; red, green and black none of it).
violet_in() {
  convert "$1" ${2:+-crop "$2" +repage} -separate -delete 0 -compose minus_dst -composite \
    -threshold 39% -format '%[fx:round(mean*w*h)]' info:
}

case "$case_name" in
check_exit_codes)
  expect_exit 0 "$mb" check "$models/icosphere.obj"
  expect_in "$work/out" "watertight yes"
  # check exits 1 exactly when repair would change the mesh (DESIGN 8a: check predicts repair).
  for m in twocubes hourglass bowtie book_of_three t_junction_rib plate_box_rib prisms24 moebius; do
    expect_exit 1 "$mb" check "$models/$m.obj"
    grep -q "^repair would: " "$work/out" || fail "$m: no 'repair would:' line"
    "$mb" repair "$models/$m.obj" "$work/predicted.obj" >"$work/repaired.txt" || fail "$m: repair"
    copies=$(sed -n 's/^repair would: .*make \([0-9]*\) vertex cop.*/\1/p' "$work/out")
    expect_in "$work/repaired.txt" "(${copies:-0} cop"
  done
  # The forecast names the cause of a topology change as repair's report does.
  expect_exit 1 "$mb" check "$models/moebius.obj"
  expect_in "$work/out" "cut 2 sides open, change the topology (Euler characteristic) of 1 component (1 where sides are cut for orientation)"
  # An open box with nothing to close: defects listed, but repair would leave it as it is.
  expect_exit 0 "$mb" check "$models/cube_with_hole.obj"
  expect_in "$work/out" "boundary edges: 4"
  expect_in "$work/out" "repair would change nothing (4 boundary edges stay open)"
  "$mb" repair "$models/cube_with_hole.obj" "$work/hole.obj" >/dev/null || fail "repair of cube_with_hole"
  cmp -s <(grep -E '^(v|f) ' "$models/cube_with_hole.obj") <(grep -E '^(v|f) ' "$work/hole.obj") ||
    fail "repair changed cube_with_hole, which check said it would not"
  expect_exit 1 "$mb" check "$models/twocubes.obj"
  expect_in "$work/out" "singular edges: 1"
  expect_exit 2 "$mb" check "$work/missing.obj"
  expect_in "$work/err" "meshbridge check: error: $work/missing.obj: cannot read: no such file"
  # A face record with no corner (OFF "0") is a face of the file set aside: a defect, as one
  # with 1 or 2 corners is (check exits 1, batch calls the file repaired, not clean).
  printf 'OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n0\n' \
    >"$work/cornerless.off"
  expect_exit 1 "$mb" check --json "$work/cornerless.off"
  [ "$(json_field "$work/out" faces)/$(json_field "$work/out" faces_set_aside)" = 5/1 ] ||
    fail "check --json of a face record without corners: faces/faces_set_aside"
  [ "$(json_field "$work/out" has_defects)" = true ] || fail "cornerless record: has_defects"
  mkdir -p "$work/cornerless_in" && cp "$work/cornerless.off" "$work/cornerless_in/"
  expect_exit 0 "$mb" batch "$work/cornerless_in" "$work/cornerless_out" --json
  [ "$(json_line_field "$work/out" 0 status)/$(json_line_field "$work/out" 0 faces_in)" = \
    repaired/5 ] || fail "batch of a face record without corners: status/faces_in"
  expect_exit 0 "$mb" check "$work/cornerless_out/cornerless.off"
  # With --json, stdout still holds one object a script can parse: the failure and its reason.
  expect_exit 2 "$mb" check --json "$work/missing.obj"
  [ "$(json_field "$work/out" status)" = failed ] || fail "check --json of a missing file: status"
  [ "$(json_field "$work/out" reason)" = "$work/missing.obj: cannot read: no such file" ] ||
    fail "check --json of a missing file: reason"
  printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' >"$work/short.off"
  expect_exit 2 "$mb" check --json "$work/short.off"
  expect_in "$work/out" '"reason":"'"$work"'/short.off: OFF vertex 3 of 3: expected 3 numbers'
  expect_in "$work/err" "meshbridge check: error: $work/short.off: OFF vertex 3 of 3"
  expect_exit 2 "$mb" check
  expect_in "$work/err" "meshbridge check: error: FILE is required (see \`meshbridge check --help\`)"
  expect_exit 2 "$mb" frobnicate
  expect_exit 0 "$mb" --help
  mkdir -p "$work/a_folder"
  expect_exit 2 "$mb" repair "$models/icosphere.obj" "$work/a_folder"
  expect_in "$work/err" "$work/a_folder: cannot write: it is a folder"
  MESHBRIDGE_THREADS=abc expect_exit 2 "$mb" check "$models/icosphere.obj"
  expect_in "$work/err" "meshbridge: error: MESHBRIDGE_THREADS=abc: expected a whole number >= 1 or 'auto'"
  MESHBRIDGE_THREADS=2 expect_exit 0 "$mb" check "$models/icosphere.obj"
  MESHBRIDGE_PROGRESS_DELAY=x expect_exit 2 "$mb" check "$models/icosphere.obj"
  expect_in "$work/err" "meshbridge: error: MESHBRIDGE_PROGRESS_DELAY=x: expected seconds"
  MESHBRIDGE_PROGRESS_DELAY=0.5 expect_exit 0 "$mb" check "$models/icosphere.obj"
  # An STL facet with one point three times is set aside; the point stays as an isolated vertex
  # of an indexed output, which is listed, not a defect: check of the repaired file exits 0.
  {
    echo "solid t"
    for f in "0 0 0|0 1 0|1 0 0" "0 0 0|1 0 0|0 0 1" "0 0 0|0 0 1|0 1 0" "1 0 0|0 1 0|0 0 1" \
             "5 5 5|5 5 5|5 5 5"; do
      echo " facet normal 0 0 0"; echo "  outer loop"
      IFS='|' read -r a b c <<<"$f"
      printf '   vertex %s\n' "$a" "$b" "$c"
      echo "  endloop"; echo " endfacet"
    done
    echo "endsolid t"
  } >"$work/point.stl"
  expect_exit 1 "$mb" check "$work/point.stl"
  expect_in "$work/out" "faces set aside (< 3 distinct vertices): 1"
  for ext in ply obj off; do
    expect_exit 0 "$mb" repair "$work/point.stl" "$work/point_out.$ext"
    expect_exit 0 "$mb" check "$work/point_out.$ext"
    expect_in "$work/out" "isolated vertices: 1"
    expect_in "$work/out" "watertight yes"
  done
  ;;
check_json)
  expect_exit 1 "$mb" check "$models/prisms24.obj" --json
  [ "$(json_field "$work/out" singular_edges)" = 79 ] || fail "prisms24 singular edges"
  [ "$(json_field "$work/out" singular_vertices)" = 38 ] || fail "prisms24 singular vertices"
  [ "$(json_field "$work/out" faces)" = 120 ] || fail "prisms24 faces"
  [ "$(json_field "$work/out" duplicate_faces)" = 30 ] || fail "prisms24 duplicate faces"
  [ "$(json_field "$work/out" file)" = "$models/prisms24.obj" ] || fail "prisms24 file"
  [ "$(json_field "$work/out" schema_version)" = 3 ] || fail "schema_version"
  [ "$(json_field "$work/out" kind)" = check ] || fail "kind"
  [ "$(json_field "$work/out" read.declared_faces)" = 120 ] || fail "read.declared_faces"
  [ "$(json_field "$work/out" read.faces_kept)" = 120 ] || fail "read.faces_kept"
  grep -q '"elements"' "$work/out" && fail "element lists without --elements"
  [ "$(wc -l <"$work/out")" = 1 ] || fail "check --json is not one line"
  expect_exit 1 "$mb" check "$models/prisms24.obj" --json --elements
  [ "$(json_field "$work/out" 'elements.singular_edges#')" = 79 ] || fail "79 listed singular edges"
  [ "$(json_field "$work/out" singular_edges)" = 79 ] || fail "count with --elements"
  expect_exit 1 "$mb" check "$models/hourglass.obj" --json --elements
  [ "$(json_field "$work/out" elements.pinch_vertices)" = "[0]" ] || fail "hourglass pinch vertex"
  [ "$(json_field "$work/out" pinch_vertices)" = 1 ] || fail "hourglass pinch count"
  expect_exit 0 "$mb" check "$models/icosphere.obj" --json
  [ "$(json_field "$work/out" watertight)" = true ] || fail "icosphere watertight"
  [ "$(json_field "$work/out" has_defects)" = false ] || fail "icosphere has_defects"
  # What reading passed over is a warning of check too, and counted in its "read" object:
  # bytes after a binary PLY's last element, an OBJ l/p without an index.
  { printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n'
    printf 'property float y\nproperty float z\nelement face 1\n'
    printf 'property list uchar int vertex_indices\nend_header\n'
    /usr/bin/python3 -c 'import struct,sys; sys.stdout.buffer.write(struct.pack("<9fB3i", 0,0,0, 1,0,0, 0,1,0, 3, 0,1,2) + bytes(13))'
  } >"$work/tail.ply"
  expect_exit 1 "$mb" check "$work/tail.ply" --json
  expect_in "$work/err" "meshbridge: warning: $work/tail.ply: 1 face record: all kept; 13 bytes after the end of the mesh not read (padding, or items a false count leaves out)"
  [ "$(json_field "$work/out" read.trailing_bytes)" = 13 ] || fail "read.trailing_bytes"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl\np\n' >"$work/empty_lp.obj"
  expect_exit 1 "$mb" check "$work/empty_lp.obj" --json
  expect_in "$work/err" "2 records holding no face skipped"
  [ "$(json_field "$work/out" read.empty_records)" = 2 ] || fail "read.empty_records"
  # Faults among what the reader reads past: check names them as repair does.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/9 2/1 3/1\n' >"$work/bad_vt.obj"
  expect_exit 0 "$mb" check "$work/bad_vt.obj"  # one triangle: repair would change nothing
  expect_in "$work/err" "meshbridge: warning: $work/bad_vt.obj: OBJ texture coordinate (vt) or normal (vn) indices the file has no record for, on 3 corners"
  printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0 255 9\n' >"$work/junk.off"
  expect_exit 0 "$mb" check "$work/junk.off"  # one triangle: repair would change nothing
  expect_in "$work/err" "OFF values after a face's corners that are no colour (not 1, 3 or 4 numbers), on 1 face line"
  # Words that are no number after an OFF vertex or face, and colours clamped into range: warned
  # by check, and by repair, which writes the clamped colour.
  printf 'COFF
3 1 0
0 0 0 300 0 0
1 0 0 abc
0 1 0
3 0 1 2 hello
' >"$work/words.off"
  expect_exit 0 "$mb" check "$work/words.off"  # one triangle: repair would change nothing
  expect_in "$work/err" "meshbridge: warning: $work/words.off: OFF words after a vertex's numbers that are no number (read past), on 1 vertex line"
  expect_in "$work/err" "OFF words after a face's numbers that are no number (read past), on 1 face line"
  expect_in "$work/err" "OFF vertex colour values outside 0-1 (or 0-255) or not finite, clamped to the range, on 1 vertex"
  expect_exit 0 "$mb" repair "$work/words.off" "$work/words_out.off"
  expect_in "$work/err" "clamped to the range, on 1 vertex: written clamped"
  expect_exit 0 "$mb" check "$models/icosphere.obj"
  [ ! -s "$work/err" ] || fail "warnings on a clean file: $(cat "$work/err")"
  ;;
compare_twocubes)
  expect_exit 0 "$mb" compare "$models/twocubes.obj"
  grep -E '^vertices +38 +16$' "$work/out" >/dev/null || fail "vertices row: $(cat "$work/out")"
  grep -E '^boundary edges +30 +0$' "$work/out" >/dev/null || fail "boundary row"
  grep -E '^components +10 +2$' "$work/out" >/dev/null || fail "components row"
  grep -E '^faces kept +24 +24$' "$work/out" >/dev/null || fail "faces row"
  expect_exit 0 "$mb" compare "$models/twocubes.obj" --json
  [ "$(json_field "$work/out" stock.vertices)" = 38 ] || fail "compare stock vertices"
  [ "$(json_field "$work/out" bridged.vertices)" = 16 ] || fail "compare bridged vertices"
  [ "$(json_field "$work/out" stock.components)" = 10 ] || fail "compare stock components"
  [ "$(json_field "$work/out" faces)" = 24 ] || fail "compare faces"
  # Records with fewer than 3 distinct corners: set aside by MeshBridge (and said so), dropped
  # by OpenMesh; one row for both, not "lost" for MeshBridge.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\nf\n' >"$work/aside.obj"
  expect_exit 0 "$mb" compare "$work/aside.obj"
  grep -E '^faces not loaded +2 +2$' "$work/out" >/dev/null || fail "not loaded row: $(cat "$work/out")"
  expect_in "$work/out" "MeshBridge sets aside faces with fewer than 3 distinct corners and counts them"
  expect_in "$work/err" "2 set aside (< 3 distinct corners; 1 without any corner)"
  ;;
repair_canonical)
  # model faces vertices-after components-after
  while read -r m faces vertices components; do
    expect_exit 0 "$mb" repair "$models/$m.obj" "$work/$m.obj" --report "$work/$m.json"
    [ "$(json_field "$work/$m.json" faces_out)" = "$faces" ] || fail "$m faces_out"
    [ "$(json_field "$work/$m.json" vertices_out)" = "$vertices" ] || fail "$m vertices_out"
    [ "$(json_field "$work/$m.json" after.components)" = "$components" ] || fail "$m components"
    [ "$(json_field "$work/$m.json" file)" = "$models/$m.obj" ] || fail "$m report file"
    [ "$(json_field "$work/$m.json" output)" = "$work/$m.obj" ] || fail "$m report output"
    "$mb" check "$work/$m.obj" --json >"$work/after.json"
    [ "$(json_field "$work/after.json" singular_edges)" = 0 ] || fail "$m singular edges left"
    [ "$(json_field "$work/after.json" singular_vertices)" = 0 ] || fail "$m singular vertices left"
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
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/e.obj" --report "$work/e.json" --elements
  [ "$(json_field "$work/e.json" 'before.elements.singular_edges#')" = 1 ] || fail "--elements before"
  [ "$(json_field "$work/e.json" before.elements.singular_edges.0.contenders)" = 4 ] || fail "contenders"
  [ "$(json_field "$work/e.json" 'after.elements.singular_edges#')" = 0 ] || fail "--elements after"
  grep -q '"elements"' "$work/twocubes.json" && fail "repair report lists elements without --elements"
  expect_exit 0 "$mb" repair "$models/moebius.obj" "$work/m.obj" --cut-nonorientable --report "$work/m.json"
  [ "$(json_field "$work/m.json" before.nonorientable_components)" = 1 ] || fail "moebius non-orientable"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --pairing combinatorial --no-stitch --no-orient
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --pairing sideways
  expect_in "$work/err" "--pairing: sideways not in {geometric,combinatorial}"
  ;;
repair_formats)
  # A box of 7 quads with two T-junction cracks: closing them makes 2 pentagons, and STL and
  # 3MF hold triangles only: the summary says how many the file has (16, as check reads it).
  source "$(dirname "${BASH_SOURCE[0]}")/../meshlab/crack_models.sh"
  write_t_junction_box "$work/box.off"
  for ext in stl 3mf; do
    expect_exit 0 "$mb" repair "$work/box.off" "$work/box.$ext" --report "$work/box.json"
    expect_in "$work/out" "faces: 7 in, 7 out"
    expect_in "$work/out" "written as 16 triangles: 7 polygons cut into triangles (the format holds triangles only)"
    [ "$(json_field "$work/box.json" written.triangles)" = 16 ] || fail "$ext: written.triangles"
    [ "$(json_field "$work/box.json" written.polygons_triangulated)" = 7 ] || fail "$ext: written.polygons_triangulated"
    expect_exit 0 "$mb" check "$work/box.$ext" --json
    [ "$(json_field "$work/out" faces)" = 16 ] || fail "$ext: check reads 16 triangles"
  done
  expect_exit 0 "$mb" repair "$work/box.off" "$work/box.ply" --report "$work/box.json"
  grep -q "written as" "$work/out" && fail "PLY keeps polygons: no 'written as' line"
  [ "$(json_field "$work/box.json" written.polygons_triangulated)" = 0 ] || fail "PLY: written.polygons_triangulated"
  # What the output format cannot hold is named on stderr and in the report, never dropped
  # without a word; OBJ to OBJ keeps mtllib, groups and the vertices' own colours.
  printf 'mtllib m.mtl\nv 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\nvn 1 0 0\nusemtl red\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' >"$work/tex.obj"
  expect_exit 0 "$mb" repair "$work/tex.obj" "$work/tex.stl" --report "$work/tex.json"
  expect_in "$work/err" "tex.stl: 1 texture coordinate (vt) and 2 normals (vn) not written: STL holds none per corner (write OBJ to keep them)"
  expect_in "$work/err" "tex.stl: vertex colours not written: STL holds none"
  expect_in "$work/err" "tex.stl: OBJ groups and materials not written (1 o/g/usemtl line, 1 mtllib line): STL holds none"
  [ "$(json_field "$work/tex.json" written.left_out.2)" = "OBJ groups and materials not written (1 o/g/usemtl line, 1 mtllib line): STL holds none" ] ||
    fail "written.left_out.2: $(cat "$work/tex.json")"
  expect_exit 0 "$mb" repair "$work/tex.obj" "$work/tex_out.obj"
  [ "$(grep -c "not written" "$work/err")" = 0 ] || fail "OBJ keeps all, vt/vn too: $(cat "$work/err")"
  [ "$(grep -c '^vt 0 0$' "$work/tex_out.obj") $(grep -c '^vn ' "$work/tex_out.obj")" = "1 2" ] ||
    fail "vt and vn records written back: $(cat "$work/tex_out.obj")"
  [ "$(grep -c '^v .* .* .* 1 0 0$' "$work/tex_out.obj") $(grep -c '^v [^ ]* [^ ]* [^ ]*$' "$work/tex_out.obj")" = "1 3" ] ||
    fail "vertex colours where the input had them: $(cat "$work/tex_out.obj")"
  expect_in "$work/tex_out.obj" "mtllib m.mtl"
  for ext in obj off ply; do
    expect_exit 0 "$mb" repair "$models/prisms24.obj" "$work/p.$ext"
    expect_exit 0 "$mb" check "$work/p.$ext" --json
    [ "$(json_field "$work/out" faces)" = 120 ] || fail "$ext faces"
    [ "$(json_field "$work/out" vertices)" = 144 ] || fail "$ext vertices"
    [ "$(json_field "$work/out" components)" = 24 ] || fail "$ext components"
  done
  ;;
stl_warning)
  # STL keeps the repair by default: the split copies move apart, by a size the summary names.
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/d.stl" --report "$work/d.json"
  expect_in "$work/out" "separated the 2 split vertex copies for STL: moved 4 vertices by 9.53674e-07"
  grep -q "rounded to 32-bit floats" "$work/err" && fail "moved copies not on float32 positions: $(cat "$work/err")"
  expect_in "$work/out" "as re-read from $work/d.stl: singular edges 0, singular vertices 0, watertight yes"
  grep -q "STL has no shared vertices" "$work/err" && fail "a warning for an STL that keeps the repair"
  [ "$(json_field "$work/d.json" written.copies_moved)" = 4 ] || fail "written.copies_moved"
  [ "$(json_field "$work/d.json" written.separation)" = 9.5367431640625e-07 ] || fail "written.separation"
  expect_exit 0 "$mb" check "$work/d.stl" --json
  [ "$(json_field "$work/out" singular_edges) $(json_field "$work/out" boundary_edges) $(json_field "$work/out" components)" = "0 0 2" ] ||
    fail "default STL re-read: $(cat "$work/out")"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.stl" --separate 0
  expect_in "$work/err" "STL has no shared vertices"
  expect_exit 1 "$mb" check "$work/c.stl"   # welded back: the singular edge returns
  expect_in "$work/out" "singular edges: 1"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --separate auto
  expect_in "$work/out" "separate: not needed for $work/c.obj (the format keeps shared vertices)"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c2.obj"
  grep -q "separate" "$work/out" && fail "a separate line for OBJ without --separate"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/s.stl" --separate 1e-4
  expect_in "$work/out" "separated the 2 split vertex copies: moved 4 vertices"
  expect_in "$work/out" "as re-read from $work/s.stl: singular edges 0, singular vertices 0, watertight yes"
  expect_exit 0 "$mb" check "$work/s.stl"
  expect_in "$work/out" "watertight yes"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/a.stl" --separate auto
  expect_in "$work/out" "as re-read from $work/a.stl: singular edges 0, singular vertices 0"
  # Repairing that STL again changes no byte: the default gap closing does not weld the copies.
  for model in bowtie book_of_three moebius; do
    expect_exit 0 "$mb" repair "$models/$model.obj" "$work/$model-1.stl" --separate auto
    expect_exit 0 "$mb" repair "$work/$model-1.stl" "$work/$model-2.stl" --separate auto
    expect_in "$work/out" "gaps (tolerance"
    cmp -s "$work/$model-1.stl" "$work/$model-2.stl" || fail "$model: a repaired STL repaired again changed"
  done
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/t.stl" --separate 1e-9
  expect_in "$work/err" "the smallest EPS that works is"
  # The JSON report says what the STL file re-reads as, next to the repair's own counts.
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/r.stl" --separate 0 --report "$work/r.json"
  [ "$(json_field "$work/r.json" after.singular_edges)" = 0 ] || fail "after in memory"
  [ "$(json_field "$work/r.json" written.copies_moved)" = 0 ] || fail "--separate 0 moved copies"
  [ "$(json_field "$work/r.json" reread.singular_edges)" = 1 ] || fail "reread singular edges"
  [ "$(json_field "$work/r.json" reread.singular_vertices)" = 2 ] || fail "reread singular vertices"
  [ "$(json_field "$work/r.json" gaps.vertices_welded)" = 0 ] || fail "gaps in the report"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/r.obj" --report "$work/o.json"
  grep -q '"reread"' "$work/o.json" && fail "reread in a report of an OBJ output"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/ra.stl" --separate auto --report "$work/ra.json"
  [ "$(json_field "$work/ra.json" reread.singular_edges)" = 0 ] || fail "--separate auto reread"
  [ "$(json_field "$work/ra.json" reread.watertight)" = true ] || fail "--separate auto watertight"
  # batch: an STL output counts as re-read (table and JSON); 3MF keeps the repair.
  mkdir -p "$work/in"
  cp "$models/twocubes.obj" "$work/in/"
  expect_exit 0 "$mb" batch "$work/in" "$work/bs" --format stl
  expect_in "$work/out" "| twocubes.obj | repaired | 24 | 1 | 2 | 24 | 2 | yes |"
  expect_exit 0 "$mb" check "$work/bs/twocubes.stl"
  expect_exit 0 "$mb" batch "$work/in" "$work/bj" --format stl --json --quiet
  [ "$(json_line_field "$work/out" 0 reread.singular_edges)" = 0 ] || fail "batch reread"
  [ "$(json_line_field "$work/out" 0 written.copies_moved)" = 4 ] || fail "batch copies_moved"
  expect_exit 0 "$mb" batch "$work/in" "$work/b0" --format stl --separate 0
  expect_in "$work/out" "| twocubes.obj | repaired | 24 | 1 | 2 | 24 | 1 | no |"
  expect_in "$work/err" "re-creates 1 singular edge and 2 singular vertices (positions were kept exact)"
  expect_exit 0 "$mb" batch "$work/in" "$work/b0j" --format stl --separate 0 --json --quiet
  [ "$(json_line_field "$work/out" 0 reread.singular_edges)" = 1 ] || fail "batch reread, exact"
  expect_exit 0 "$mb" batch "$work/in" "$work/b3" --format 3mf --weld 0
  expect_in "$work/out" "| twocubes.obj | repaired | 24 | 1 | 2 | 24 | 2 | yes |"
  expect_exit 0 "$mb" check "$work/b3/twocubes.3mf"
  expect_in "$work/out" "watertight yes"
  expect_exit 0 "$mb" check "$work/b3/twocubes.3mf" --weld 0
  expect_in "$work/out" "gaps: not closed (weld tolerance 0: --weld 0, or every coordinate is 0)"
  expect_exit 2 "$mb" check "$work/b3/twocubes.3mf" --weld -1
  expect_in "$work/err" "--weld: expects auto or a finite number >= 0, got '-1'"
  ;;
print_preset)
  # --print: 3MF only; a closed result says so; what stays open is named with its reason.
  expect_exit 2 "$mb" repair "$models/cube_with_hole.obj" "$work/p.obj" --print
  expect_in "$work/err" "p.obj: --print writes 3MF"
  expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/p.3mf" --print --report "$work/p.json"
  expect_in "$work/out" "print: watertight as written"
  [ "$(json_field "$work/p.json" holes.holes_filled) $(json_field "$work/p.json" after.boundary_edges)" = "1 0" ] ||
    fail "--print filled: $(cat "$work/p.json")"
  expect_exit 0 "$mb" check "$work/p.3mf"
  printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' >"$work/sheet.obj"
  expect_exit 0 "$mb" repair "$work/sheet.obj" "$work/sheet.3mf" --print --report "$work/s.json"
  expect_in "$work/out" "print: 4 open edges in 1 boundary loop left: 1 loop outlining an open sheet"
  [ "$(json_field "$work/s.json" holes.patches_refused) $(json_field "$work/s.json" faces_out)" = "1 1" ] ||
    fail "sheet outline filled: $(cat "$work/s.json")"
  # A triangle written twice back to back (a slicer reads it as a closed part of no volume):
  # removing the duplicate would open it, so the preset keeps it and says so.
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 2\n' >"$work/twice.obj"
  expect_exit 0 "$mb" repair "$work/twice.obj" "$work/twice.3mf" --print
  expect_in "$work/out" "print: kept the 1 duplicate face: removing them left 3 open edges (keeping them: 0"
  # 3MF holds triangles: the repair's polygons are cut without doubling an edge (slivers split at
  # their midpoints, RHR; RWP, a hull written twice whose quads split at one midpoint on both
  # sides of the sheet take the two diagonals, one triangle of no area each, where they used to
  # share one: 1 singular edge, which PrusaSlicer read as an open edge); the report's reread says
  # what the file holds (never "watertight" unseen).
  data="$models/../../tests/data/realworld2"
  for hull in RHR RWP; do
    expect_exit 0 "$mb" repair "$data/dart_drchubo_convhull_${hull}_merged.stl" "$work/$hull.3mf" --report "$work/$hull.json"
    [ "$(json_field "$work/$hull.json" reread.singular_edges) $(json_field "$work/$hull.json" reread.watertight)" = "0 true" ] ||
      fail "$hull as 3MF triangles: $(cat "$work/$hull.json")"
    expect_exit 0 "$mb" check "$work/$hull.3mf"
  done
  [ "$(json_field "$work/RWP.json" written.polygons_triangulated)" = 38 ] || fail "RWP polygons cut: $(cat "$work/RWP.json")"
  # Without --print, an open result gets a hint of what would close it.
  expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/h.obj"
  expect_in "$work/out" "hint: 4 open edges in 1 boundary loop left; --fill-holes closes holes of up to 32 edges"
  ;;
nested_shells)
  # A cube of side 4 with a cube of side 2 inside, both wound outward: an insert, or a cavity
  # written the wrong way. Kept as written (material) by default; --nested-shells cavity turns
  # the inner cube into a void, in check's prediction, repair and batch alike.
  {
    for c in 0 2; do  # the outer cube's corners at 0/4 (c = 0), the inner one's at 1/3 (c = 2)
      lo=$((c / 2)) hi=$((4 - c / 2))
      for z in $lo $hi; do for y in $lo $hi; do for x in $lo $hi; do echo "v $x $y $z"; done; done; done
    done
    for base in 0 8; do
      awk -v b=$base 'BEGIN { split("1 3 4 2|5 6 8 7|1 2 6 5|3 7 8 4|1 5 7 3|2 4 8 6", q, "|");
        for (i = 1; i <= 6; i++) { split(q[i], c, " "); printf "f %d %d %d %d\n", c[1]+b, c[2]+b, c[3]+b, c[4]+b } }'
    done
  } >"$work/nested.obj"
  expect_exit 0 "$mb" repair "$work/nested.obj" "$work/n1.obj" --report "$work/n1.json"
  [ "$(json_field "$work/n1.json" faces_flipped)" = 0 ] || fail "material: flipped $(json_field "$work/n1.json" faces_flipped)"
  [ "$(json_field "$work/n1.json" ambiguous_nested_shells)" = 1 ] || fail "ambiguous shells not counted"
  expect_exit 0 "$mb" repair "$work/nested.obj" "$work/n2.obj" --nested-shells cavity --report "$work/n2.json"
  [ "$(json_field "$work/n2.json" faces_flipped)" = 6 ] || fail "cavity: flipped $(json_field "$work/n2.json" faces_flipped)"
  expect_exit 1 "$mb" check "$work/nested.obj" --nested-shells cavity
  mkdir -p "$work/nin" && cp "$work/nested.obj" "$work/nin/"
  expect_exit 0 "$mb" batch "$work/nin" "$work/nout" --nested-shells cavity --json --quiet
  [ "$(json_line_field "$work/out" 0 faces_flipped)" = 6 ] || fail "batch --nested-shells cavity"
  cmp -s "$work/n2.obj" "$work/nout/nested.obj" || fail "batch and repair wrote different meshes"
  expect_exit 0 "$mb" batch "$work/nin" "$work/nout2" --json --quiet
  [ "$(json_line_field "$work/out" 0 faces_flipped)" = 0 ] || fail "batch default material"
  expect_exit 2 "$mb" batch "$work/nin" "$work/nout3" --nested-shells hollow
  ;;
bad_input)
  : >"$work/empty.obj"
  expect_exit 2 "$mb" check "$work/empty.obj"
  expect_in "$work/err" "file is empty"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/range.obj"
  expect_exit 2 "$mb" check "$work/range.obj"
  expect_in "$work/err" "range.obj: line 4: face corner 3 refers to vertex 9, but the file has 3 vertices"
  printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >"$work/nan.obj"
  expect_exit 2 "$mb" check "$work/nan.obj"
  expect_in "$work/err" "line 3: vertex 3 has a non-finite coordinate"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 1 2\nf 1 2 3\n' >"$work/repeat.obj"
  expect_exit 1 "$mb" check "$work/repeat.obj"
  expect_in "$work/err" "2 face records: 1 kept, 1 set aside (< 3 distinct corners)"
  printf 'garbage\n' >"$work/garbage.obj"
  expect_exit 2 "$mb" check "$work/garbage.obj"
  expect_in "$work/err" "no polygons"
  printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n' >"$work/range.off"
  expect_exit 2 "$mb" check "$work/range.off"
  expect_in "$work/err" "OFF face 1 refers to vertex index 5 (line 6), but the file has 3 vertices (OFF counts from 0)"
  printf 'OFF\n300000000 1 0\n0 0 0\n' >"$work/huge.off"
  expect_exit 2 "$mb" check "$work/huge.off"
  expect_in "$work/err" "declares 300000000 vertices"
  printf 'solid x\n' >"$work/x.dxf"
  expect_exit 2 "$mb" check "$work/x.dxf"
  expect_in "$work/err" "unknown format"
  expect_exit 2 "$mb" check "$work"
  expect_in "$work/err" "cannot read: it is a folder"
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
  # OUT that is IN itself (by name, through a link or another spelling) is refused, the input
  # untouched, unless --in-place.
  cp "$models/twocubes.obj" "$work/self.obj"
  ln -s self.obj "$work/self_link.obj"
  for same in "$work/self.obj" "$work/./self.obj" "$work/self_link.obj"; do
    expect_exit 2 "$mb" repair "$work/self.obj" "$same"
    expect_in "$work/err" "is the input file itself; repair would replace it (pass --in-place"
  done
  # Nor may --report name IN or OUT.
  for same in "$work/self.obj" "$work/./self_link.obj" "$work/report_out.obj"; do
    expect_exit 2 "$mb" repair "$work/self.obj" "$work/report_out.obj" --report "$same"
    expect_in "$work/err" "--report names the"
  done
  cmp -s "$models/twocubes.obj" "$work/self.obj" || fail "the input changed"
  chmod 0640 "$work/self.obj"
  expect_exit 0 "$mb" repair "$work/self.obj" "$work/self.obj" --in-place
  expect_in "$work/out" "vertices: 14 in, 16 out"
  [ "$(stat -c %a "$work/self.obj")" = 640 ] || fail "--in-place changed the mode to $(stat -c %a "$work/self.obj")"
  # A replaced output keeps its permissions, as a shell redirection would (0600 stays private).
  echo old >"$work/private.ply"
  chmod 0600 "$work/private.ply"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/private.ply"
  [ "$(stat -c %a "$work/private.ply")" = 600 ] || fail "the output's mode became $(stat -c %a "$work/private.ply")"
  expect_exit 0 "$mb" check "$work/self.obj"
  # A pipe or a device is written in place, never replaced by a file (as root, renaming over
  # /dev/stdout or a device node would replace it); a symbolic link stays one.
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/plain.ply"
  mkfifo "$work/pipe.ply"
  cat "$work/pipe.ply" >"$work/from_pipe.ply" &
  reader=$!
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/pipe.ply"
  wait "$reader"
  [ -p "$work/pipe.ply" ] || fail "the FIFO was replaced by a file"
  cmp -s "$work/plain.ply" "$work/from_pipe.ply" || fail "the FIFO got other bytes than the file"
  # A report on standard output ('-', /dev/stdout, piped or redirected) is the JSON alone there;
  # the summary goes to standard error.
  "$mb" repair "$models/twocubes.obj" "$work/r.ply" --report /dev/stdout 2>"$work/err" |
    cat >"$work/piped.json" || fail "repair --report /dev/stdout failed: $(cat "$work/err")"
  [ "$(json_field "$work/piped.json" kind)" = repair ] || fail "no report alone on the pipe"
  expect_in "$work/err" "twocubes.obj -> $work/r.ply"
  for target in /dev/stdout -; do
    "$mb" repair "$models/twocubes.obj" "$work/r.ply" --report "$target" >"$work/redirected.json" \
      2>"$work/err" || fail "repair --report $target failed: $(cat "$work/err")"
    [ "$(json_field "$work/redirected.json" after.singular_edges)" = 0 ] ||
      fail "--report $target into a redirected stdout is not the JSON alone"
    expect_in "$work/err" "after: singular edges 0"
  done
  [ ! -e "./-" ] && [ ! -e "$work/-" ] || fail "--report - wrote a file named '-'"
  [ -L /dev/stdout ] || fail "/dev/stdout is no longer a symbolic link"
  echo "old content" >"$work/real.obj"
  ln -s real.obj "$work/link.obj"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/link.obj"
  [ -L "$work/link.obj" ] || fail "the symbolic link was replaced by a file"
  expect_in "$work/real.obj" "v "
  # A report that cannot be created is found before anything is written.
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/early.ply" --report /proc/report.json
  expect_in "$work/err" "meshbridge repair: error: /proc/report.json: cannot write into the folder '/proc'"
  [ ! -e "$work/early.ply" ] || fail "the mesh was written though the report cannot be"
  ;;
batch)
  mkdir -p "$work/in/sub"
  cp "$models/twocubes.obj" "$models/twocubes.off" "$models/icosphere.obj" "$work/in/"
  cp "$models/prisms24.obj" "$work/in/sub/"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --format ply
  expect_in "$work/out" "4 file(s): 1 clean, 3 repaired, 0 failed, 0 skipped"
  expect_in "$work/out" "| sub/prisms24.obj | repaired | 120 | 79 | 38 | 120 | 24 | yes |"
  expect_in "$work/out" "| icosphere.obj | clean | 80 | 0 | 0 | 80 | 1 | yes |"
  [ ! -s "$work/err" ] || fail "progress on a pipe without --progress: $(cat "$work/err")"
  [ -f "$work/res/twocubes.ply" ] && [ -f "$work/res/twocubes-off.ply" ] && [ -f "$work/res/sub/prisms24.ply" ] \
    || fail "batch outputs missing: $(ls -R "$work/res")"
  expect_exit 0 "$mb" batch "$work/in" "$work/res1" --progress --jobs 1
  expect_in "$work/err" "[4/4]"
  expect_in "$work/err" "ETA"
  # What a reader changed is a warning on stderr in table and JSON mode, with any --jobs.
  mkdir -p "$work/pinched"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 1 4 5\nf 1 2\nl 1 3\n' >"$work/pinched/p.obj"
  for jobs in 1 2; do
    for mode in "" --json; do
      expect_exit 0 "$mb" batch "$work/pinched" "$work/pinched_out$jobs$mode" --jobs "$jobs" $mode
      expect_in "$work/err" \
        "meshbridge: warning: p.obj: 2 face records: 0 kept, 1 split (pinched: a vertex revisited), 1 set aside (< 3 distinct corners); 1 dangling edge"
    done
  done
  # What an output format cannot hold is a warning too, and the record's written.left_out.
  mkdir -p "$work/coloured"
  printf 'COFF\n4 4 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n0 0 1 9 9 9\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >"$work/coloured/c.off"
  for jobs in 1 2; do
    expect_exit 0 "$mb" batch "$work/coloured" "$work/coloured_out$jobs" --format stl --json --jobs "$jobs"
    expect_in "$work/err" "meshbridge: warning: c.off: output c.stl: vertex colours not written: STL holds none"
    [ "$(json_line_field "$work/out" 0 written.left_out.0)" = "vertex colours not written: STL holds none" ] ||
      fail "batch written.left_out: $(cat "$work/out")"
    [ "$(json_line_field "$work/out" 0 written.triangles)" = 4 ] || fail "batch written.triangles"
  done
  printf 'v 0 0 0\nf 1 2 3\n' >"$work/in/broken.obj"
  expect_exit 2 "$mb" batch "$work/in" "$work/res2" --json --quiet
  [ ! -s "$work/err" ] || fail "--quiet printed progress: $(cat "$work/err")"
  [ "$(json_lines "$work/out")" = 5 ] || fail "5 JSON lines: $(cat "$work/out")"
  [ "$(json_line_field "$work/out" 0 file)" = broken.obj ] || fail "sorted by file: broken.obj first"
  [ "$(json_line_field "$work/out" 0 status)" = failed ] || fail "broken.obj failed"
  json_line_field "$work/out" 0 reason | grep -q "line 2: face corner 2 refers to vertex 2, but the file has 1 vertex" || fail "broken.obj reason"
  [ "$(json_line_field "$work/out" 1 status)" = clean ] || fail "icosphere clean"
  [ "$(json_line_field "$work/out" 2 file)" = sub/prisms24.obj ] || fail "line 2 is sub/prisms24.obj"
  [ "$(json_line_field "$work/out" 2 before.singular_edges)" = 79 ] || fail "prisms24 singular edges"
  [ "$(json_line_field "$work/out" 2 after.watertight)" = true ] || fail "prisms24 watertight after"
  [ "$(json_line_field "$work/out" 3 status)" = repaired ] || fail "twocubes repaired"
  [ "$(json_line_field "$work/out" 3 output)" = twocubes.obj ] || fail "twocubes output"
  [ ! -e "$work/res2/broken.obj" ] || fail "a failed file left an output"
  # Same records, same order, for any --jobs.
  expect_exit 2 "$mb" batch "$work/in" "$work/res3" --json --jobs 1
  cp "$work/out" "$work/jobs1.jsonl"
  expect_in "$work/err" "5 file(s): 1 clean, 3 repaired, 1 failed, 0 skipped"
  expect_exit 2 "$mb" batch "$work/in" "$work/res4" --json --jobs 3
  cmp -s "$work/out" "$work/jobs1.jsonl" || fail "--jobs 3 differs from --jobs 1: $(diff "$work/out" "$work/jobs1.jsonl")"
  cmp -s "$work/res3/sub/prisms24.obj" "$work/res4/sub/prisms24.obj" || fail "outputs differ by --jobs"
  ;;
batch_safety)
  mkdir -p "$work/in/sub"
  cp "$models/twocubes.obj" "$models/icosphere.obj" "$work/in/"
  cp "$models/prisms24.obj" "$work/in/sub/"
  cp "$work/in/twocubes.obj" "$work/original.obj"
  # An output folder that cannot be made is one error before any work, not a failed row per file.
  echo "a file" >"$work/plain.txt"
  expect_exit 2 "$mb" batch "$work/in" "$work/plain.txt/out"
  expect_in "$work/err" "meshbridge batch: error: $work/plain.txt/out: cannot create the output folder (Not a directory)"
  [ "$(wc -l <"$work/err")" = 1 ] || fail "one error line: $(cat "$work/err")"
  [ ! -s "$work/out" ] || fail "no table for a batch that could not start: $(cat "$work/out")"
  expect_exit 2 "$mb" batch "$work/in" "$work/in"
  expect_in "$work/err" "is the input folder"
  expect_exit 2 "$mb" batch "$work/in" "$work/in/sub/out"
  expect_in "$work/err" "is inside the input folder"
  expect_exit 2 "$mb" batch "$work/in" "$work/in/./sub/.."
  expect_in "$work/err" "is the input folder"
  cmp -s "$work/in/twocubes.obj" "$work/original.obj" || fail "a refused batch touched the input"
  [ ! -e "$work/in/sub/out" ] || fail "a refused batch made OUTDIR"
  expect_exit 2 "$mb" batch "$work/missing" "$work/res"
  expect_in "$work/err" "missing: no such folder"
  # --resume: the second run skips everything, and that is success.
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json --resume
  [ "$(json_line_field "$work/out" 0 status)" = skipped ] || fail "resume did not skip"
  json_line_field "$work/out" 0 reason | grep -q "is up to date (same input and options as its last run)" || fail "resume reason"
  expect_in "$work/err" "3 file(s): 0 clean, 0 repaired, 0 failed, 3 skipped"
  touch -d '+10 seconds' "$work/in/icosphere.obj"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json --resume
  [ "$(json_line_field "$work/out" 0 status)" = clean ] || fail "resume skipped a changed input"
  [ "$(json_line_field "$work/out" 1 status)" = skipped ] || fail "resume redid sub/prisms24.obj"
  # In the table a skipped or failed file has no counts: its reason is the last column (note).
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --resume
  grep -q '^| file | status | .* | watertight after | note |$' "$work/out" || fail "table header: $(cat "$work/out")"
  grep -qE '^\| sub/prisms24\.obj \| skipped \| \| \| \| \| \| \| .*is up to date .* \|$' "$work/out" ||
    fail "skipped row, reason in the note column: $(cat "$work/out")"
  # --resume redoes a file whose options changed (the log keeps them), and retries a failed one.
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json --resume --fill-holes
  [ "$(json_line_field "$work/out" 0 status)" = clean ] || fail "resume skipped files made without --fill-holes"
  expect_in "$work/err" "3 file(s): 1 clean, 2 repaired, 0 failed, 0 skipped"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json --resume --fill-holes
  expect_in "$work/err" "3 file(s): 0 clean, 0 repaired, 0 failed, 3 skipped"
  grep -c '"batch_log":{"options":"format=same weld=auto .* fill_holes=32 ' "$work/res/.meshbridge-batch.jsonl" | grep -qx 3 ||
    fail "the log keeps each file's options: $(cat "$work/res/.meshbridge-batch.jsonl")"
  echo "not a mesh" >"$work/in/later.obj"
  expect_exit 2 "$mb" batch "$work/in" "$work/res" --json --resume --fill-holes
  expect_in "$work/err" "4 file(s): 0 clean, 0 repaired, 1 failed, 3 skipped"
  cp "$models/bowtie.obj" "$work/in/later.obj"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --json --resume --fill-holes
  expect_in "$work/err" "4 file(s): 0 clean, 1 repaired, 0 failed, 3 skipped"
  rm "$work/in/later.obj"
  # --in-place into INDIR itself replaces the originals.
  cp -r "$work/in" "$work/inplace"
  expect_exit 0 "$mb" batch "$work/inplace" "$work/inplace" --in-place --json
  [ "$(json_lines "$work/out")" = 3 ] || fail "in place: 3 records"
  "$mb" check "$work/inplace/twocubes.obj" >/dev/null || fail "in place: twocubes.obj not repaired"
  # --in-place into a folder inside INDIR: earlier results are not taken as inputs.
  expect_exit 0 "$mb" batch "$work/in" "$work/in/fixed" --in-place --json
  expect_exit 0 "$mb" batch "$work/in" "$work/in/fixed" --in-place --json
  [ "$(json_lines "$work/out")" = 3 ] || fail "OUTDIR inside INDIR was read back: $(cat "$work/out")"
  rm -rf "$work/in/fixed"
  # An OUTDIR that cannot be made, in JSON mode too: one error, no record.
  : >"$work/blocker"
  expect_exit 2 "$mb" batch "$work/in" "$work/blocker/res" --json
  expect_in "$work/err" "$work/blocker/res: cannot create the output folder (Not a directory)"
  [ ! -s "$work/out" ] || fail "records for a batch that could not start: $(cat "$work/out")"
  # Unreadable folders and files are skipped with a warning naming them; the rest goes on.
  # Root reads everything, so as root the run drops to user nobody (setpriv, util-linux).
  mkdir -p "$work/in/locked"
  cp "$models/bowtie.obj" "$work/in/locked/"
  cp "$models/bowtie.obj" "$work/in/secret.obj"
  chmod 000 "$work/in/locked" "$work/in/secret.obj"
  chmod 755 "$work"
  run_as=()
  if [ "$(id -u)" = 0 ]; then
    run_as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    mkdir -p "$work/res5" && chmod 777 "$work/res5"
  fi
  if "${run_as[@]}" test -x "$mb"; then
    expect_exit 2 "${run_as[@]}" "$mb" batch "$work/in" "$work/res5" --json
    expect_in "$work/err" "skipped locked in $work/in: cannot list the folder (Permission denied)"
    expect_in "$work/err" "skipped secret.obj in $work/in: cannot open the file (Permission denied)"
    expect_in "$work/err" "5 file(s): 1 clean, 2 repaired, 0 failed, 2 skipped"
    [ "$(json_lines "$work/out")" = 5 ] || fail "5 records with the unreadable ones"
    [ "$(json_line_field "$work/out" 1 file)" = locked ] || fail "record of the locked folder"
    [ "$(json_line_field "$work/out" 1 status)" = skipped ] || fail "locked folder skipped"
  else
    echo "note: $mb is not executable by user nobody; unreadable-folder check left out" >&2
  fi
  chmod 755 "$work/in/locked" && chmod 644 "$work/in/secret.obj"
  # Symbolic links: a linked file is read and written under the link's own name below OUTDIR
  # (never where the link points: that file stays as it was); a link to nothing, a link loop, a
  # link to a folder and a FIFO with a mesh name are skipped with their reason.
  mkdir -p "$work/links/in" "$work/links/elsewhere"
  cp "$models/twocubes.obj" "$work/links/elsewhere/original.obj"
  cp "$models/bowtie.obj" "$work/links/in/a.obj"
  ln -s ../elsewhere/original.obj "$work/links/in/outside.obj"
  ln -s a.obj "$work/links/in/alias.obj"
  ln -s nowhere.obj "$work/links/in/dangling.obj"
  ln -s ../elsewhere "$work/links/in/folder_link"
  ln -s loop.off "$work/links/in/loop.off"
  mkfifo "$work/links/in/pipe.stl"
  expect_exit 2 "$mb" batch "$work/links/in" "$work/links/out" --json
  cmp -s "$work/links/elsewhere/original.obj" "$models/twocubes.obj" || fail "batch wrote through a link"
  for name in a.obj alias.obj outside.obj; do
    [ -f "$work/links/out/$name" ] || fail "no output $name: $(ls "$work/links/out")"
  done
  [ "$(json_lines "$work/out")" = 7 ] || fail "7 records: $(cat "$work/out")"
  grep -F '"file":"outside.obj"' "$work/out" | grep -qF '"status":"repaired"' || fail "outside.obj record"
  expect_in "$work/err" "skipped dangling.obj in $work/links/in: a symbolic link to nothing"
  expect_in "$work/err" "skipped folder_link in $work/links/in: a symbolic link to a folder, not followed"
  expect_in "$work/err" "skipped loop.off in $work/links/in: cannot follow the symbolic link"
  expect_in "$work/err" "skipped pipe.stl in $work/links/in: not a regular file (a FIFO, socket or device)"
  expect_in "$work/err" "7 file(s): 0 clean, 3 repaired, 0 failed, 4 skipped"
  # check --json carries what repair's gap closing would do, as the text does.
  expect_exit 0 "$mb" check "$models/icosphere.obj" --json
  [ "$(json_field "$work/out" gaps.vertices_welded)" = 0 ] || fail "check --json gaps: $(cat "$work/out")"
  # A report that cannot reach standard output is an error, not a silent success.
  if [ -w /dev/full ]; then
    "$mb" check "$models/icosphere.obj" --json >/dev/full 2>"$work/err"
    [ $? = 2 ] || fail "check --json > /dev/full did not fail"
    expect_in "$work/err" "meshbridge check: error: cannot write to standard output"
  fi
  # A report that cannot be written says so, and that OUT was written.
  if [ -w /dev/full ]; then
    expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/full_report.obj" --report /dev/full
    expect_in "$work/err" "/dev/full: cannot write the report (write failed (No space left on device)); $work/full_report.obj is written"
  fi
  # check on a FIFO is an error at once, not a wait for a writer.
  expect_exit 2 timeout 20 "$mb" check "$work/links/in/pipe.stl"
  expect_in "$work/err" "not a regular file (a FIFO, socket or device cannot be mapped)"
  ;;
json_paths)
  # Quotes, backslashes, a tab and Latin-1 (non-UTF-8) bytes in file and folder names.
  dir="$work/in \"q\" \\back"$'\t'"tab"
  mkdir -p "$dir/caf"$'\xe9'
  weird="$dir/caf"$'\xe9'"/two \"cubes\"\\"$'\xff'".obj"
  cp "$models/twocubes.obj" "$weird"
  expect_exit 1 "$mb" check "$weird" --json
  /usr/bin/python3 -c 'import json,sys; f=json.load(open(sys.argv[1],encoding="utf-8"))["file"]
want=sys.argv[2].encode("utf-8","surrogateescape").decode("utf-8","replace")
sys.exit(0 if f==want else "check file %r != %r" % (f, want))' "$work/out" "$weird" || fail "check file"
  [ "$(json_field "$work/out" singular_edges)" = 1 ] || fail "check through a weird path"
  expect_exit 0 "$mb" repair "$weird" "$dir/out \"x\".obj" --report "$dir/r\"\\.json"
  [ "$(json_field "$dir/r\"\\.json" after.singular_edges)" = 0 ] || fail "repair report"
  json_field "$dir/r\"\\.json" file | grep -qF 'two "cubes"\'$'\xef\xbf\xbd''.obj' || fail "U+FFFD in repair file"
  expect_exit 0 "$mb" compare "$weird" --json
  [ "$(json_field "$work/out" bridged.vertices)" = 16 ] || fail "compare"
  expect_exit 0 "$mb" batch "$dir" "$work/res" --json
  # Two meshes: the weird one and the repair output; the report is not a mesh.
  [ "$(json_lines "$work/out")" = 2 ] || fail "batch: two records: $(cat "$work/out")"
  [ "$(json_line_field "$work/out" 0 file)" = "caf"$'\xef\xbf\xbd'"/two \"cubes\"\\"$'\xef\xbf\xbd'".obj" ] \
    || fail "batch file: $(cat "$work/out")"
  [ -f "$work/res/caf"$'\xe9'"/two \"cubes\"\\"$'\xff'".obj" ] || fail "batch output under the real name"
  ;;
snapshot)
  expect_exit 1 "$mb" snapshot "$models/twocubes.obj" "$work/twocubes.png"
  expect_in "$work/out" "1 singular edge, 2 singular vertices, 0 boundary edges"
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
  # Seen end on from +z, the singular edge is a point on screen: still drawn (its vertex's dot).
  expect_exit 1 "$mb" snapshot "$models/twocubes.obj" "$work/twocubes-z.png" --view z
  [ "$(pixels "$work/out" red)" -ge 20 ] 2>/dev/null || fail "edge seen end on not drawn: $(cat "$work/out")"
  for view in iso x y z; do
    expect_exit 1 "$mb" snapshot "$models/prisms24.obj" "$work/p-$view.png" --view "$view" --size 99
    [ "$(pixels "$work/out" red)" -gt 0 ] 2>/dev/null || fail "no red pixels in prisms24, $view"
  done
  # A keyhole polygon (assimp's ring: an outline and its hole joined by a slit) repaired: the
  # hole stays open, so the middle of the picture is the white background, not grey surface.
  expect_exit 0 "$mb" repair "$models/../../tests/data/realworld2/assimp_concave_polygon.obj" \
    "$work/ring.obj"
  expect_in "$work/out" "1 keyhole polygon triangulated"
  expect_exit 1 "$mb" snapshot "$work/ring.obj" "$work/ring.png" --view x --size 400 --focus whole
  expect_in "$work/out" "0 singular edges, 0 singular vertices, 64 boundary edges"
  [ "$(convert "$work/ring.png" -format '%[pixel:p{200,210}]' info:)" = "srgba(255,255,255,1)" ] ||
    fail "keyhole's hole covered: $(convert "$work/ring.png" -format '%[pixel:p{200,210}]' info:)"
  ls -a "$work" | grep -q tmp && fail "temporary file left behind"
  expect_exit 0 "$mb" snapshot --help
  expect_in "$work/out" "Usage: meshbridge snapshot [OPTIONS] FILE OUT.png"
  ;;
snapshot_errors)
  expect_exit 2 "$mb" snapshot "$work/missing.obj" "$work/a.png"
  expect_in "$work/err" "missing.obj: cannot read: no such file"
  [ ! -e "$work/a.png" ] || fail "missing input left an output"
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/range.obj"
  echo "previous content" >"$work/keep.png"
  expect_exit 2 "$mb" snapshot "$work/range.obj" "$work/keep.png"
  expect_in "$work/err" "line 4: face corner 3 refers to vertex 9, but the file has 3 vertices"
  [ "$(cat "$work/keep.png")" = "previous content" ] || fail "output overwritten on bad input"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/nodir/a.png"
  expect_in "$work/err" "nodir/a.png: cannot write: the folder '$work/nodir' does not exist"
  [ ! -e "$work/nodir" ] || fail "created a directory"
  mkdir "$work/locked"
  chmod 555 "$work/locked"
  if ! touch "$work/locked/probe" 2>/dev/null; then  # root writes anyway: nothing to test then
    expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/locked/a.png"
    expect_in "$work/err" "cannot write into the folder '$work/locked' (Permission denied)"
    [ -z "$(ls -A "$work/locked")" ] || fail "file left in the locked directory: $(ls -A "$work/locked")"
  fi
  chmod 755 "$work/locked"
  mkdir "$work/dir.png"  # the PNG is written, but cannot replace a directory: the temporary goes
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/dir.png"
  expect_in "$work/err" "dir.png: cannot write: it is a folder"
  ls -a "$work" | grep -q tmp && fail "temporary file left behind: $(ls -a "$work")"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --size 8
  expect_in "$work/err" "--size: Value 8 not in range 16 to 8192"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --view top
  expect_in "$work/err" "--view: top is not auto, iso, x, y, z, -x, -y, -z or a corner such as -x+y+z"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.jpg"
  expect_in "$work/err" "name it .png"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj"
  expect_in "$work/err" "meshbridge snapshot: error: OUT.png is required"
  [ ! -e "$work/a.png" ] && [ ! -e "$work/a.jpg" ] || fail "an output was written on a usage error"
  ;;
arguments)
  expect_exit 0 "$mb" --version
  grep -Eq '^meshbridge [0-9]+\.[0-9]+\.[0-9]+$' "$work/out" || fail "--version: $(cat "$work/out")"
  expect_exit 2 "$mb"  # no command: the overview on stderr, exit 2
  expect_in "$work/err" "Subcommands:"
  expect_exit 0 "$mb" --help
  for command in check repair batch snapshot compare explain; do
    expect_in "$work/out" "  $command "
  done
  # Every command answers --help and -h with its own options (defaults shown); -h is no file name.
  for command in check repair batch snapshot compare explain; do
    for flag in --help -h; do
      expect_exit 0 "$mb" "$command" "$flag"
      expect_in "$work/out" "Usage: meshbridge $command"
    done
  done
  expect_exit 0 "$mb" repair --help
  for option in --report --elements "--pairing TEXT:{geometric,combinatorial}=geometric" --no-orient \
    --no-stitch --cut-nonorientable --remove-duplicates --remove-degenerate --remove-isolated \
    "--weld TEXT:NUMBER>=0|auto=auto" "--separate TEXT:NUMBER>=0|auto=auto"; do
    expect_in "$work/out" "$option"
  done
  # Choices show their words only, never CLI11's mapping of them to values ("{cavity->1,...}").
  for command in check repair batch snapshot compare explain; do
    expect_exit 0 "$mb" "$command" --help
    ! grep -E -- '->|ENUM' "$work/out" || fail "$command --help shows a value mapping (above)"
  done
  for command in check repair batch; do
    expect_exit 0 "$mb" "$command" --help
    expect_in "$work/out" "--nested-shells TEXT:{material,cavity}=material"
  done
  expect_exit 0 "$mb" snapshot --help
  expect_in "$work/out" "--size INT:INT in [16 - 8192]=800"
  expect_in "$work/out" "--view TEXT:VIEW=auto"
  expect_exit 0 "$mb" batch --help
  for option in "--format TEXT:{obj,off,ply,stl,3mf}" "--weld TEXT:NUMBER>=0|auto=auto" --json --quiet --progress --in-place --resume "--jobs"; do
    expect_in "$work/out" "$option"
  done
  # Errors name the command and the bad argument.
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/a.obj" --frobnicate
  expect_in "$work/err" "meshbridge repair: error: The following argument was not expected: --frobnicate"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/a.obj" --separate -1
  expect_in "$work/err" "--separate: expects auto or a finite number >= 0, got '-1'"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/a.obj" --separate inf
  expect_in "$work/err" "got 'inf'"
  expect_exit 2 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --size 12.5
  expect_in "$work/err" "--size"
  expect_exit 2 "$mb" batch "$work" "$work/out" --jobs 0
  expect_in "$work/err" "--jobs: expects a whole number from 1 to 1024, got '0'"
  expect_exit 2 "$mb" frobnicate
  expect_in "$work/err" "frobnicate"
  [ ! -e "$work/a.obj" ] && [ ! -e "$work/a.png" ] || fail "an output was written on a usage error"
  # Choice names are case-insensitive.
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/g.obj" --pairing Geometric
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/c.obj" --pairing=COMBINATORIAL
  ;;
check_self_intersections)
  write_crossing_obj "$work/crossing.obj"
  # Without the flag: no word about them (two closed cubes: exit 0, no key).
  expect_exit 0 "$mb" check "$work/crossing.obj" --json
  grep -q '"self_intersections"' "$work/out" && fail "self_intersections without the flag"
  expect_exit 1 "$mb" check "$work/crossing.obj" --self-intersections
  expect_in "$work/out" "self-intersecting face pairs: 6  [1-8 1-10 3-6 3-10 5-6 5-8]"
  expect_in "$work/out" "faces in them: 6"
  expect_in "$work/out" "pairs of components (shells) crossing: 1  [0-1]"
  expect_exit 1 "$mb" check "$work/crossing.obj" --self-intersections --json
  [ "$(json_field "$work/out" self_intersections.face_pairs)" = 6 ] || fail "face_pairs"
  [ "$(json_field "$work/out" self_intersections.faces)" = 6 ] || fail "faces"
  [ "$(json_field "$work/out" self_intersections.component_pairs)" = 1 ] || fail "component_pairs"
  grep -q '"elements"' "$work/out" && fail "element lists without --elements"
  expect_exit 1 "$mb" check "$work/crossing.obj" --self-intersections --json --elements
  [ "$(json_field "$work/out" 'self_intersections.elements.face_pairs#')" = 6 ] || fail "6 pairs listed"
  [ "$(json_field "$work/out" 'self_intersections.elements.faces#')" = 6 ] || fail "6 faces listed"
  # Two cubes on one edge, and their repair (split copies at equal positions): touching only.
  expect_exit 1 "$mb" check "$models/twocubes.obj" --self-intersections
  expect_in "$work/out" "self-intersecting face pairs: 0"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/fixed.obj"
  expect_exit 0 "$mb" check "$work/fixed.obj" --self-intersections
  expect_in "$work/out" "self-intersecting face pairs: 0"
  # repair --self-intersections: the counts of the result, in the summary and the report.
  expect_exit 0 "$mb" repair "$work/crossing.obj" "$work/crossing_fixed.obj" --self-intersections \
    --report "$work/crossing.json"
  expect_in "$work/out" "self-intersections of the result:"
  expect_in "$work/out" "self-intersecting face pairs: 6"
  [ "$(json_field "$work/crossing.json" self_intersections.face_pairs)" = 6 ] || fail "repair face_pairs"
  [ "$(json_field "$work/crossing.json" self_intersections.component_pairs)" = 1 ] ||
    fail "repair component_pairs"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/fixed2.obj" --self-intersections \
    --report -
  [ "$(json_field "$work/out" self_intersections.face_pairs)" = 0 ] || fail "repaired twocubes"
  expect_exit 0 "$mb" explain self-intersection
  expect_in "$work/out" "shared"
  expect_in "$work/out" "Shown violet: \`snapshot --self-intersections\` and MeshLab's Detect."
  ;;
batch_self_intersections)
  # batch --self-intersections: each output's crossing faces as repair --self-intersections
  # counts them, with any --jobs: the crossing cubes 6 pairs, two cubes on one edge 0.
  mkdir -p "$work/in"
  write_crossing_obj "$work/in/crossing.obj"
  cp "$models/twocubes.obj" "$work/in/"
  for jobs in 1 2; do
    expect_exit 0 "$mb" batch "$work/in" "$work/res$jobs" --self-intersections --json --jobs "$jobs"
    [ "$(json_lines "$work/out")" = 2 ] || fail "2 records"
    [ "$(json_line_field "$work/out" 0 self_intersections.face_pairs)" = 6 ] || fail "crossing pairs"
    [ "$(json_line_field "$work/out" 0 self_intersections.faces)" = 6 ] || fail "crossing faces"
    [ "$(json_line_field "$work/out" 0 self_intersections.component_pairs)" = 1 ] || fail "shells"
    [ "$(json_line_field "$work/out" 1 self_intersections.face_pairs)" = 0 ] || fail "twocubes"
    expect_in "$work/err" "2 file(s): 1 clean, 1 repaired, 0 failed, 0 skipped; 1 with self-intersections"
    cp "$work/out" "$work/jobs$jobs.jsonl"
  done
  cmp -s "$work/jobs1.jsonl" "$work/jobs2.jsonl" || fail "--jobs 2 differs from --jobs 1"
  # The record's object is repair --self-intersections' for the same file.
  expect_exit 0 "$mb" repair "$work/in/crossing.obj" "$work/one.obj" --self-intersections \
    --report "$work/one.json"
  /usr/bin/python3 -c 'import json, sys
one = json.load(open(sys.argv[1]))["self_intersections"]
batch = json.loads(open(sys.argv[2]).readline())["self_intersections"]
sys.exit(one != batch)' "$work/one.json" "$work/jobs1.jsonl" || fail "batch and repair differ"
  expect_exit 0 "$mb" batch "$work/in" "$work/res4" --self-intersections --json --elements
  [ "$(json_line_field "$work/out" 0 'self_intersections.elements.face_pairs#')" = 6 ] || fail "6 pairs listed"
  # The table: a column of the output's pairs; failed files leave it empty.
  printf 'v 0 0 0\nf 1 2 3\n' >"$work/in/broken.obj"
  expect_exit 2 "$mb" batch "$work/in" "$work/table" --self-intersections
  expect_in "$work/out" "| components after | watertight after | self-intersecting pairs | note |"
  expect_in "$work/out" "|---|---|---:|---:|---:|---:|---:|---|---:|---|"
  expect_in "$work/out" "| crossing.obj | clean | 12 | 0 | 0 | 12 | 2 | yes | 6 | |"
  expect_in "$work/out" "| twocubes.obj | repaired | 24 | 1 | 2 | 24 | 2 | yes | 0 | |"
  expect_in "$work/out" "| broken.obj | failed | | | | | | | | "
  expect_in "$work/out" "3 file(s): 1 clean, 1 repaired, 1 failed, 0 skipped; 1 with self-intersections"
  rm "$work/in/broken.obj"
  # Without the flag: no column, no key, the summary as before.
  expect_exit 0 "$mb" batch "$work/in" "$work/plain"
  grep -q "self-intersecting" "$work/out" && fail "a column without --self-intersections"
  expect_in "$work/out" "2 file(s): 1 clean, 1 repaired, 0 failed, 0 skipped"
  # STL outputs: the quads written as triangles, the split copies moved apart (still touching).
  expect_exit 0 "$mb" batch "$work/in" "$work/stl" --self-intersections --json --format stl
  [ "$(json_line_field "$work/out" 0 self_intersections.component_pairs)" = 1 ] || fail "STL shells"
  [ "$(json_line_field "$work/out" 1 self_intersections.face_pairs)" = 0 ] || fail "STL twocubes"
  # The log keeps the option: --resume with it skips, without it redoes both files.
  grep -c " self_intersections=1" "$work/res1/.meshbridge-batch.jsonl" | grep -qx 2 || fail "log"
  expect_exit 0 "$mb" batch "$work/in" "$work/res1" --self-intersections --resume
  expect_in "$work/out" "2 file(s): 0 clean, 0 repaired, 0 failed, 2 skipped"
  expect_exit 0 "$mb" batch "$work/in" "$work/res1" --resume --json
  expect_in "$work/err" "2 file(s): 1 clean, 1 repaired, 0 failed, 0 skipped"
  grep -q '"self_intersections"' "$work/out" && fail "self_intersections without the flag"
  ;;
snapshot_self_intersections)
  # snapshot --self-intersections: the 6 crossing faces violet, counted by the drawing and by
  # ImageMagick alike; none without the flag, none on cubes that only touch (twocubes).
  write_crossing_obj "$work/crossing.obj"
  expect_exit 1 "$mb" snapshot "$work/crossing.obj" "$work/crossing.png" --self-intersections
  expect_in "$work/out" "0 boundary edges, 6 self-intersecting faces; red pixels 0, green pixels 0, violet pixels"
  violet=$(pixels "$work/out" violet)
  [ "${violet:-0}" -gt 10000 ] 2>/dev/null || fail "too few violet pixels: $(cat "$work/out")"
  [ "$(violet_in "$work/crossing.png")" = "$violet" ] ||
    fail "ImageMagick counts $(violet_in "$work/crossing.png") violet pixels, snapshot $violet"
  expect_exit 0 "$mb" snapshot "$work/crossing.obj" "$work/plain.png"
  grep -q violet "$work/out" && fail "violet pixels counted without --self-intersections"
  [ "$(violet_in "$work/plain.png")" = 0 ] || fail "violet without --self-intersections"
  expect_exit 1 "$mb" snapshot "$models/twocubes.obj" "$work/touching.png" --self-intersections
  expect_in "$work/out" "0 self-intersecting faces"
  [ "$(pixels "$work/out" violet)" = 0 ] || fail "violet pixels on twocubes: $(cat "$work/out")"
  [ "$(pixels "$work/out" red)" -gt 0 ] 2>/dev/null || fail "twocubes lost its red edge"
  # repair --self-intersections --before-after: violet on both sides (repair leaves the crossing
  # shells as they are), none on the touching cubes before or after.
  expect_exit 0 "$mb" repair "$work/crossing.obj" "$work/fixed.obj" --self-intersections \
    --before-after "$work/ba.png"
  left=$(violet_in "$work/ba.png" 800x800+0+0)
  right=$(violet_in "$work/ba.png" 800x800+802+0)
  [ "$left" -gt 10000 ] 2>/dev/null || fail "before: $left violet pixels"
  [ "$right" = "$left" ] || fail "after: $right violet pixels, before $left (the same mesh)"
  expect_exit 0 "$mb" repair "$work/crossing.obj" "$work/fixed.obj" --before-after "$work/ba0.png"
  [ "$(violet_in "$work/ba0.png")" = 0 ] || fail "violet in --before-after without --self-intersections"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/fixed.stl" --self-intersections \
    --before-after "$work/ba2.png"
  [ "$(violet_in "$work/ba2.png")" = 0 ] || fail "violet on twocubes before or after (STL read back)"
  ;;
explain)
  expect_exit 0 "$mb" explain
  for term in "singular edge" contender "sides cut" fan "pinch vertex" "set aside" watertight; do
    grep -q "^$term\$" "$work/out" || fail "explain lacks '$term'"
  done
  expect_in "$work/out" "3-7 (4 faces)"
  expect_exit 0 "$mb" explain Fan
  expect_in "$work/out" "umbrella"
  [ "$(grep -c '^[a-zA-Z]' "$work/out")" = 1 ] || fail "explain fan printed more: $(cat "$work/out")"
  expect_exit 0 "$mb" explain sides cut
  expect_in "$work/out" "cut for orientation"
  # --cut-nonorientable: explain, --help and the docs say the same true thing (a breadth-first
  # spanning tree; not necessarily the fewest edges), never "the fewest".
  expect_exit 0 "$mb" explain non-orientable component
  expect_in "$work/out" "With --cut-nonorientable its faces take the orientation of a breadth-first"
  expect_in "$work/out" "the cut makes the piece orientable, but it is not necessarily the fewest edges."
  ! grep -q "cuts the fewest" "$work/out" || fail "explain claims the fewest cut"
  expect_exit 0 "$mb" repair --help
  tr -s ' \n' ' ' <"$work/out" >"$work/help"
  expect_in "$work/help" "with it are cut (not necessarily the fewest). Default: such a component keeps its faces' directions"
  expect_exit 0 "$mb" explain Euler characteristic
  expect_in "$work/out" "where sides were cut for orientation'. Pieces holding stacked face copies"
  # The words today's check and repair reports use resolve, each to an entry that explains it.
  for pair in "midpoint|adds a new vertex in the middle" "edges split at the midpoint|became quads" \
    "stacked face copies|each face once" "nested|--nested-shells cavity makes it a void" \
    "weld|closer than the tolerance" "welded|2^-21" "T-junction|splits" \
    "t-junctions|the long edge at that vertex" "gaps|T-junction closings together" \
    "keyhole|holes left open" "pinched polygon|simple polygons" "vertex copies|copies from split fans" \
    "split fans|copy of the vertex" "topology|vertices - edges + faces" \
    "Euler|vertices - edges + faces" "paired with copies|back to back" \
    "stitched|glued back together" "copies|stacked face copies"; do
    expect_exit 0 "$mb" explain "${pair%%|*}"
    expect_in "$work/out" "${pair#*|}"
  done
  # An exact term prints its entry alone: "midpoint" not also the entries that mention it.
  expect_exit 0 "$mb" explain midpoint
  [ "$(grep -c '^[a-zA-Z]' "$work/out")" = 1 ] || fail "explain midpoint printed more: $(cat "$work/out")"
  # "copies" names no entry exactly: every entry with copies in its name.
  expect_exit 0 "$mb" explain copies
  [ "$(grep -c '^[a-zA-Z]' "$work/out")" = 3 ] || fail "explain copies: $(grep '^[a-zA-Z]' "$work/out")"
  # Out-of-date wording gone: repair prints "watertight yes/no"; only compare has "detached".
  expect_exit 0 "$mb" explain watertight
  expect_in "$work/out" "'watertight yes' or 'watertight no'"
  ! grep -q "calls this 'closed'" "$work/out" || fail "explain watertight: 'closed'"
  expect_exit 0 "$mb" explain detached
  expect_in "$work/out" "Only in \`compare\`"
  ! grep -q "Normally 0" "$work/out" || fail "explain detached: 'Normally 0'"
  expect_exit 2 "$mb" explain frobnicate
  expect_in "$work/err" "no entry for 'frobnicate'; known terms: manifold, singular edge"
  ;;
progress)
  # On a pipe: nothing unless --progress, then one line per stage (MESHBRIDGE_PROGRESS_DELAY=0:
  # from the start instead of after a second).
  export MESHBRIDGE_PROGRESS_DELAY=0
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/a.obj"
  [ ! -s "$work/err" ] || fail "progress on a pipe without --progress: $(cat "$work/err")"
  expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/a.obj" --progress
  [ "$(grep -c '%  ' "$work/err")" = 5 ] || fail "repair stages: $(cat "$work/err")"
  for stage in read group pair detect write; do
    grep -Eq "twocubes.obj  \[[#.]{24}\] [0-9]+%  $stage  0:00$" "$work/err" || fail "no $stage line"
  done
  expect_in "$work/out" "-> $work/a.obj"
  expect_exit 1 "$mb" check "$models/twocubes.obj" --progress
  [ "$(grep -c '%  ' "$work/err")" = 2 ] || fail "check stages: $(cat "$work/err")"
  expect_in "$work/err" "0%  read"
  expect_in "$work/err" "60%  detect"
  expect_exit 1 "$mb" snapshot "$models/twocubes.obj" "$work/a.png" --progress
  expect_in "$work/err" "80%  write"
  # A terminal (script(1) gives one): the line is redrawn in place and erased at the end.
  if command -v script >/dev/null; then
    script -qec "'$mb' repair '$models/twocubes.obj' '$work/t.obj'" /dev/null >"$work/tty" 2>&1 ||
      fail "repair on a terminal: $(cat "$work/tty")"
    grep -q $'\r.*twocubes.obj  \[.*write' "$work/tty" || fail "no bar on a terminal: $(cat -v "$work/tty")"
    grep -q $'\r\033\[K' "$work/tty" || fail "bar not erased: $(cat -v "$work/tty")"
  fi
  # Work that ends within the delay shows nothing (the default delay is 1 s).
  MESHBRIDGE_PROGRESS_DELAY=600 expect_exit 0 "$mb" repair "$models/twocubes.obj" "$work/a.obj" --progress
  [ ! -s "$work/err" ] || fail "progress for work within the delay: $(cat "$work/err")"
  unset MESHBRIDGE_PROGRESS_DELAY
  ;;
messages)
  # A crack of 2e-6 in a unit tetrahedron (each face written with its own corners) is wider than
  # the automatic weld tolerance: check says what a wider one would weld, and it does.
  printf 'v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0.000002 0 0\nv 1.000002 0 0\nv 0 0 1\nv 0 0.000002 0\nv 0 0 1.000002\nv 0 1.000002 0\nv 1 0.000002 0\nv 0 1 0.000002\nv 0 0.000002 1\nf 1 2 3\nf 4 5 6\nf 7 8 9\nf 10 11 12\n' >"$work/crack.obj"
  expect_exit 0 "$mb" check "$work/crack.obj"  # repair (automatic tolerance) would change nothing
  expect_in "$work/out" "repair would change nothing (12 boundary edges stay open); it refuses 0 welds and 7 T-junction closings (with them the repaired mesh would have 13 open edges (without: 12))"
  expect_in "$work/out" "hint: 12 boundary edges; cracks wider than the automatic tolerance stay open: --weld 5e-05 would weld 8 vertices (largest move 2e-06)"
  expect_exit 0 "$mb" repair "$work/crack.obj" "$work/crack_out.obj" --weld 5e-05
  expect_in "$work/out" "after: singular edges 0, singular vertices 0, non-orientable components 0, watertight yes"
  expect_exit 0 "$mb" check "$work/crack_out.obj"
  grep -q "hint:" "$work/out" && fail "a hint on a closed mesh"
  # Each names the path and the cause, before any work is done.
  expect_exit 2 "$mb" check "$work/no/such/folder/a.obj"
  expect_in "$work/err" "$work/no/such/folder/a.obj: cannot read: the folder '$work/no' does not exist"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/nodir/sub/out.obj"
  expect_in "$work/err" "$work/nodir/sub/out.obj: cannot write: the folder '$work/nodir' does not exist"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/out.obj" --report "$work/nodir/r.json"
  expect_in "$work/err" "r.json: cannot write: the folder '$work/nodir' does not exist"
  [ ! -e "$work/out.obj" ] || fail "repair wrote its output before failing on the report's folder"
  touch "$work/plain"
  expect_exit 2 "$mb" repair "$models/twocubes.obj" "$work/plain/out.obj"
  expect_in "$work/err" "cannot write: '$work/plain' is not a folder"
  # Permission denied, with the OS reason: as an unprivileged user (root may write anywhere).
  mkdir "$work/locked" "$work/secret"
  cp "$models/twocubes.obj" "$work/secret/a.obj"
  chmod 555 "$work/locked"
  chmod 000 "$work/secret/a.obj"
  as_user=()
  if [ "$(id -u)" -eq 0 ]; then
    command -v setpriv >/dev/null && as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
    chmod 755 "$work"
  fi
  if [ "$(id -u)" -ne 0 ] || [ ${#as_user[@]} -gt 0 ]; then
    # The input is copied into $work: the checkout itself may be private to its owner.
    cp "$models/twocubes.obj" "$work/public.obj"
    chmod 644 "$work/public.obj"
    expect_exit 2 "${as_user[@]}" "$mb" repair "$work/public.obj" "$work/locked/a.obj"
    expect_in "$work/err" "$work/locked/a.obj: cannot write into the folder '$work/locked' (Permission denied)"
    # A read-only file in a writable folder is not replaced (renaming over it would be allowed).
    mkdir "$work/open" && chmod 777 "$work/open"
    echo "keep me" >"$work/open/readonly.obj" && chmod 444 "$work/open/readonly.obj"
    expect_exit 2 "${as_user[@]}" "$mb" repair "$work/public.obj" "$work/open/readonly.obj"
    expect_in "$work/err" "$work/open/readonly.obj: cannot write (Permission denied): the file is read-only"
    [ "$(cat "$work/open/readonly.obj")" = "keep me" ] || fail "a read-only output was replaced"
    expect_exit 2 "${as_user[@]}" "$mb" check "$work/secret/a.obj"
    expect_in "$work/err" "$work/secret/a.obj: cannot read (Permission denied)"
  else
    echo "messages: permission checks skipped (root without setpriv)"
  fi
  chmod 755 "$work/locked"
  # Disk full (ENOSPC) on an 8 KiB tmpfs in a private mount namespace, where unshare allows it.
  mkdir "$work/full"
  if unshare -rm true 2>/dev/null; then
    # shellcheck disable=SC2016
    full_run() {  # full_run COMMAND...: runs COMMAND with an 8 KiB tmpfs mounted on $work/full
      unshare -rm sh -c 'mount -t tmpfs -o size=8k tmpfs "$0" && exec "$@"' "$work/full" "$@"
    }
    expect_exit 2 full_run sh -c 'head -c 6000 /dev/zero >"$0/fill" 2>/dev/null; exec "$@"' \
      "$work/full" "$mb" repair "$models/prisms24.obj" "$work/full/a.obj"
    expect_in "$work/err" "$work/full/a.obj"
    expect_in "$work/err" "No space left on device"
    expect_exit 2 full_run sh -c 'head -c 9000 /dev/zero >"$0/fill" 2>/dev/null; exec "$@"' \
      "$work/full" "$mb" repair "$models/prisms24.obj" "$work/b.obj" --report "$work/full/r.json"
    expect_in "$work/err" "$work/full/r.json: cannot write the report (write failed (No space left on device)); $work/b.obj is written"
    expect_exit 2 full_run sh -c 'head -c 9000 /dev/zero >"$0/fill" 2>/dev/null; exec "$@"' \
      "$work/full" "$mb" snapshot "$models/prisms24.obj" "$work/full/a.png"
    expect_in "$work/err" "$work/full/a.png: write failed (No space left on device)"
  else
    echo "messages: disk-full checks skipped (unshare -rm not permitted here)"
  fi
  ;;
snapshot_views)
  # --focus defects zooms in: prisms24's defects span the model, the hole of cube_with_hole does
  # not, so its green rim gets longer (more green pixels) when zoomed.
  expect_exit 1 "$mb" snapshot "$models/cube_with_hole.obj" "$work/whole.png" --size 400 --view iso
  expect_in "$work/out" "cube_with_hole.obj ->"
  whole=$(pixels "$work/out" green)
  expect_exit 1 "$mb" snapshot "$models/cube_with_hole.obj" "$work/zoom.png" --size 400 --focus defects --view iso
  zoom=$(pixels "$work/out" green)
  [ "$zoom" -gt "$whole" ] 2>/dev/null || fail "--focus defects did not zoom: $whole -> $zoom green"
  [ "$(pixels "$work/out" red)" = 0 ] || fail "red pixels for cube_with_hole"
  expect_exit 0 "$mb" snapshot "$models/icosphere.obj" "$work/ico.png" --focus DEFECTS --size 64
  [ "$(pixels "$work/out" red)" = 0 ] && [ "$(pixels "$work/out" green)" = 0 ] || fail "icosphere"
  expect_exit 2 "$mb" snapshot "$models/icosphere.obj" "$work/ico.png" --focus edges
  expect_in "$work/err" "--focus: edges not in {auto,whole,defects}"
  # The default (auto) zooms toward defects that are small, keeping the model around them: a
  # closed cube with a tiny open triangle beside a corner.
  { sed -n '/^v /p' "$models/icosphere.obj"; echo 'v 1.1 1.1 1.1'; echo 'v 1.14 1.1 1.1'; echo 'v 1.1 1.14 1.1'
    sed -n '/^f /p' "$models/icosphere.obj"; n=$(grep -c '^v ' "$models/icosphere.obj")
    echo "f $((n + 1)) $((n + 2)) $((n + 3))"; } >"$work/speck.obj"
  expect_exit 1 "$mb" snapshot "$work/speck.obj" "$work/speck_whole.png" --focus whole
  whole=$(pixels "$work/out" green)
  expect_exit 1 "$mb" snapshot "$work/speck.obj" "$work/speck_auto.png"
  auto=$(pixels "$work/out" green)
  expect_exit 1 "$mb" snapshot "$work/speck.obj" "$work/speck_defects.png" --focus defects
  zoom=$(pixels "$work/out" green)
  [ "$whole" -lt "$auto" ] && [ "$auto" -lt "$zoom" ] 2>/dev/null ||
    fail "auto focus between whole and defects: $whole < $auto < $zoom green pixels"
  # The surface is shaded grey: many grey levels, not a wireframe on white.
  if command -v convert >/dev/null; then
    levels=$(convert "$work/whole.png" -colorspace gray -format %k info:)
    [ "$levels" -ge 4 ] 2>/dev/null || fail "only $levels grey levels in the shaded picture"
  fi
  # repair --before-after: the input and the result side by side, red only on the left.
  expect_exit 0 "$mb" repair "$models/prisms24.obj" "$work/p.obj" --before-after "$work/ba.png"
  is_png "$work/ba.png" || fail "ba.png is not a PNG"
  [ "$(png_size "$work/ba.png")" = 1602x800 ] || fail "before-after size: $(png_size "$work/ba.png")"
  if command -v convert >/dev/null; then
    red_in() {  # red_in FILE GEOMETRY -> count of (220,0,0)-ish pixels in that part
      convert "$1" -crop "$2" +repage -fuzz 18% -fill black +opaque 'rgb(220,0,0)' \
        -fill white -opaque 'rgb(220,0,0)' -format '%[fx:round(mean*w*h)]' info:
    }
    [ "$(red_in "$work/ba.png" 800x800+0+0)" -gt 100 ] 2>/dev/null || fail "no red on the left"
    [ "$(red_in "$work/ba.png" 800x800+802+0)" = 0 ] || fail "red on the right (after repair)"
    # A 3MF whose polygons were cut into triangles (UR20: 4 edges split at their midpoint) is
    # drawn too: the right half once came out empty.
    expect_exit 0 "$mb" repair "$models/../../tests/data/realworld2/ur_ur20_forearm_collision.stl" \
      "$work/ur.3mf" --before-after "$work/ur.png"
    shaded=$(convert "$work/ur.png" -crop 760x700+822+80 +repage -fuzz 3% -fill black +opaque white \
      -fill white -opaque white -negate -format '%[fx:round(mean*w*h)]' info:)
    [ "$shaded" -gt 50000 ] 2>/dev/null || fail "the 3MF result is not drawn: $shaded model pixels"
    # A keyhole polygon (assimp's ring) is drawn as the file has it on the left, its hole open
    # (the middle is the white background), as the repaired triangles are on the right: the two
    # halves shade about as many pixels (main drew the hole filled: 364974 against 54912).
    expect_exit 0 "$mb" repair "$models/../../tests/data/realworld2/assimp_concave_polygon.obj" \
      "$work/ring.obj" --before-after "$work/ring.png" --view x
    model_pixels() {  # model_pixels FILE GEOMETRY -> count of pixels that are not white there
      convert "$1" -crop "$2" +repage -fuzz 3% -fill black +opaque white -fill white -opaque white \
        -negate -format '%[fx:round(mean*w*h)]' info:
    }
    left=$(model_pixels "$work/ring.png" 800x700+0+80)
    right=$(model_pixels "$work/ring.png" 800x700+802+80)
    [ "$right" -gt 50000 ] && [ "$left" -gt $((right * 95 / 100)) ] &&
      [ "$left" -lt $((right * 105 / 100)) ] 2>/dev/null ||
      fail "keyhole before/after: $left model pixels on the left, $right on the right"
    [ "$(convert "$work/ring.png" -format '%[pixel:p{400,420}]' info:)" = "srgba(255,255,255,1)" ] ||
      fail "keyhole's hole covered in the before half"
  fi
  expect_exit 2 "$mb" repair "$models/prisms24.obj" "$work/q.obj" --before-after "$work/ba.jpg"
  expect_in "$work/err" "name it .png"
  [ ! -e "$work/q.obj" ] || fail "repair wrote its output despite a bad --before-after"
  # --view and --focus draw --before-after as snapshot draws: cube_with_hole's hole, zoomed to,
  # has a longer green rim on the left than in the whole view.
  if command -v convert >/dev/null; then
    green_in() {  # green_in FILE GEOMETRY -> count of green-ish pixels in that part
      convert "$1" -crop "$2" +repage -fuzz 18% -fill black +opaque 'rgb(0,160,0)' \
        -fill white -opaque 'rgb(0,160,0)' -format '%[fx:round(mean*w*h)]' info:
    }
    expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/h.obj" --before-after "$work/hw.png" --view iso
    expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/h.obj" --before-after "$work/hz.png" --view z --focus defects
    whole=$(green_in "$work/hw.png" 800x800+0+0)
    zoom=$(green_in "$work/hz.png" 800x800+0+0)
    [ "$zoom" -gt "$whole" ] 2>/dev/null || fail "--before-after --focus defects did not zoom: $whole -> $zoom green"
    # --up y: a strip 10 long along +y stands upright from the side (--view x); with +z up it lies
    # flat, a horizontal line through the middle, nothing in the top quarter.
    printf 'v 0 0 0\nv 0 0 0.1\nv 0 10 0.1\nv 0 10 0\nf 1 2 3 4\n' >"$work/strip.obj"
    expect_exit 1 "$mb" snapshot "$work/strip.obj" "$work/flat.png" --view x
    expect_exit 1 "$mb" snapshot "$work/strip.obj" "$work/upright.png" --view x --up Y
    expect_in "$work/out" "(800x800, view x, y up)"
    [ "$(green_in "$work/flat.png" 800x200+0+0)" = 0 ] || fail "z up: the strip is not flat"
    [ "$(green_in "$work/upright.png" 800x200+0+0)" -gt 50 ] 2>/dev/null || fail "--up y: the strip does not stand"
    expect_exit 0 "$mb" repair "$work/strip.obj" "$work/s.obj" --before-after "$work/sba.png" --view x --up y
    [ "$(green_in "$work/sba.png" 800x200+0+0)" -gt 50 ] 2>/dev/null || fail "--before-after --up y"
  fi
  # --view auto (the default) looks from where the defects show. A unit box with a fin on its
  # back vertical edge (x = y = 0): iso (from +x+y+z) sees only the dot at the edge's top end;
  # auto picks the side view from +x, where the red edge and the fin's green rim show.
  printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nv -0.3 -0.3 0.5\n%s\n' \
    'f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
f 1 5 9' >"$work/finbox.obj"
  defect_pixels() { echo $(($(pixels "$1" red) + $(pixels "$1" green))); }
  expect_exit 1 "$mb" snapshot "$work/finbox.obj" "$work/fin_iso.png" --size 400 --view iso
  iso=$(defect_pixels "$work/out")
  expect_exit 1 "$mb" snapshot "$work/finbox.obj" "$work/fin_auto.png" --size 400
  expect_in "$work/out" "(400x400, view auto -> x):"
  auto=$(defect_pixels "$work/out")
  [ "$(pixels "$work/out" green)" -gt 100 ] 2>/dev/null || fail "auto: the fin's green rim is not seen"
  [ "$auto" -gt $((10 * iso)) ] 2>/dev/null || fail "auto shows $auto defect pixels, iso $iso"
  expect_exit 1 "$mb" snapshot "$work/finbox.obj" "$work/fin_x.png" --size 400 --view X
  [ "$(defect_pixels "$work/out")" = "$auto" ] || fail "auto -> x differs from --view x"
  # The same box written y-up (file y = model z): with --up y the same view, the same pixels.
  awk '/^v /{print "v", $2, $4, -$3; next} {print}' "$work/finbox.obj" >"$work/finbox_y.obj"
  expect_exit 1 "$mb" snapshot "$work/finbox_y.obj" "$work/fin_y.png" --size 400 --up y
  expect_in "$work/out" "(400x400, view auto -> x, y up):"
  [ "$(defect_pixels "$work/out")" = "$auto" ] || fail "--up y: $(cat "$work/out")"
  # Other views by name; a name printed by auto is taken back by --view.
  expect_exit 1 "$mb" snapshot "$work/finbox.obj" "$work/fin_c.png" --size 64 --view -x-y+z
  expect_in "$work/out" "(64x64, view -x-y+z):"
  expect_exit 1 "$mb" snapshot "$work/finbox.obj" "$work/fin_c.png" --size 64 --view=+X+y+z
  expect_in "$work/out" "(64x64, view iso):"
  expect_exit 2 "$mb" snapshot "$work/finbox.obj" "$work/fin_c.png" --view=+x+y
  expect_in "$work/err" "--view: +x+y is not auto, iso, x, y, z, -x, -y, -z or a corner such as -x+y+z"
  # Where iso already shows the most, auto keeps it: prisms24.
  expect_exit 1 "$mb" snapshot "$models/prisms24.obj" "$work/p_iso.png" --size 300 --view iso
  iso=$(defect_pixels "$work/out")
  expect_exit 1 "$mb" snapshot "$models/prisms24.obj" "$work/p_auto.png" --size 300
  expect_in "$work/out" "(300x300, view auto -> iso):"
  [ "$(defect_pixels "$work/out")" = "$iso" ] || fail "prisms24: auto is not iso"
  # Real files, each with defects iso hides or shows small: a printer (Cura's Weedo X40: the
  # bed's underside), the UR20 forearm (a seam seen from above), a cycloidal drive (pinch
  # vertices under its base). Auto shows strictly more defect pixels than iso.
  data="$models/../../tests/data"
  for file in realworld2/cura_weedo_x40.3mf realworld2/ur_ur20_forearm_collision.stl \
    realworld/trimesh_cycloidal.ply; do
    expect_exit 1 "$mb" snapshot "$data/$file" "$work/rw_iso.png" --size 400 --view iso
    iso=$(defect_pixels "$work/out")
    expect_exit 1 "$mb" snapshot "$data/$file" "$work/rw_auto.png" --size 400
    expect_in "$work/out" "view auto -> "
    auto=$(defect_pixels "$work/out")
    [ "$auto" -gt "$iso" ] 2>/dev/null || fail "$file: auto $auto defect pixels, iso $iso"
  done
  if command -v convert >/dev/null; then
    # The counts are those of the PNG.
    [ "$(red_in "$work/fin_auto.png" 400x400+0+0)" -gt 300 ] 2>/dev/null || fail "fin_auto.png: no red"
    [ "$(green_in "$work/fin_auto.png" 400x400+0+0)" -gt 100 ] 2>/dev/null || fail "fin_auto.png: no green"
    [ "$(green_in "$work/fin_iso.png" 400x400+0+0)" = 0 ] || fail "fin_iso.png: green"
    # repair --before-after takes the view auto chooses for the input, both halves alike.
    expect_exit 0 "$mb" repair "$work/finbox.obj" "$work/f.obj" --before-after "$work/fba.png"
    expect_in "$work/out" "before/after picture $work/fba.png: view auto -> x"
    [ "$(red_in "$work/fba.png" 800x800+0+0)" -gt 300 ] 2>/dev/null || fail "fba.png: no red on the left"
    [ "$(green_in "$work/fba.png" 800x800+802+0)" -gt 100 ] 2>/dev/null || fail "fba.png: no green on the right"
    expect_exit 0 "$mb" repair "$work/finbox.obj" "$work/f.obj" --before-after "$work/fba.png" --view iso
    expect_in "$work/out" "before/after picture $work/fba.png: view iso"
    [ "$(red_in "$work/fba.png" 800x800+0+0)" -lt 100 ] 2>/dev/null || fail "fba.png, iso: the fin is seen"
  fi
  expect_exit 2 "$mb" repair "$models/prisms24.obj" "$work/q.obj" --view z
  expect_in "$work/err" "--view draws the --before-after picture: give --before-after PIC.png too"
  ;;
fill_holes)
  # --fill-holes [MAX_EDGES]: off by default; bare = 32; the summary line and the JSON `holes`.
  expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/plain.obj" --report "$work/plain.json"
  expect_in "$work/out" "holes: not filled (off)"
  grep -q '"holes"' "$work/plain.json" && fail "holes in the report of a repair without --fill-holes"
  [ "$(json_field "$work/plain.json" faces_out)" = 10 ] || fail "faces_out without filling"
  expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/f.obj" --report "$work/f.json" --fill-holes
  expect_in "$work/out" "holes (up to 32 edges): 1 filled with 2 new triangles, 0 left open"
  expect_in "$work/out" "boundary edges: 4 -> 0"
  expect_in "$work/out" "watertight yes"
  [ "$(json_field "$work/f.json" holes.max_edges)" = 32 ] || fail "holes.max_edges"
  [ "$(json_field "$work/f.json" holes.holes_filled)" = 1 ] || fail "holes.holes_filled"
  [ "$(json_field "$work/f.json" holes.faces_added)" = 2 ] || fail "holes.faces_added"
  [ "$(json_field "$work/f.json" holes.holes_left)" = 0 ] || fail "holes.holes_left"
  [ "$(json_field "$work/f.json" faces_out)" = 12 ] || fail "faces_out with the hole filled"
  [ "$(json_field "$work/f.json" after.watertight)" = true ] || fail "after.watertight"
  expect_exit 0 "$mb" check "$work/f.obj"
  expect_in "$work/out" "watertight yes"
  # A number after the flag; a loop longer than it stays open and is counted.
  expect_exit 0 "$mb" repair "$models/cube_with_hole.obj" "$work/l.obj" --fill-holes 3 --report "$work/l.json"
  expect_in "$work/out" "holes (up to 3 edges): 0 filled with 0 new triangles, 1 left open"
  [ "$(json_field "$work/l.json" holes.holes_left)" = 1 ] || fail "holes.holes_left with 3"
  [ "$(json_field "$work/l.json" faces_out)" = 10 ] || fail "faces_out with the hole left open"
  expect_exit 2 "$mb" repair "$models/cube_with_hole.obj" "$work/x.obj" --fill-holes x
  expect_in "$work/err" "--fill-holes: expects a whole number from 0 to 1000000, got 'x'"
  # Bare before IN and OUT: fine when they end the line, a clear error when options follow.
  expect_exit 0 "$mb" repair --fill-holes "$models/cube_with_hole.obj" "$work/b.obj"
  expect_in "$work/out" "1 filled with 2 new triangles"
  expect_exit 0 "$mb" repair --fill-holes=4 "$models/cube_with_hole.obj" "$work/b.obj" --report "$work/b.json"
  [ "$(json_field "$work/b.json" holes.max_edges)" = 4 ] || fail "--fill-holes=4"
  expect_exit 2 "$mb" repair --fill-holes "$models/cube_with_hole.obj" "$work/b.obj" --report "$work/b.json"
  expect_in "$work/err" "put it after IN and OUT, or write --fill-holes=N"
  # Face colours: the input's stay with their faces, the new triangle has none (OFF lets a face
  # go without; PLY, a colour on every face or none, gives it the default).
  printf 'OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1 200 0 0 255\n3 0 1 3 0 200 0 255\n3 0 3 2 0 0 200 255\n' >"$work/tet.off"
  expect_exit 0 "$mb" repair "$work/tet.off" "$work/tet_out.off" --fill-holes
  expect_in "$work/out" "1 filled with 1 new triangle,"
  [ "$(sed -n 7,10p "$work/tet_out.off" | awk '{print NF ":" $5, $6, $7, $8}' | tr '\n' ' ')" = \
    "8:200 0 0 255 8:0 200 0 255 8:0 0 200 255 4:    " ] || fail "face colours: $(cat "$work/tet_out.off")"
  expect_exit 0 "$mb" repair "$work/tet.off" "$work/tet_out.ply" --fill-holes
  # Binary faces: uchar count, 3 ints, then red green blue alpha: the last 4 faces' 17 bytes.
  [ "$(tail -c 68 "$work/tet_out.ply" | od -An -v -tu1 -w17 | awk '{print $14, $15, $16, $17}' | tr '\n' ' ')" = \
    "200 0 0 255 0 200 0 255 0 0 200 255 0 0 0 255 " ] || fail "PLY face colours: $(od -c "$work/tet_out.ply")"
  # batch: the filled file counts as repaired and is closed; a closed one stays clean.
  mkdir -p "$work/in"
  cp "$models/cube_with_hole.obj" "$models/icosphere.obj" "$work/in/"
  expect_exit 0 "$mb" batch "$work/in" "$work/res" --fill-holes
  expect_in "$work/out" "| cube_with_hole.obj | repaired | 10 | 0 | 0 | 12 | 1 | yes |"
  expect_in "$work/out" "| icosphere.obj | clean | 80 | 0 | 0 | 80 | 1 | yes |"
  expect_exit 0 "$mb" batch "$work/in" "$work/resj" --json --quiet --fill-holes 8
  [ "$(json_line_field "$work/out" 0 holes.faces_added)" = 2 ] || fail "batch holes.faces_added"
  [ "$(json_line_field "$work/out" 0 holes.max_edges)" = 8 ] || fail "batch holes.max_edges"
  [ "$(json_line_field "$work/out" 1 holes.holes_filled)" = 0 ] || fail "batch: icosphere has no hole"
  ;;
pictures_module)
  # Qt is loaded with the meshbridge_pictures module, by the commands that draw only: the
  # executable does not link it, and without the module those commands fail cleanly, naming
  # the folders they looked in, while the others work.
  if ldd "$mb" | grep -q 'libQt5'; then
    fail "meshbridge links Qt: $(ldd "$mb" | grep libQt5)"
  fi
  mkdir "$work/alone"
  cp "$mb" "$work/alone/meshbridge"
  expect_exit 1 "$work/alone/meshbridge" check "$models/twocubes.obj"
  expect_in "$work/out" "singular edges: 1"
  expect_exit 2 "$work/alone/meshbridge" snapshot "$models/twocubes.obj" "$work/a.png"
  expect_in "$work/err" "meshbridge snapshot: error: cannot draw pictures: meshbridge_pictures module not found in $work/alone, "
  expect_in "$work/err" "/meshbridge (looked for meshbridge_pictures"
  [ ! -e "$work/a.png" ] || fail "snapshot without the module wrote a PNG"
  # --before-after is checked before the repair: no output either.
  expect_exit 2 "$work/alone/meshbridge" repair "$models/twocubes.obj" "$work/a.obj" --before-after "$work/a.png"
  expect_in "$work/err" "cannot draw pictures: meshbridge_pictures module not found in $work/alone"
  [ ! -e "$work/a.obj" ] && [ ! -e "$work/a.png" ] || fail "repair without the module wrote output"
  expect_exit 0 "$work/alone/meshbridge" repair "$models/twocubes.obj" "$work/a.obj"
  # A module that is not a shared library: the loader's reason, no crash.
  echo "not a library" >"$work/alone/$(basename "$(ls "$(dirname "$mb")"/meshbridge_pictures.*)")"
  expect_exit 2 "$work/alone/meshbridge" snapshot "$models/twocubes.obj" "$work/a.png"
  expect_in "$work/err" "meshbridge snapshot: error: cannot draw pictures: $work/alone/meshbridge_pictures"
  [ ! -e "$work/a.png" ] || fail "snapshot with a broken module wrote a PNG"
  ;;
batch_warnings)
  # Harmless warnings (STL solid names, float rounding) once per kind with a count; lost data
  # (texture coordinates and normals) once per file; --quiet prints none, errors only.
  mkdir -p "$work/in"
  for n in 1 2 3; do
    printf 'solid part%s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid part%s\n' "$n" "$n" >"$work/in/s$n.stl"
    printf 'v 0.1 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n' >"$work/in/uv$n.obj"
  done
  expect_exit 0 "$mb" batch "$work/in" "$work/out_stl" --format stl
  [ "$(grep -c 'solid names' "$work/err")" = 1 ] || fail "solid names once: $(cat "$work/err")"
  expect_in "$work/err" "meshbridge: warning: 3 files: ASCII STL solid names not written (MeshBridge reads past them)"
  expect_in "$work/err" "meshbridge: warning: 3 files: vertex positions rounded to 32-bit floats (STL and 3MF hold no more)"
  for n in 1 2 3; do
    expect_in "$work/err" "meshbridge: warning: uv$n.obj: output uv$n.stl: 1 texture coordinate (vt) and 1 normal (vn) not written"
  done
  [ "$(wc -l <"$work/err")" = 5 ] || fail "5 warning lines: $(cat "$work/err")"
  expect_exit 0 "$mb" batch "$work/in" "$work/out_quiet" --format stl --quiet
  [ ! -s "$work/err" ] || fail "--quiet printed: $(cat "$work/err")"
  printf 'v 0 0 0\nf 1 2 3\n' >"$work/in/broken.obj"
  expect_exit 2 "$mb" batch "$work/in" "$work/out_quiet2" --quiet
  [ ! -s "$work/err" ] || fail "--quiet printed on stderr (the failure is in the table): $(cat "$work/err")"
  expect_in "$work/out" "| broken.obj | failed |"
  # On a terminal (script(1) gives one) the progress line is erased before each table row and
  # warning: no visible line holds both.
  if command -v script >/dev/null; then
    script -qec "'$mb' batch '$work/in' '$work/out_tty' --jobs 2" /dev/null >"$work/tty" 2>&1
    grep -q $'\033\[K\[[0-9]*/7\]' "$work/tty" || fail "no progress on a terminal: $(cat -v "$work/tty")"
    # What the terminal shows of each line: the text after its last carriage return.
    tr -d '\033' <"$work/tty" | sed -e 's/\[K//g' -e 's/\r$//' | awk -F'\r' '{print $NF}' >"$work/visible"
    ! grep -E '\[[0-9]+/7\].*(\||warning)|(\||warning).*\[[0-9]+/7\]' "$work/visible" ||
      fail "progress mixed with the table: $(cat -v "$work/visible")"
    [ "$(grep -c '^|' "$work/visible")" = 9 ] || fail "9 table lines: $(cat -v "$work/visible")"
  fi
  ;;
interop)
  # OBJ vertex colours: RGB only unless alpha carries information (Open3D reads
  # "v x y z r g b a" as 0 points).
  header='ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
  printf "$header"'0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n' >"$work/opaque.ply"
  expect_exit 0 "$mb" repair "$work/opaque.ply" "$work/opaque.obj"
  [ "$(grep -c '^v [^ ]* [^ ]* [^ ]* [^ ]* [^ ]* [^ ]*$' "$work/opaque.obj")" = 3 ] ||
    fail "opaque colours: v x y z r g b: $(cat "$work/opaque.obj")"
  printf "$header"'0 0 0 255 0 0 128\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n' >"$work/seethrough.ply"
  expect_exit 0 "$mb" repair "$work/seethrough.ply" "$work/seethrough.obj"
  [ "$(grep -c '^v [^ ]* [^ ]* [^ ]* [^ ]* [^ ]* [^ ]* [^ ]*$' "$work/seethrough.obj")" = 3 ] ||
    fail "alpha that carries information is kept: $(cat "$work/seethrough.obj")"
  # A PLY header line that is neither a keyword nor a comment (Blender 2.47) is read past with a
  # warning naming it, as MeshLab and Blender read it.
  printf 'ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: ""\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$work/blender.ply"
  expect_exit 0 "$mb" check "$work/blender.ply"  # one triangle: repair would change nothing
  expect_in "$work/out" "vertices 3, faces 1"
  expect_in "$work/err" "meshbridge: warning: $work/blender.ply: PLY header lines that are neither keywords nor comments, read past (the first, line 3: 'Created by Blender3D 247 - www.blender.org, source file: \"\"'), on 1 line"
  expect_exit 0 "$mb" repair "$work/blender.ply" "$work/blender_out.ply"
  # OBJ texture coordinates and normals through a repair: twocubes with a vt of its own on every
  # corner and one vn. The output keeps all 72 vt and the vn, every face v/vt/vn, and each
  # corner's position with its vt is one of the input's (the split vertices' copies carry the vt
  # of their own faces' corners); nothing is said to be lost.
  awk '/^v /{print; next} /^f /{f[++n]=$0} END{for (k = 0; k < 3 * n; ++k) print "vt " k / 128 " " 1 - k / 128; print "vn 0 0 1"; for (i = 1; i <= n; ++i) {split(f[i], c, " "); print "f " c[2] "/" 3*i-2 "/1 " c[3] "/" 3*i-1 "/1 " c[4] "/" 3*i "/1"}}' \
    "$models/twocubes.obj" >"$work/uv_cubes.obj"
  expect_exit 0 "$mb" repair "$work/uv_cubes.obj" "$work/uv_cubes_out.obj"
  expect_in "$work/out" "vertices: 14 in, 16 out"
  grep -q "not written" "$work/err" && fail "textured OBJ to OBJ lost something: $(cat "$work/err")"
  [ "$(grep -c '^vt ' "$work/uv_cubes_out.obj")" = 72 ] || fail "72 vt: $(grep -c '^vt ' "$work/uv_cubes_out.obj")"
  [ "$(grep -c '^vn 0 0 1$' "$work/uv_cubes_out.obj")" = 1 ] || fail "one vn"
  [ "$(grep -c '^f [0-9]*/[0-9]*/1 [0-9]*/[0-9]*/1 [0-9]*/[0-9]*/1$' "$work/uv_cubes_out.obj")" = 24 ] ||
    fail "24 faces v/vt/vn: $(grep '^f' "$work/uv_cubes_out.obj" | head -3)"
  corners_with_vt() {  # "x y z | u v" of every face corner, sorted
    awk '/^v /{p[++v]=$2" "$3" "$4} /^vt /{t[++u]=$2" "$3} /^f /{for (i = 2; i <= NF; ++i) {split($i, c, "/"); print p[c[1]] " | " t[c[2]]}}' "$1" | sort
  }
  [ "$(corners_with_vt "$work/uv_cubes.obj")" = "$(corners_with_vt "$work/uv_cubes_out.obj")" ] ||
    fail "a corner's vt changed: $(diff <(corners_with_vt "$work/uv_cubes.obj") <(corners_with_vt "$work/uv_cubes_out.obj") | head -4)"
  # To STL they cannot go (no vt per corner there): said.
  expect_exit 0 "$mb" repair "$work/uv_cubes.obj" "$work/uv_cubes_out.stl"
  expect_in "$work/err" "uv_cubes_out.stl: 72 texture coordinates (vt) and 1 normal (vn) not written: STL holds none per corner (write OBJ to keep them)"
  # A hole filled in a textured OBJ: its new faces have no vt or vn, written 'f a b c' and said.
  if "$mb" repair --help | grep -q -- --fill-holes; then
    printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 -1\nf 1/1/1 4/4/1 3/3/1 2/2/1\nf 1/1 2/2 6/3 5/4\nf 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n' >"$work/uv_open.obj"
    expect_exit 0 "$mb" repair "$work/uv_open.obj" "$work/uv_open_out.obj" --fill-holes
    expect_in "$work/err" "uv_open_out.obj: 2 faces added by hole filling written without texture coordinates (vt) and normals (vn): they have no input corner to take them from"
    [ "$(grep -c '^f [0-9]* [0-9]* [0-9]*$' "$work/uv_open_out.obj")" = 2 ] || fail "2 plain faces: $(cat "$work/uv_open_out.obj")"
    [ "$(grep -c '^f .*/' "$work/uv_open_out.obj")" = 5 ] || fail "5 textured faces"
  fi
  ;;
readme_quick_start)
  # The `meshbridge` lines of README's quick start, as written, from a folder with the
  # repository's resources/ (the meshlabserver line runs in the meshlab tests' way, not here).
  readme="$models/../../README.md"
  awk '/^## Quick start/,/^## More/' "$readme" | grep '^meshbridge ' >"$work/commands"
  [ "$(wc -l <"$work/commands")" = 2 ] || fail "two meshbridge lines in the quick start: $(cat "$work/commands")"
  mkdir "$work/user" && ln -s "$(cd "$models/.." && pwd)" "$work/user/resources"
  meshbridge() { "$mb" "$@"; }
  while read -r line; do
    command=${line%%#*}
    (cd "$work/user" && eval "$command") >"$work/out" 2>"$work/err"
    code=$?
    case "$command" in
    *check*) [ "$code" = 1 ] || fail "'$command' exited $code, expected 1 (repair would change it)" ;;
    *) [ "$code" = 0 ] || fail "'$command' exited $code: $(cat "$work/err")" ;;
    esac
  done <"$work/commands"
  [ -s "$work/user/prisms24.3mf" ] || fail "the quick start's repair wrote no prisms24.3mf"
  expect_exit 0 "$mb" check "$work/user/prisms24.3mf"
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
