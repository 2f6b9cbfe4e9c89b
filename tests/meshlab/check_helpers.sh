# SPDX-License-Identifier: GPL-3.0-or-later
# Checks shared by the MeshLab integration runners (tests/meshlab for 2020.09 through
# meshlabserver, tests/meshlab2025 for 2025.07 through the headless runner). Sourced; needs
# MLCHECK and, for input_off, `model`. Counts failures in `failures`.

failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { echo "ok:   $*"; }
# value KEY FILE: the value of KEY=... in a key=value file (empty if missing)
value() { sed -n "s/^$1=//p" "$2" | tail -n1; }
expect_eq() {  # expect_eq WHAT ACTUAL EXPECTED
  if [ "$2" = "$3" ]; then pass "$1 = $2"; else fail "$1 = '$2', expected '$3'"; fi
}
input_off() {  # MODEL as in.off (Debian's meshlabserver 2020.09 aborts on any OBJ input)
  [ -f "$model" ] || { echo "no model $model"; exit 1; }
  "$MLCHECK" to-off "$model" in.off
}
check_expectations() {  # check_expectations REPORT k=v...
  local report=$1; shift
  local kv
  for kv in "$@"; do
    expect_eq "${kv%%=*}" "$(value "${kv%%=*}" "$report")" "${kv#*=}"
  done
}
expect_attributes_kept_and_manifold() {  # IN OUT: OUT has IN's attributes and no singular element
  "$MLCHECK" same-attributes "$1" "$2" >same.txt || true
  cat same.txt
  expect_eq "attribute mismatches" "$(value mismatches same.txt)" 0
  "$MLCHECK" report "$2" >output.txt
  expect_eq "core: singular edges after" "$(value singular_edges output.txt)" 0
  expect_eq "core: singular vertices after" "$(value singular_vertices output.txt)" 0
}
expect_tube_layer() {  # LAYER_REPORT INPUT_REPORT: the tube layer shows exactly the core's defects
  # 12 triangles per tube (hexagonal, open), 8 per marker (octahedron): defect_tubes.h. An empty
  # layer (no defects) has no colour counts: they count as 0.
  # Self-intersecting faces: two violet triangles per triangle MeshLab made of them
  # (crossing_faces.h), so some exactly when the core finds some in the file.
  local layer=$1 input=$2 red green magenta violet
  red=$(value red_faces "$layer"); red=${red:-0}
  green=$(value green_faces "$layer"); green=${green:-0}
  magenta=$(value magenta_faces "$layer"); magenta=${magenta:-0}
  violet=$(value violet_faces "$layer"); violet=${violet:-0}
  expect_eq "tube layer: red faces" "$red" \
    "$(( 12 * $(value singular_edges "$input") + 8 * ($(value singular_vertices "$input") - $(value pinch_vertices "$input")) ))"
  expect_eq "tube layer: green faces" "$green" "$(( 12 * $(value boundary_edges "$input") ))"
  expect_eq "tube layer: magenta faces" "$magenta" "$(( 8 * $(value pinch_vertices "$input") ))"
  if [ "$(value self_intersecting_faces "$input")" -gt 0 ]; then
    [ "$violet" -gt 0 ] && pass "tube layer: $violet violet faces" || fail "tube layer: no violet faces"
  else
    expect_eq "tube layer: violet faces" "$violet" 0
  fi
  expect_eq "tube layer: no other faces" "$(value faces "$layer")" "$(( red + green + magenta + violet ))"
}
expect_gui_shot() {  # SHOT_DIR INPUT_REPORT NAME: gui_detect.sh's screenshot and log
  local shot=$1 input=$2 name=$3 red green violet
  red=$(value red "$shot/view.txt")
  green=$(value green "$shot/view.txt")
  violet=$(value violet "$shot/view.txt")
  echo "3D view: red=$red green=$green violet=$violet pixels=$(value pixels "$shot/view.txt") ($shot/view.png)"
  # Violet (self-intersecting faces) only where the core finds some; they may all lie inside
  # (prisms24's shared walls), so more than 0 is asserted on crossing cubes only (gui-crossings).
  [ "$(value self_intersecting_faces "$input")" -gt 0 ] || expect_eq "violet pixels" "$violet" 0
  if [ "$(value singular_edges "$input")" -gt 0 ] || [ "$(value singular_vertices "$input")" -gt 0 ]; then
    [ "${red:-0}" -gt 0 ] && pass "red pixels: $red" || fail "no red pixels in the 3D view"
  else
    expect_eq "red pixels" "$red" 0
  fi
  if [ "$(value boundary_edges "$input")" -gt 0 ]; then
    [ "${green:-0}" -gt 0 ] && pass "green pixels: $green" || fail "no green pixels in the 3D view"
  else
    expect_eq "green pixels" "$green" 0
  fi
  # Every line of the report arrives as its own log entry, escaped, the summary last.
  local summary="LOG: [0-9]* Defect layer '$name - defects': $(value singular_edges "$input") red (singular) edges, $(value boundary_edges "$input") green (boundary) edges, $(value singular_vertices "$input") singular vertex markers"
  grep -q "$summary" "$shot/meshlab.log" && pass "GUI log: summary line" || fail "GUI log has no line '$summary'"
  grep -q "LOG: [0-9]* .*faces set aside (&lt; 3 distinct vertices)" "$shot/meshlab.log" \
    && pass "GUI log: '<' escaped, report lines arrive" || fail "GUI log: no escaped 'faces set aside' line"
}
finish_checks() {  # DIR: exit 1 naming DIR if any check failed
  if [ "$failures" -ne 0 ]; then
    echo "$failures check(s) failed; files in $1"
    exit 1
  fi
}
