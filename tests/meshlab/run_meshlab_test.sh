#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One MeshLab integration test: runs Debian's real meshlabserver from a private root (see
# scripts/meshlab_private_root.sh) with the freshly built plugin and checks what it wrote.
#
# Usage: run_meshlab_test.sh MODE [MODEL.obj] [key=value ...]
#   root                      make the private root (ctest fixture)
#   lists-plugin              meshlabserver loads the plugin and lists both filters
#   detect MODEL [k=v...]     detect.mlx: log, defect layer edges == core report, selection
#   repair MODEL [k=v...]     repair.mlx + MeshLab's own manifold checks in the same script
#   attributes MODEL          colours, qualities, wedge texcoords survive repair, face order kept
#   no-faces                  a point cloud gets a clear error and is left unchanged
#   gui MODEL                 the real MeshLab GUI under Xvfb (gui_detect.sh): opens MODEL, runs
#                             Detect from Filters' search with default settings; red and green
#                             pixels of the 3D view as the model's defects say, summary line logged
#   gaps cube_written_twice|t_junction_box
#                             weld_tolerance / close_t_junctions set in .mlx scripts, on the
#                             crack models of tests/unit/close_gaps_test.cpp (crack_models.sh):
#                             exact counts in Detect's and Repair's logs, the repaired file
#   holes open_boxes          fill_holes set in .mlx scripts on two open boxes (crack_models.sh):
#                             holes of 4 and 6 edges, exact counts in Repair's log and file
#   crossings crossing_cubes|apart_cubes
#                             Detect's self_intersections on two cubes whose shells cross (or lie
#                             apart), as triangles (crossing_models.sh): the log's counts == the
#                             core's, two violet triangles per crossing face in the tube layer,
#                             none with self_intersections=false
#   gui-crossings crossing_cubes|apart_cubes
#                             the real GUI (gui_detect.sh) on them: violet pixels exactly when the
#                             shells cross, the summary line with the violet faces
#   stl-truth MODEL           Repair's "STL re-read" line on MODEL written as STL, checked
#                             against the STL file meshlabserver then writes
#   compare-builtin MODEL     ours vs MeshLab's "Repair non Manifold Edges" (both methods):
#                             faces kept and wall time (informative; asserts only that ours
#                             keeps every face and MeshLab finds nothing non-manifold after it)
# k=v: expected values of `mlcheck report` on the input (detect) or on the repaired output
# (repair), e.g. singular_edges=1 vertices=16.
#
# Environment (set by tests/meshlab/CMakeLists.txt): MLCHECK, PLUGIN, ROOT, WORK, SOURCE_DIR.
set -euo pipefail

: "${MLCHECK:?}" "${PLUGIN:?}" "${ROOT:?}" "${WORK:?}" "${SOURCE_DIR:?}"
root_script="$SOURCE_DIR/scripts/meshlab_private_root.sh"
scripts="$SOURCE_DIR/resources/scripts"
check_mlx="$SOURCE_DIR/tests/meshlab/check_manifold.mlx"

mode=${1:?mode}; shift
# fail, pass, value, expect_eq, input_off, check_expectations
source "$(dirname "${BASH_SOURCE[0]}")/check_helpers.sh"
# write_cube_twice, write_t_junction_box, off_to_stl, expect_in_log, the expected gap lines
source "$(dirname "${BASH_SOURCE[0]}")/crack_models.sh"
# write_crossing_cubes
source "$(dirname "${BASH_SOURCE[0]}")/crossing_models.sh"
# server LOG ARGS...: runs meshlabserver, its stdout (the filter log) into LOG; returns its status
server() {
  local log=$1; shift
  echo "+ meshlabserver $*" >&2
  "$root_script" run "$ROOT" "$@" >"$log" 2>"$log.stderr"
}
# Last value printed by meshlabserver's log line "Mesh <path> loaded has <vn> vn <fn> fn".
loaded_fn() { sed -n 's/.* loaded has \([0-9]*\) vn \([0-9]*\) fn.*/\2/p' "$1" | tail -n1; }
loaded_vn() { sed -n 's/.* loaded has \([0-9]*\) vn \([0-9]*\) fn.*/\1/p' "$1" | tail -n1; }
# mlx FILE detect|repair [key=value...]: resources/scripts/<filter>.mlx with these values (the
# python-form names). meshlabserver 2020.09 asserts that a script lists every parameter.
mlx() {
  local file=$1 template="$scripts/$2.mlx" kv
  shift 2
  cp "$template" "$file"
  for kv in "$@"; do
    grep -q "<Param name=\"${kv%%=*}\" " "$file" || { echo "no parameter ${kv%%=*} in $template"; exit 2; }
    sed -i -E "s|(<Param name=\"${kv%%=*}\" type=\"[A-Za-z]*\" value=\")[^\"]*\"|\\1${kv#*=}\"|" "$file"
  done
}
# repair_case LABEL IN [key=value...]: Repair with these parameters, MeshLab's manifold checks,
# LABEL.ply saved and reported by the core (LABEL.txt); the log is LABEL.log
repair_case() {
  local label=$1 in=$2 status=0
  shift 2
  mlx "$label.mlx" repair "$@"
  server "$label.log" -i "$in" -o "$label.ply" -m vf ff sa -s "$label.mlx" -s "$check_mlx" || status=$?
  cat "$label.log"
  expect_eq "$label: meshlabserver status" "$status" 0
  "$MLCHECK" report "$label.ply" >"$label.txt"
}
model=${1:-}
name=$(basename "${model:-$mode}" .obj)
dir="$WORK/$mode.$name"
if [ "$mode" != root ]; then
  rm -rf "$dir"
  mkdir -p "$dir"
  cd "$dir"
fi


case "$mode" in
  root)
    "$root_script" make "$ROOT" "$PLUGIN"
    ;;

  lists-plugin)
    "$root_script" list "$ROOT" >filters.txt 2>stderr.txt || { cat stderr.txt; fail "meshlabserver -d failed"; }
    for f in "Detect Singular Defects (Bridged Half-Edge)" "Repair Singular Defects (Bridged Half-Edge)" \
             "Select non Manifold Edges " "Select non Manifold Vertices" \
             "Repair non Manifold Edges by removing faces" "Repair non Manifold Edges by splitting vertices" \
             "Compute Topological Measures"; do
      if grep -qxF "$f" filters.txt; then pass "lists '$f'"; else fail "does not list '$f'"; fi
    done
    grep -q "Current Plugins Dir is: $ROOT/" stderr.txt && pass "plugins from the private root" \
      || fail "plugins not loaded from $ROOT"
    ;;

  detect)
    shift
    input_off
    "$MLCHECK" report "$model" >input.txt
    status=0
    # Layer x (last) is the defect layer, as raw edges; layer 0 the mesh itself, with its
    # selection flags (and face colours, if Detect had turned them on: it must not).
    server log.txt -i in.off -o defects.obj -l x -m vc -o mesh.ply -l 0 -m vf ff sa fc \
      -s "$SOURCE_DIR/tests/meshlab/detect_edges.mlx" || status=$?
    cat log.txt
    expect_eq "meshlabserver status" "$status" 0
    grep -q "MeshBridge defects of" log.txt && pass "report logged" || fail "no report in the log"
    if [ ! -e defects.obj ] && [ "$(value singular_edges input.txt)" = 0 ] \
       && [ "$(value boundary_edges input.txt)" = 0 ] && [ "$(value singular_vertices input.txt)" = 0 ]; then
      # Nothing to draw: the defect layer is empty and meshlabserver does not save empty meshes.
      grep -q "0 red (singular) edges, 0 green (boundary) edges" log.txt \
        && pass "empty defect layer (nothing to show; meshlabserver saves no empty mesh)" \
        || fail "no defect layer saved"
      printf 'vertices=0\nfaces=0\nred_edges=0\ngreen_edges=0\nother_edges=0\nmarker_points=0\n' >defects.obj.txt
      defects=defects.obj.txt
    else
      "$MLCHECK" report defects.obj >defects.txt
      defects=defects.txt
    fi
    "$MLCHECK" report mesh.ply >mesh.txt
    expect_eq "mesh has no face colour after Detect (colour faces off)" "$(value red_faces mesh.txt)" ""
    grep -q "Defect layer 'in - defects': " log.txt \
      && pass "log names the layer 'in - defects'" || fail "no summary line naming 'in - defects'"
    grep -q "(< 3 distinct" log.txt && fail "unescaped '<' in the log" || pass "log escaped for HTML"
    echo "--- core on the input:"; cat input.txt
    echo "--- defect layer:"; cat "$defects"
    expect_eq "red edges == core singular edges" "$(value red_edges "$defects")" "$(value singular_edges input.txt)"
    expect_eq "green edges == core boundary edges" "$(value green_edges "$defects")" "$(value boundary_edges input.txt)"
    expect_eq "other edges" "$(value other_edges "$defects")" 0
    expect_eq "defect layer faces" "$(value faces "$defects")" 0
    expect_eq "singular vertex markers == core singular vertices" \
      "$(value marker_points "$defects")" "$(value singular_vertices input.txt)"
    # MeshLab triangulates polygons on loading: compare with the file's triangle count.
    expect_eq "mesh faces unchanged" "$(value faces mesh.txt)" "$(value triangles input.txt)"
    expect_eq "mesh vertices unchanged" "$(value vertices mesh.txt)" "$(value vertices input.txt)"
    singular=$(( $(value singular_edges input.txt) + $(value singular_vertices input.txt) ))
    selected=$(value selected_faces mesh.txt)
    if [ "$singular" -gt 0 ]; then
      [ "$selected" -gt 0 ] && pass "selected $selected faces at singular elements" || fail "nothing selected"
    else
      expect_eq "selected faces" "$selected" 0
    fi
    expect_eq "selected vertices == singular vertices" "$(value selected_vertices mesh.txt)" \
      "$(value singular_vertices input.txt)"
    # Both options on: the selected faces are exactly the coloured ones (red at singular edges,
    # orange at pinch vertices), and the mesh itself is still unchanged.
    status=0
    server colour.log -i in.off -o coloured.ply -l 0 -m vf ff fc sa \
      -s "$SOURCE_DIR/tests/meshlab/detect_color.mlx" || status=$?
    expect_eq "meshlabserver status (colour faces)" "$status" 0
    "$MLCHECK" report coloured.ply >coloured.txt
    expect_eq "coloured faces == selected faces" \
      "$(( $(value red_faces coloured.txt) + $(value orange_faces coloured.txt) ))" "$(value selected_faces coloured.txt)"
    expect_eq "coloured mesh faces unchanged" "$(value faces coloured.txt)" "$(value triangles input.txt)"
    # The default layer: tubes and markers, coloured per face (and per vertex).
    status=0
    server tubes.log -i in.off -o tubes.ply -l x -m vc fc sa -s "$scripts/detect.mlx" || status=$?
    expect_eq "meshlabserver status (tubes)" "$status" 0
    if [ -e tubes.ply ]; then
      "$MLCHECK" report tubes.ply >tubes.txt
      expect_tube_layer tubes.txt input.txt
    else
      expect_eq "no tube layer: nothing to show" \
        "$(( $(value singular_edges input.txt) + $(value boundary_edges input.txt) + $(value singular_vertices input.txt) ))" 0
    fi
    check_expectations input.txt "$@"
    ;;

  repair)
    shift
    input_off
    "$MLCHECK" report "$model" >input.txt
    # MeshLab's own checks on the input first: they must see what the core sees.
    status=0
    server before.log -i in.off -o before.ply -m vf ff sa -s "$check_mlx" || status=$?
    expect_eq "meshlabserver status (checks on input)" "$status" 0
    "$MLCHECK" report before.ply >before.txt
    if [ "$(value singular_edges input.txt)" -gt 0 ]; then
      [ "$(value selected_faces before.txt)" -gt 0 ] \
        && pass "MeshLab selects $(value selected_faces before.txt) faces on non-manifold edges of the input" \
        || fail "MeshLab finds no non-manifold edge in the input"
    fi
    status=0
    server log.txt -i in.off -o repaired.ply -m vc vf ff fc fq wt sa \
      -s "$scripts/repair.mlx" -s "$check_mlx" || status=$?
    cat log.txt
    expect_eq "meshlabserver status" "$status" 0
    "$MLCHECK" report repaired.ply >output.txt
    echo "--- core on the output:"; cat output.txt
    expect_eq "faces kept (saved == loaded)" "$(value faces output.txt)" "$(loaded_fn log.txt)"
    expect_eq "faces kept (saved == file's triangles)" "$(value faces output.txt)" "$(value triangles input.txt)"
    expect_eq "MeshLab: faces on non-manifold edges (selection)" "$(value selected_faces output.txt)" 0
    expect_eq "MeshLab: non-manifold vertices (selection)" "$(value selected_vertices output.txt)" 0
    if grep -q "non two manifold" log.txt; then fail "MeshLab: $(grep 'non two manifold' log.txt | tail -n1)";
    else pass "MeshLab: no non two manifold edges or vertices"; fi
    grep -q "Mesh is two-manifold" log.txt && pass "MeshLab: Mesh is two-manifold" || fail "MeshLab: not two-manifold"
    expect_eq "core: singular edges after" "$(value singular_edges output.txt)" 0
    expect_eq "core: singular vertices after" "$(value singular_vertices output.txt)" 0
    grep -q "after: singular edges 0, singular vertices 0" log.txt && pass "repair log" || fail "repair log line missing"
    if [ "$(value vertices output.txt)" -gt "$(loaded_vn log.txt)" ]; then
      grep -q "To keep the repair, save as PLY, OBJ or OFF: they keep the" log.txt \
        && pass "log: which formats keep the repair" || fail "log: no hint on formats that keep the repair"
      grep -q "STL re-read: saved as STL and loaded again, .*STL stores no shared vertices" log.txt \
        && pass "log: what STL would re-read" || fail "log: no 'STL re-read' line"
    fi
    # Detect, then Repair: the defect layer is gone (the last layer is the mesh again) and so is
    # the selection Detect made.
    status=0
    server clean.log -i in.off -o last.ply -l x -m vf ff sa -s "$scripts/detect.mlx" -s "$scripts/repair.mlx" \
      || status=$?
    expect_eq "meshlabserver status (Detect, Repair)" "$status" 0
    "$MLCHECK" report last.ply >last.txt
    expect_eq "last layer after Detect + Repair is the mesh (faces)" "$(value faces last.txt)" "$(value faces output.txt)"
    expect_eq "selected faces after Detect + Repair" "$(value selected_faces last.txt)" 0
    expect_eq "selected vertices after Detect + Repair" "$(value selected_vertices last.txt)" 0
    check_expectations output.txt "$@"
    ;;

  attributes)
    "$MLCHECK" make-attributed "$model" in.ply
    status=0
    server log.txt -i in.ply -o repaired.ply -m vc vq fc fq wt sa -s "$scripts/repair.mlx" || status=$?
    cat log.txt
    expect_eq "meshlabserver status" "$status" 0
    expect_attributes_kept_and_manifold in.ply repaired.ply
    ;;

  no-faces)
    printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' >points.off
    for filter in repair detect; do
      status=0
      server "$filter.log" -i points.off -o out.ply -m sa -s "$scripts/$filter.mlx" || status=$?
      cat "$filter.log"
      [ "$status" -ne 0 ] && pass "$filter: meshlabserver reports failure ($status)" || fail "$filter: status 0"
      grep -q "needs a mesh with faces" "$filter.log" && pass "$filter: clear error message" \
        || fail "$filter: no error message"
      [ ! -e out.ply ] && pass "$filter: nothing saved" || fail "$filter: a mesh was saved"
    done
    ;;

  gui)
    input_off
    "$MLCHECK" report "$model" >input.txt
    cp in.off "$name.off"  # MeshLab names the layer after the file
    gui_bin=$("$root_script" make-gui "$ROOT/gui" "$PLUGIN")
    status=0
    t0=$(date +%s%N)
    COUNT_PIXELS="$COUNT_PIXELS" bash "$SOURCE_DIR/tests/meshlab/gui_detect.sh" "$gui_bin" \
      "$dir/$name.off" "$dir/shot" >gui.txt || status=$?
    echo "GUI session: $(( ($(date +%s%N) - t0) / 1000000 )) ms"
    cat shot/session.txt
    expect_eq "GUI session status" "$status" 0
    expect_gui_shot shot input.txt "$name"
    ;;

  gaps)
    status=0
    case "$name" in
      cube_written_twice)
        write_cube_twice cube.off 7.62939453125e-06  # 2^-17: one float32 step at 110
        mlx detect.mlx detect weld_tolerance=-1 close_t_junctions=true
        server detect.log -i cube.off -o mesh.ply -m sa -s detect.mlx || status=$?
        cat detect.log
        expect_eq "Detect: meshlabserver status" "$status" 0
        expect_in_log "Detect: what Repair would weld" detect.log "$cube_detect_line"
        "$MLCHECK" report mesh.ply >mesh.txt
        expect_eq "Detect moves no vertex (vertices)" "$(value vertices mesh.txt)" 16
        expect_eq "Detect moves no vertex (boundary edges)" "$(value boundary_edges mesh.txt)" 12
        repair_case auto cube.off weld_tolerance=-1 close_t_junctions=true
        expect_in_log "Repair (automatic): what it welded" auto.log "$cube_repair_line"
        expect_in_log "Repair (automatic)" auto.log "boundary edges: 12 -&gt; 0"  # the log is HTML-escaped
        check_expectations auto.txt vertices=10 faces=12 boundary_edges=0 singular_edges=0 watertight=1
        grep -q "Mesh is two-manifold" auto.log && pass "MeshLab: Mesh is two-manifold" || fail "MeshLab: not two-manifold"
        # From an STL file (no vertex split): the log says the repair survives STL.
        off_to_stl cube.off cube.stl
        repair_case stl cube.stl
        expect_in_log "Repair of an STL layer" stl.log "$cube_repair_line"
        expect_in_log "Repair of an STL layer: STL re-read" stl.log \
          "STL re-read: saved as STL and loaded again, this layer has singular edges 0, singular vertices 0, watertight yes"
        expect_not_in_log "Repair of an STL layer: no save hint" stl.log "To keep the repair"
        check_expectations stl.txt vertices=8 faces=12 boundary_edges=0 watertight=1
        repair_case off cube.off weld_tolerance=0
        expect_in_log "Repair (weld_tolerance=0)" off.log "gaps: not closed (tolerance 0)"
        check_expectations off.txt vertices=16 faces=12 boundary_edges=12
        # A crack of 1e-3 (19x the automatic tolerance) stays open unless the tolerance covers it.
        write_cube_twice wide.off 0.001
        repair_case wide_auto wide.off
        expect_in_log "Repair (wide crack, automatic)" wide_auto.log "0 vertices welded"
        check_expectations wide_auto.txt vertices=16 faces=12 boundary_edges=12
        repair_case wide wide.off weld_tolerance=0.002
        expect_in_log "Repair (wide crack, weld_tolerance=0.002)" wide.log \
          "gaps (tolerance 0.002): 6 vertices welded (largest move 0.00173"
        check_expectations wide.txt vertices=10 faces=12 boundary_edges=0 watertight=1
        ;;
      t_junction_box)
        write_t_junction_box box.off
        mlx detect.mlx detect weld_tolerance=-1 close_t_junctions=true
        server detect.log -i box.off -o mesh.ply -m sa -s detect.mlx || status=$?
        cat detect.log
        expect_eq "Detect: meshlabserver status" "$status" 0
        expect_in_log "Detect: what Repair would close" detect.log "$box_detect_line"
        repair_case auto box.off weld_tolerance=-1 close_t_junctions=true
        expect_in_log "Repair: what it closed" auto.log "$box_repair_line"
        expect_in_log "Repair: split sides fanned back into triangles" auto.log \
          "Triangulated 2 polygons (2 extra triangles)"
        expect_in_log "Repair" auto.log "boundary edges: 6 -&gt; 0"  # the log is HTML-escaped
        # MeshLab triangulates the 7 quads into 14 triangles; two gain a T-junction corner.
        check_expectations auto.txt vertices=10 faces=16 boundary_edges=0 singular_edges=0 watertight=1
        grep -q "Mesh is two-manifold" auto.log && pass "MeshLab: Mesh is two-manifold" || fail "MeshLab: not two-manifold"
        repair_case no_t box.off close_t_junctions=false
        expect_in_log "Repair (close_t_junctions=false)" no_t.log "0 T-junctions closed (0 sides split)"
        check_expectations no_t.txt vertices=10 faces=14 boundary_edges=6
        ;;
      *) echo "unknown gap model $name"; exit 2 ;;
    esac
    ;;

  holes)
    # MeshLab loads the 13 quads as 26 triangles; the holes' rims keep 4 and 6 edges.
    write_open_boxes boxes.off
    repair_case off boxes.off
    expect_in_log "Repair (fill_holes=0, the default)" off.log "holes: not filled (off)"
    check_expectations off.txt faces=26 boundary_edges=10 boundary_loops=2
    repair_case four boxes.off fill_holes=4
    expect_in_log "Repair (fill_holes=4)" four.log \
      "holes (up to 4 edges): 1 filled with 2 new triangles, 1 left open"
    expect_in_log "Repair (fill_holes=4)" four.log "boundary edges: 10 -&gt; 6"  # HTML-escaped
    check_expectations four.txt vertices=20 faces=28 boundary_edges=6 boundary_loops=1 watertight=0
    repair_case six boxes.off fill_holes=6
    expect_in_log "Repair (fill_holes=6)" six.log \
      "holes (up to 6 edges): 2 filled with 6 new triangles, 0 left open"
    check_expectations six.txt vertices=20 faces=32 boundary_edges=0 singular_edges=0 \
      inconsistent_edges=0 watertight=1
    grep -q "Mesh is two-manifold" six.log && pass "MeshLab: Mesh is two-manifold" || fail "MeshLab: not two-manifold"
    ;;

  crossings)
    write_crossing_cubes cubes.off "$([ "$name" = crossing_cubes ] && echo 0.5 || echo 2)"
    "$MLCHECK" report cubes.off >input.txt
    pairs=$(value self_intersecting_face_pairs input.txt)
    faces=$(value self_intersecting_faces input.txt)
    components=$(value crossing_component_pairs input.txt)
    if [ "$name" = crossing_cubes ]; then
      expect_eq "core: crossing faces" "$faces" 12
    else
      expect_eq "core: crossing faces" "$faces" 0
    fi
    mlx on.mlx detect self_intersections=true
    status=0
    server on.log -i cubes.off -o layer.ply -l x -m vc fc sa -s on.mlx || status=$?
    cat on.log
    expect_eq "Detect: meshlabserver status" "$status" 0
    expect_in_log "Detect: face pairs" on.log "self-intersecting face pairs: $pairs"
    expect_in_log "Detect: faces" on.log "faces in them: $faces"
    expect_in_log "Detect: shells" on.log "pairs of components (shells) crossing: $components"
    expect_in_log "Detect: summary" on.log \
      "0 singular vertex markers, $faces violet (self-intersecting) faces"
    if [ "$faces" -gt 0 ]; then
      "$MLCHECK" report layer.ply >layer.txt
      expect_eq "tube layer: two violet triangles per crossing face" \
        "$(value violet_faces layer.txt)" "$(( 2 * faces ))"
      expect_eq "tube layer: nothing else" "$(value faces layer.txt)" "$(( 2 * faces ))"
    else
      "$MLCHECK" report layer.ply >layer.txt
      expect_eq "empty defect layer (nothing to show)" "$(value faces layer.txt)" 0
    fi
    mlx off.mlx detect self_intersections=false
    server off.log -i cubes.off -o off_layer.ply -l x -m vc fc sa -s off.mlx || status=$?
    expect_eq "Detect (off): meshlabserver status" "$status" 0
    expect_in_log "Detect (off)" off.log "self-intersections: not searched"
    expect_not_in_log "Detect (off): no violet" off.log "violet"
    "$MLCHECK" report off_layer.ply >off_layer.txt
    expect_eq "off: empty defect layer" "$(value faces off_layer.txt)" 0
    ;;

  gui-crossings)
    write_crossing_cubes "$name.off" "$([ "$name" = crossing_cubes ] && echo 0.5 || echo 2)"
    "$MLCHECK" report "$name.off" >input.txt
    gui_bin=$("$root_script" make-gui "$ROOT/gui" "$PLUGIN")
    status=0
    # Turned with the mouse as a user does, so the crossing is seen from above and aside.
    DRAG="160 120" COUNT_PIXELS="$COUNT_PIXELS" bash "$SOURCE_DIR/tests/meshlab/gui_detect.sh" \
      "$gui_bin" "$dir/$name.off" "$dir/shot" >gui.txt || status=$?
    cat shot/session.txt
    expect_eq "GUI session status" "$status" 0
    expect_gui_shot shot input.txt "$name"
    faces=$(value self_intersecting_faces input.txt)
    grep -q "LOG: [0-9]* Defect layer '$name - defects': .*, $faces violet (self-intersecting) faces" \
      shot/meshlab.log && pass "GUI log: $faces violet faces" || fail "GUI log: no '$faces violet' summary"
    if [ "$faces" -gt 0 ]; then
      # The shells cross near the view's middle: a clear patch, not a few stray pixels.
      [ "$(value violet shot/view.txt)" -gt 5000 ] && pass "violet patch" || fail "violet patch too small"
    fi
    ;;

  stl-truth)
    shift
    "$MLCHECK" to-off "$model" model.off
    off_to_stl model.off in.stl
    "$MLCHECK" to-off in.stl welded.off  # what every STL reader gets: positions welded
    "$MLCHECK" report welded.off >input.txt
    status=0
    server log.txt -i in.stl -o repaired.stl -s "$scripts/repair.mlx" || status=$?
    cat log.txt
    expect_eq "meshlabserver status" "$status" 0
    split=$(sed -n 's/^.*vertices: [0-9]* in, [0-9]* out (\([0-9]*\) cop[a-z]* from split fans.*/\1/p' log.txt | tail -n1)
    # The STL meshlabserver wrote, read back as every STL reader does: the log must have said so.
    "$MLCHECK" to-off repaired.stl reread.off
    "$MLCHECK" report reread.off >reread.txt
    line="STL re-read: saved as STL and loaded again, this layer has singular edges $(value singular_edges reread.txt), singular vertices $(value singular_vertices reread.txt), watertight $([ "$(value watertight reread.txt)" = 1 ] && echo yes || echo no)"
    expect_in_log "log == the STL file written" log.txt "$line"
    if [ "${split:-0}" -gt 0 ]; then
      expect_in_log "log: why" log.txt "STL stores no shared vertices: every reader welds the $split split vertex copies together again"
      expect_in_log "log: what keeps it" log.txt "To keep the repair, save as PLY, OBJ or OFF: they keep the $split split vertex copies apart"
    else
      expect_not_in_log "log: no save hint without split vertices" log.txt "To keep the repair"
    fi
    check_expectations reread.txt "$@"
    ;;

  compare-builtin)
    input_off
    faces_in=$("$MLCHECK" report "$model" | sed -n 's/^triangles=//p')
    empty_mlx="$dir/none.mlx"
    printf '<!DOCTYPE FilterScript>\n<FilterScript>\n</FilterScript>\n' >"$empty_mlx"
    run_one() {  # run_one LABEL MLX: one meshlabserver run, then MeshLab's own checks
      local label=$1 mlx=$2 t0 t1 status=0 fn nm=yes
      t0=$(date +%s%N)
      server "$label.log" -i in.off -o "$label.ply" -m vf ff sa -s "$mlx" -s "$check_mlx" || status=$?
      t1=$(date +%s%N)
      fn=$("$MLCHECK" report "$label.ply" 2>/dev/null | sed -n 's/^faces=//p') || true
      grep -q "non two manifold" "$label.log" && nm="NO ($(grep 'non two manifold' "$label.log" | tail -n1 | sed 's/^Mesh has //'))"
      if [ "$status" -ne 0 ]; then
        fn=none
        nm="meshlabserver failed, status $status: $(grep -h -m1 'terminate called\|what()\|Assertion\|Problem with filter' "$label.log" "$label.log.stderr" | head -n1)"
      fi
      printf '%-34s faces %6s of %6s  wall %5d ms  two-manifold: %s\n' \
        "$label" "${fn:-?}" "$faces_in" $(( (t1 - t0) / 1000000 )) "$nm" | tee -a table.txt
      eval "faces_$label=\${fn:-none}"
    }
    run_one baseline "$empty_mlx"
    run_one meshbridge "$scripts/repair.mlx"
    for method in "removing faces" "splitting vertices"; do
      label="meshlab_${method// /_}"
      printf '<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name="Repair non Manifold Edges by %s"/>\n</FilterScript>\n' \
        "$method" >"$label.mlx"
      run_one "$label" "$dir/$label.mlx"
    done
    echo "(wall time of one meshlabserver run each, start-up and MeshLab's checks included;"
    echo " 'baseline' runs no repair)"
    expect_eq "MeshBridge keeps every face" "$faces_meshbridge" "$faces_in"
    grep -q "^meshbridge .*two-manifold: yes" table.txt && pass "MeshBridge result is two-manifold" \
      || fail "MeshBridge result not two-manifold"
    ;;

  *)
    echo "unknown mode $mode"; exit 2 ;;
esac

finish_checks "$dir"
