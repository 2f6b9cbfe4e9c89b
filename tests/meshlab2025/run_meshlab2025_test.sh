#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# One MeshLab 2025.07 integration test, run inside the sid root (tests/meshlab2025/CMakeLists.txt):
# the headless runner (meshbridge-mlrun: MeshLab's own PluginManager, MeshDocument and IO plugins,
# as pymeshlab uses them) applies our filters and MeshLab's by their python names; the checks are
# those of tests/meshlab/run_meshlab_test.sh (MeshLab 2020.09 through meshlabserver), plus the
# filters' result maps.
#
# Usage: run_meshlab2025_test.sh MODE [MODEL.obj] [key=value ...]
#   version                   MeshLab's PluginManager loads the plugin: same version and precision
#   lists-plugin              both filters under their python names, with their parameters
#   detect MODEL [k=v...]     log, result map == core, defect layer edges == core, selection
#   repair MODEL [k=v...]     repair + MeshLab's own manifold checks in the same run
#   attributes MODEL          colours, qualities, wedge texcoords survive repair, face order kept
#   no-faces                  a point cloud: MeshLab's precondition error, and our MLException
#   gui MODEL                 the real MeshLab 2025.07 GUI under Xvfb (tests/meshlab/gui_detect.sh):
#                             Detect from Filters' search with default settings; red and green
#                             pixels of the 3D view as the model's defects say, summary logged
#   gaps cube_written_twice|t_junction_box
#                             weld_tolerance / close_t_junctions by python name on the crack
#                             models of tests/unit/close_gaps_test.cpp (crack_models.sh): exact
#                             counts in the logs and result maps, the repaired layer
#   holes open_boxes          fill_holes by python name on two open boxes (crack_models.sh): holes
#                             of 4 and 6 edges, exact counts in the log, result map and file
#   crossings crossing_cubes|apart_cubes
#                             Detect's self-intersections on two cubes whose shells cross or lie
#                             apart (crossing_models.sh), by default and with
#                             self_intersections=False: result map == core, violet layer faces
#   stl-truth MODEL           Repair's "STL re-read" line and reread.* results on MODEL written
#                             as STL, checked against the STL file MeshLab then writes
#   compare-builtin MODEL     ours vs MeshLab's "Repair non Manifold Edges" (both methods)
# k=v: expected values of `mlcheck report` on the input (detect) or on the repaired output
# (repair), as in tests/meshlab/expectations.cmake.
#
# Environment (set by CMakeLists.txt): MLRUN, MLCHECK, PLUGIN, MESHLAB_PLUGIN_DIR, WORK.
set -euo pipefail

: "${MLRUN:?}" "${MLCHECK:?}" "${PLUGIN:?}" "${MESHLAB_PLUGIN_DIR:?}" "${WORK:?}"
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/runtime-$(id -u)}
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"

detect_filter=compute_singular_defects_bridged
repair_filter=meshing_repair_singular_defects_bridged
# MeshLab's own checks, as tests/meshlab/check_manifold.mlx runs them in 2020.09.
checks=(filter get_topological_measures
        filter compute_selection_by_non_manifold_edges_per_face
        filter compute_selection_by_non_manifold_per_vertex)

mode=${1:?mode}; shift
# fail, pass, value, expect_eq, input_off, check_expectations
source "$(dirname "${BASH_SOURCE[0]}")/../meshlab/check_helpers.sh"
# write_cube_twice, write_t_junction_box, off_to_stl, expect_in_log, the expected gap lines
source "$(dirname "${BASH_SOURCE[0]}")/../meshlab/crack_models.sh"
# write_crossing_cubes
source "$(dirname "${BASH_SOURCE[0]}")/../meshlab/crossing_models.sh"
# result FILTER KEY LOG: the value of KEY in the result map of the last FILTER step in LOG
result() {
  awk -v f="$1" -v k="$2" '
    /^filter / { current = $2 }
    current == f && index($0, "result: " k "=") == 1 { v = substr($0, length("result: " k "=") + 1) }
    END { print v }' "$3"
}
# run LOG STEP...: the runner with MeshLab's IO, cleaning, selection and measuring plugins and
# ours; stdout (steps, MeshLab's log, result maps) into LOG, stderr into LOG.stderr
run() {
  local log=$1; shift
  echo "+ meshbridge-mlrun ... $*" >&2
  "$MLRUN" plugin "$MESHLAB_PLUGIN_DIR/libio_base.so" plugin "$MESHLAB_PLUGIN_DIR/libfilter_clean.so" \
    plugin "$MESHLAB_PLUGIN_DIR/libfilter_select.so" plugin "$MESHLAB_PLUGIN_DIR/libfilter_measure.so" \
    plugin "$PLUGIN" "$@" >"$log" 2>"$log.stderr"
}
loaded_fn() { sed -n 's/^loaded .* \([0-9]*\) vertices, \([0-9]*\) faces$/\2/p' "$1" | tail -n1; }
# repair_case LABEL IN [key=value...]: Repair with these parameters and MeshLab's manifold checks;
# LABEL.ply saved and reported by the core (LABEL.txt); the log is LABEL.log
repair_case() {
  local label=$1 in=$2 status=0
  shift 2
  run "$label.log" load "$in" filter "$repair_filter" "$@" "${checks[@]}" \
    save "$label.ply" attributes=vf,ff binary=false || status=$?
  cat "$label.log"
  expect_eq "$label: runner status" "$status" 0
  "$MLCHECK" report "$label.ply" >"$label.txt"
  expect_eq "$label: MeshLab: is_mesh_two_manifold" \
    "$(result get_topological_measures is_mesh_two_manifold "$label.log")" True
}
# expect_results FILTER LOG key=value...: the filter's result map (pymeshlab's dict)
expect_results() {
  local filter=$1 log=$2 kv
  shift 2
  for kv in "$@"; do
    expect_eq "result ${kv%%=*}" "$(result "$filter" "${kv%%=*}" "$log")" "${kv#*=}"
  done
}

model=${1:-}
name=$(basename "${model:-$mode}" .obj)
dir="$WORK/$mode.$name"
rm -rf "$dir"
mkdir -p "$dir"
cd "$dir"

case "$mode" in
  version)
    status=0
    "$MLRUN" plugin "$MESHLAB_PLUGIN_DIR/libio_base.so" plugin "$PLUGIN" version >log.txt 2>&1 || status=$?
    cat log.txt
    expect_eq "runner status (PluginManager accepted the plugin)" "$status" 0
    ours=$(sed -n 's/^plugin libfilter_meshbridge.so version=\(.*\) precision=\(.*\)$/\1 \2/p' log.txt)
    theirs=$(sed -n 's/^plugin libio_base.so version=\(.*\) precision=\(.*\)$/\1 \2/p' log.txt)
    common=$(sed -n 's/^meshlab-common version=//p' log.txt)
    [ -n "$ours" ] || fail "no version line for our plugin"
    expect_eq "our version and precision == MeshLab's io_base" "$ours" "$theirs"
    expect_eq "our version (first 6 characters) == libmeshlab-common's" "${ours:0:6}" "${common:0:6}"
    ;;

  lists-plugin)
    status=0
    run list.txt list || status=$?
    expect_eq "runner status" "$status" 0
    for f in "$detect_filter (Detect Singular Defects (Bridged Half-Edge))" \
             "$repair_filter (Repair Singular Defects (Bridged Half-Edge))" \
             "compute_selection_by_non_manifold_edges_per_face (Select non Manifold Edges)" \
             "compute_selection_by_non_manifold_per_vertex (Select non Manifold Vertices)" \
             "meshing_repair_non_manifold_edges (Repair non Manifold Edges)" \
             "get_topological_measures (Compute Topological Measures)"; do
      grep -qxF "filter $f" list.txt && pass "lists $f" || fail "does not list $f"
    done
    # Our parameters, by python name, with type and default, in dialog order.
    params() { awk -v f="filter $1 " 'index($0, f) == 1 { on = 1; next } /^filter / { on = 0 } on' list.txt; }
    expect_eq "$detect_filter parameters" "$(params "$detect_filter" | tr '\n' '|')" \
      "  select_faces : bool = True|  color_faces : bool = False|  defect_layer : str = 'Tubes'|  self_intersections : bool = True|  weld_tolerance : PercentageValue = -57.735%|  close_t_junctions : bool = True|"
    expect_eq "$repair_filter parameters" "$(params "$repair_filter" | tr '\n' '|')" \
      "  pairing : str = 'Geometric'|  orient : bool = True|  stitch : bool = True|  cut_nonorientable : bool = False|  remove_duplicate_faces : bool = False|  remove_degenerate_faces : bool = False|  remove_isolated_vertices : bool = False|  recompute_normals : bool = True|  weld_tolerance : PercentageValue = -57.735%|  close_t_junctions : bool = True|  fill_holes : int = 0|"
    ;;

  detect)
    shift
    input_off
    "$MLCHECK" report "$model" >input.txt
    status=0
    # Layer "last" is the defect layer, as raw edges; layer 0 the mesh itself, with its selection
    # flags (and face colours, if Detect had turned them on: it must not).
    run log.txt load in.off filter "$detect_filter" defect_layer=Edges \
      save defects.obj layer=last attributes=vc save mesh.ply layer=0 attributes=vf,ff,fc binary=false \
      || status=$?
    cat log.txt
    expect_eq "runner status" "$status" 0
    grep -q "^log: MeshBridge defects of" log.txt && pass "report logged" || fail "no report in MeshLab's log"
    if [ ! -e defects.obj ]; then
      # Nothing to draw: the defect layer is empty and MeshLab's exporters refuse empty meshes.
      grep -q "^not saved defects.obj: .* is empty" log.txt \
        && grep -q "^log: Defect layer .*: 0 red (singular) edges, 0 green (boundary) edges, 0 singular" log.txt \
        && pass "empty defect layer (nothing to show; not saved)" || fail "no defect layer saved"
      printf 'vertices=0\nfaces=0\nred_edges=0\ngreen_edges=0\nother_edges=0\nmarker_points=0\n' >defects.txt
    else
      "$MLCHECK" report defects.obj >defects.txt
    fi
    "$MLCHECK" report mesh.ply >mesh.txt
    expect_eq "mesh has no face colour after Detect (colour faces off)" "$(value red_faces mesh.txt)" ""
    grep -q "^log: Defect layer 'in - defects': " log.txt \
      && pass "log names the layer 'in - defects'" || fail "no summary line naming 'in - defects'"
    grep -q "(< 3 distinct" log.txt && fail "unescaped '<' in the log" || pass "log escaped for HTML"
    echo "--- core on the input:"; cat input.txt
    echo "--- defect layer:"; cat defects.txt
    expect_eq "red edges == core singular edges" "$(value red_edges defects.txt)" "$(value singular_edges input.txt)"
    expect_eq "green edges == core boundary edges" "$(value green_edges defects.txt)" "$(value boundary_edges input.txt)"
    expect_eq "other edges" "$(value other_edges defects.txt)" 0
    expect_eq "defect layer faces" "$(value faces defects.txt)" 0
    expect_eq "singular vertex markers == core singular vertices" \
      "$(value marker_points defects.txt)" "$(value singular_vertices input.txt)"
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
    # The result map (pymeshlab's return value) says what the files show.
    for k in singular_edges singular_edge_contenders singular_vertices pinch_vertices boundary_edges \
             components inconsistent_edges; do
      expect_eq "result $k == core" "$(result "$detect_filter" "$k" log.txt)" "$(value "$k" input.txt)"
    done
    expect_eq "result faces == MeshLab's triangles" "$(result "$detect_filter" faces log.txt)" "$(value triangles input.txt)"
    expect_eq "result red_edges == layer" "$(result "$detect_filter" red_edges log.txt)" "$(value red_edges defects.txt)"
    expect_eq "result green_edges == layer" "$(result "$detect_filter" green_edges log.txt)" "$(value green_edges defects.txt)"
    expect_eq "result selected_faces == saved selection" "$(result "$detect_filter" selected_faces log.txt)" "$selected"
    expect_eq "result watertight" "$(result "$detect_filter" watertight log.txt)" \
      "$([ "$(value watertight input.txt)" = 1 ] && echo True || echo False)"
    # Both options on: the selected faces are exactly the coloured ones (red at singular edges,
    # orange at pinch vertices), and the mesh itself is still unchanged.
    status=0
    run colour.log load in.off filter "$detect_filter" select_faces=true color_faces=true \
      save coloured.ply layer=0 attributes=vf,ff,fc binary=false || status=$?
    expect_eq "runner status (colour faces)" "$status" 0
    "$MLCHECK" report coloured.ply >coloured.txt
    expect_eq "coloured faces == selected faces" \
      "$(( $(value red_faces coloured.txt) + $(value orange_faces coloured.txt) ))" "$(value selected_faces coloured.txt)"
    expect_eq "result colored_faces" "$(result "$detect_filter" colored_faces colour.log)" "$(value selected_faces coloured.txt)"
    expect_eq "coloured mesh faces unchanged" "$(value faces coloured.txt)" "$(value triangles input.txt)"
    # The default layer: tubes and markers, coloured per face (and per vertex). A second Detect
    # replaces it: still one defect layer (layer 1) and no third layer.
    status=0
    run tubes.log load in.off filter "$detect_filter" filter "$detect_filter" \
      save tubes.ply layer=last attributes=vc,fc binary=false layers || status=$?
    expect_eq "runner status (tubes, Detect twice)" "$status" 0
    grep -q "^layer [0-9]* 'in - defects' " tubes.log && pass "defect layer named 'in - defects'" \
      || fail "no layer 'in - defects'"
    grep -q "^layers: 2$" tubes.log && pass "Detect twice: 2 layers (mesh, one defect layer)" \
      || fail "Detect twice: not 2 layers ($(grep '^layers:' tubes.log))"
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
    run before.log load in.off "${checks[@]}" save before.ply attributes=vf,ff binary=false || status=$?
    expect_eq "runner status (checks on input)" "$status" 0
    "$MLCHECK" report before.ply >before.txt
    if [ "$(value singular_edges input.txt)" -gt 0 ]; then
      [ "$(value selected_faces before.txt)" -gt 0 ] \
        && pass "MeshLab selects $(value selected_faces before.txt) faces on non-manifold edges of the input" \
        || fail "MeshLab finds no non-manifold edge in the input"
    fi
    expect_eq "MeshLab's non-manifold edges of the input == core singular edges" \
      "$(result get_topological_measures non_two_manifold_edges before.log)" "$(value singular_edges input.txt)"
    status=0
    run log.txt load in.off filter "$repair_filter" "${checks[@]}" \
      save repaired.ply attributes=vc,vf,ff,fc,fq,wt binary=false || status=$?
    cat log.txt
    expect_eq "runner status" "$status" 0
    "$MLCHECK" report repaired.ply >output.txt
    echo "--- core on the output:"; cat output.txt
    expect_eq "faces kept (saved == loaded)" "$(value faces output.txt)" "$(loaded_fn log.txt)"
    expect_eq "faces kept (saved == file's triangles)" "$(value faces output.txt)" "$(value triangles input.txt)"
    expect_eq "MeshLab: faces on non-manifold edges (selection)" "$(value selected_faces output.txt)" 0
    expect_eq "MeshLab: non-manifold vertices (selection)" "$(value selected_vertices output.txt)" 0
    expect_eq "MeshLab: non_two_manifold_edges" "$(result get_topological_measures non_two_manifold_edges log.txt)" 0
    expect_eq "MeshLab: non_two_manifold_vertices" "$(result get_topological_measures non_two_manifold_vertices log.txt)" 0
    expect_eq "MeshLab: is_mesh_two_manifold" "$(result get_topological_measures is_mesh_two_manifold log.txt)" True
    expect_eq "core: singular edges after" "$(value singular_edges output.txt)" 0
    expect_eq "core: singular vertices after" "$(value singular_vertices output.txt)" 0
    grep -q "^log: after: singular edges 0, singular vertices 0" log.txt && pass "repair log" || fail "repair log line missing"
    expect_eq "result after.singular_edges" "$(result "$repair_filter" after.singular_edges log.txt)" 0
    expect_eq "result after.singular_vertices" "$(result "$repair_filter" after.singular_vertices log.txt)" 0
    expect_eq "result faces_out == saved faces" "$(result "$repair_filter" faces_out log.txt)" "$(value faces output.txt)"
    expect_eq "result vertices_out == saved vertices" "$(result "$repair_filter" vertices_out log.txt)" "$(value vertices output.txt)"
    expect_eq "result before.singular_edges == core" "$(result "$repair_filter" before.singular_edges log.txt)" "$(value singular_edges input.txt)"
    if [ "$(result "$repair_filter" vertices_split log.txt)" -gt 0 ]; then
      grep -q "^log: To keep the repair, save as PLY, OBJ or OFF.*: they keep the" log.txt \
        && pass "log: which formats keep the repair" || fail "log: no hint on formats that keep the repair"
      grep -q "^log: STL re-read: saved as STL and loaded again, .*STL stores no shared vertices" log.txt \
        && pass "log: what STL would re-read" || fail "log: no 'STL re-read' line"
    else
      grep -q "^log: To keep the repair" log.txt && fail "log: save hint without split vertices" \
        || pass "log: no save hint (no vertex split)"
    fi
    # Detect, then Repair: the defect layer is gone and so is the selection Detect made.
    status=0
    run clean.log load in.off filter "$detect_filter" filter "$repair_filter" layers \
      save clean.ply layer=0 attributes=vf,ff binary=false || status=$?
    expect_eq "runner status (Detect, Repair)" "$status" 0
    expect_eq "layers after Detect + Repair" "$(sed -n 's/^layers: //p' clean.log)" 1
    "$MLCHECK" report clean.ply >clean.txt
    expect_eq "selected faces after Detect + Repair" "$(value selected_faces clean.txt)" 0
    expect_eq "selected vertices after Detect + Repair" "$(value selected_vertices clean.txt)" 0
    if [ "$(( $(value singular_edges input.txt) + $(value boundary_edges input.txt) + $(value singular_vertices input.txt) ))" -gt 0 ]; then
      grep -q "^log: Removed the defect layer 'in - defects' and cleared the selection" clean.log \
        && pass "log: defect layer removed" || fail "log: no 'Removed the defect layer'"
    fi
    check_expectations output.txt "$@"
    ;;

  attributes)
    "$MLCHECK" make-attributed "$model" in.ply
    status=0
    run log.txt load in.ply filter "$repair_filter" save repaired.ply attributes=vc,vq,fc,fq,wt binary=false \
      || status=$?
    cat log.txt
    expect_eq "runner status" "$status" 0
    expect_attributes_kept_and_manifold in.ply repaired.ply
    ;;

  no-faces)
    printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' >points.off
    for filter in "$repair_filter" "$detect_filter"; do
      # As pymeshlab does: MeshLab's own precondition check refuses first.
      status=0
      run "$filter.log" load points.off filter "$filter" save out.ply || status=$?
      cat "$filter.log" "$filter.log.stderr"
      [ "$status" -ne 0 ] && pass "$filter: refused ($status)" || fail "$filter: status 0"
      grep -q "^error: .*does not have Any Faces" "$filter.log.stderr" \
        && pass "$filter: MeshLab's precondition message" || fail "$filter: no precondition message"
      [ ! -e out.ply ] && pass "$filter: nothing saved" || fail "$filter: a mesh was saved"
      # Past the precondition check: our own MLException.
      status=0
      "$MLRUN" --no-precondition-check plugin "$MESHLAB_PLUGIN_DIR/libio_base.so" plugin "$PLUGIN" \
        load points.off filter "$filter" save out.ply >"$filter.forced.log" 2>&1 || status=$?
      cat "$filter.forced.log"
      [ "$status" -ne 0 ] && pass "$filter (forced): MLException ($status)" || fail "$filter (forced): status 0"
      grep -q "^error: Failed to apply filter: $filter" "$filter.forced.log" \
        && grep -q "needs a mesh with faces: layer 'points.off' has 3 vertices and no faces" "$filter.forced.log" \
        && pass "$filter (forced): clear error message" || fail "$filter (forced): no clear error message"
      [ ! -e out.ply ] && pass "$filter (forced): nothing saved" || fail "$filter (forced): a mesh was saved"
    done
    ;;

  gui)
    input_off
    "$MLCHECK" report "$model" >input.txt
    cp in.off "$name.off"  # MeshLab names the layer after the file
    # A private copy of the GUI that finds every plugin of Debian's MeshLab, and ours, beside
    # itself (<root>/bin/plugins: MeshLab looks there first), as a user has them.
    # The binary's RUNPATH is $ORIGIN/../lib/<multiarch>/meshlab (libmeshlab-common*.so).
    gui_root="$WORK/gui-root"
    multiarch=$(basename "$(dirname "$MESHLAB_LIB_DIR")")
    gui_lib="$gui_root/lib/$multiarch/meshlab"
    mkdir -p "$gui_root/bin" "$gui_lib/plugins"
    cmp -s /usr/bin/meshlab "$gui_root/bin/meshlab" || cp -f /usr/bin/meshlab "$gui_root/bin/meshlab"
    for p in "$MESHLAB_LIB_DIR"/*.so*; do ln -sfn "$p" "$gui_lib/$(basename "$p")"; done
    find "$gui_lib/plugins" -mindepth 1 -maxdepth 1 -name '*.so' -delete
    for p in "$MESHLAB_PLUGIN_DIR"/*.so "$PLUGIN"; do ln -sfn "$p" "$gui_lib/plugins/$(basename "$p")"; done
    ln -sfn "$gui_lib/plugins" "$gui_root/bin/plugins"
    status=0
    t0=$(date +%s%N)
    # Qt's xcb platform, not the offscreen one the headless runner uses.
    env -u QT_QPA_PLATFORM COUNT_PIXELS="$COUNT_PIXELS" bash "$(dirname "${BASH_SOURCE[0]}")/../meshlab/gui_detect.sh" \
      "$gui_root/bin/meshlab" "$dir/$name.off" "$dir/shot" >gui.txt || status=$?
    echo "GUI session: $(( ($(date +%s%N) - t0) / 1000000 )) ms"
    cat shot/session.txt
    expect_eq "GUI session status" "$status" 0
    grep -q "Error while loading plugins\|Unable to find the plugins" shot/meshlab.log \
      && fail "MeshLab could not load all its plugins" || pass "MeshLab loaded its plugins"
    expect_gui_shot shot input.txt "$name"
    ;;

  crossings)
    write_crossing_cubes cubes.off "$([ "$name" = crossing_cubes ] && echo 0.5 || echo 2)"
    "$MLCHECK" report cubes.off >input.txt
    faces=$(value self_intersecting_faces input.txt)
    expect_eq "core: crossing faces" "$faces" "$([ "$name" = crossing_cubes ] && echo 12 || echo 0)"
    status=0
    # No self_intersections given: on by default (24 faces, far below 2,000,000).
    run on.log load cubes.off filter "$detect_filter" \
      save layer.ply layer=last attributes=vc,fc binary=false || status=$?
    cat on.log
    expect_eq "Detect: runner status" "$status" 0
    expect_results "$detect_filter" on.log \
      "self_intersections.face_pairs=$(value self_intersecting_face_pairs input.txt)" \
      "self_intersections.faces=$faces" \
      "self_intersections.component_pairs=$(value crossing_component_pairs input.txt)" \
      "violet_faces=$faces" red_edges=0 green_edges=0
    expect_in_log "Detect: summary" on.log \
      "0 singular vertex markers, $faces violet (self-intersecting) faces"
    if [ -e layer.ply ]; then
      "$MLCHECK" report layer.ply >layer.txt
      expect_eq "tube layer: two violet triangles per crossing face" \
        "$(value violet_faces layer.txt)" "$(( 2 * faces ))"
    else
      expect_eq "no layer saved: nothing to show" "$faces" 0
    fi
    run off.log load cubes.off filter "$detect_filter" self_intersections=false || status=$?
    expect_eq "Detect (off): runner status" "$status" 0
    expect_results "$detect_filter" off.log self_intersections.face_pairs= violet_faces=
    expect_in_log "Detect (off)" off.log "self-intersections: not searched"
    ;;

  gaps)
    status=0
    case "$name" in
      cube_written_twice)
        write_cube_twice cube.off 7.62939453125e-06  # 2^-17: one float32 step at 110
        run detect.log load cube.off filter "$detect_filter" weld_tolerance=-1 close_t_junctions=true \
          save mesh.ply layer=0 attributes=vf binary=false || status=$?
        cat detect.log
        expect_eq "Detect: runner status" "$status" 0
        expect_in_log "Detect: what Repair would weld" detect.log "log: $cube_detect_line"
        expect_results "$detect_filter" detect.log gaps.vertices_welded=6 gaps.t_junctions_closed=0 \
          gaps.welds_refused=0 gaps.tolerance=5.245209104e-05 gaps.largest_weld_distance=1.321449896e-05
        "$MLCHECK" report mesh.ply >mesh.txt
        check_expectations mesh.txt vertices=16 boundary_edges=12
        repair_case auto cube.off weld_tolerance=-1 close_t_junctions=true
        expect_in_log "Repair (automatic): what it welded" auto.log "log: $cube_repair_line"
        expect_results "$repair_filter" auto.log gaps.vertices_welded=6 gaps.t_junctions_closed=0 \
          before.boundary_edges=12 after.boundary_edges=0 vertices_out=10
        check_expectations auto.txt vertices=10 faces=12 boundary_edges=0 singular_edges=0 watertight=1
        off_to_stl cube.off cube.stl
        repair_case stl cube.stl
        expect_in_log "Repair of an STL layer" stl.log "log: $cube_repair_line"
        expect_in_log "Repair of an STL layer: STL re-read" stl.log \
          "log: STL re-read: saved as STL and loaded again, this layer has singular edges 0, singular vertices 0, watertight yes"
        expect_results "$repair_filter" stl.log reread.singular_edges=0 reread.singular_vertices=0 \
          reread.boundary_edges=0 reread.watertight=True
        expect_not_in_log "Repair of an STL layer: no save hint" stl.log "To keep the repair"
        check_expectations stl.txt vertices=8 faces=12 boundary_edges=0 watertight=1
        repair_case off cube.off weld_tolerance=0
        expect_in_log "Repair (weld_tolerance=0)" off.log "log: gaps: not closed (tolerance 0)"
        expect_results "$repair_filter" off.log gaps.tolerance=0 gaps.vertices_welded=0
        check_expectations off.txt vertices=16 faces=12 boundary_edges=12
        write_cube_twice wide.off 0.001
        repair_case wide_auto wide.off
        expect_results "$repair_filter" wide_auto.log gaps.vertices_welded=0 after.boundary_edges=12
        repair_case wide wide.off weld_tolerance=0.002
        expect_in_log "Repair (wide crack, weld_tolerance=0.002)" wide.log \
          "log: gaps (tolerance 0.002): 6 vertices welded (largest move 0.00173"
        expect_results "$repair_filter" wide.log gaps.vertices_welded=6 after.boundary_edges=0
        check_expectations wide.txt vertices=10 faces=12 boundary_edges=0 watertight=1
        ;;
      t_junction_box)
        write_t_junction_box box.off
        run detect.log load box.off filter "$detect_filter" weld_tolerance=-1 close_t_junctions=true \
          || status=$?
        cat detect.log
        expect_eq "Detect: runner status" "$status" 0
        expect_in_log "Detect: what Repair would close" detect.log "log: $box_detect_line"
        expect_results "$detect_filter" detect.log gaps.t_junctions_closed=2 gaps.sides_split=2 \
          gaps.vertices_welded=0 boundary_edges=6
        repair_case auto box.off weld_tolerance=-1 close_t_junctions=true
        expect_in_log "Repair: what it closed" auto.log "log: $box_repair_line"
        expect_results "$repair_filter" auto.log gaps.t_junctions_closed=2 gaps.sides_split=2 \
          polygons_triangulated=2 faces_in=14 faces_out=16 after.boundary_edges=0 after.watertight=True
        check_expectations auto.txt vertices=10 faces=16 boundary_edges=0 singular_edges=0 watertight=1
        repair_case no_t box.off close_t_junctions=false
        expect_results "$repair_filter" no_t.log gaps.t_junctions_closed=0 after.boundary_edges=6
        check_expectations no_t.txt vertices=10 faces=14 boundary_edges=6
        ;;
      *) echo "unknown gap model $name"; exit 2 ;;
    esac
    ;;

  holes)
    # MeshLab loads the 13 quads as 26 triangles; the holes' rims keep 4 and 6 edges.
    write_open_boxes boxes.off
    repair_case off boxes.off
    expect_in_log "Repair (fill_holes=0, the default)" off.log "log: holes: not filled (off)"
    expect_results "$repair_filter" off.log holes.max_edges=0 holes.holes_filled=0 \
      holes.faces_added=0 after.boundary_edges=10
    repair_case four boxes.off fill_holes=4
    expect_in_log "Repair (fill_holes=4)" four.log \
      "log: holes (up to 4 edges): 1 filled with 2 new triangles, 1 left open"
    expect_results "$repair_filter" four.log holes.max_edges=4 holes.holes_filled=1 \
      holes.faces_added=2 holes.holes_left=1 faces_in=26 faces_out=28 after.boundary_edges=6
    check_expectations four.txt vertices=20 faces=28 boundary_edges=6 boundary_loops=1 watertight=0
    repair_case six boxes.off fill_holes=6
    expect_results "$repair_filter" six.log holes.max_edges=6 holes.holes_filled=2 \
      holes.faces_added=6 holes.holes_left=0 faces_out=32 after.boundary_edges=0 after.watertight=True
    check_expectations six.txt vertices=20 faces=32 boundary_edges=0 singular_edges=0 \
      inconsistent_edges=0 watertight=1
    ;;

  stl-truth)
    shift
    "$MLCHECK" to-off "$model" model.off
    off_to_stl model.off in.stl
    status=0
    run log.txt load in.stl filter "$repair_filter" save repaired.stl || status=$?
    cat log.txt
    expect_eq "runner status" "$status" 0
    split=$(result "$repair_filter" vertices_split log.txt)
    # The STL MeshLab wrote, read back as every STL reader does: the log must have said so.
    "$MLCHECK" to-off repaired.stl reread.off
    "$MLCHECK" report reread.off >reread.txt
    line="log: STL re-read: saved as STL and loaded again, this layer has singular edges $(value singular_edges reread.txt), singular vertices $(value singular_vertices reread.txt), watertight $([ "$(value watertight reread.txt)" = 1 ] && echo yes || echo no)"
    expect_in_log "log == the STL file written" log.txt "$line"
    expect_results "$repair_filter" log.txt "reread.singular_edges=$(value singular_edges reread.txt)" \
      "reread.singular_vertices=$(value singular_vertices reread.txt)" \
      "reread.boundary_edges=$(value boundary_edges reread.txt)"
    if [ "${split:-0}" -gt 0 ]; then
      expect_in_log "log: why" log.txt "STL stores no shared vertices: every reader welds the $split split vertex copies together again"
      expect_in_log "log: what keeps it" log.txt "log: To keep the repair, save as PLY, OBJ or OFF"
    else
      expect_not_in_log "log: no save hint without split vertices" log.txt "To keep the repair"
    fi
    check_expectations reread.txt "$@"
    ;;

  compare-builtin)
    input_off
    faces_in=$("$MLCHECK" report "$model" | sed -n 's/^triangles=//p')
    run_one() {  # run_one LABEL FILTER-STEP...: one runner call, then MeshLab's own checks
      local label=$1 t0 t1 status=0 fn nm
      shift
      t0=$(date +%s%N)
      run "$label.log" load in.off "$@" filter get_topological_measures \
        save "$label.ply" attributes=vf,ff binary=false || status=$?
      t1=$(date +%s%N)
      fn=$(result get_topological_measures faces_number "$label.log")
      nm=$(result get_topological_measures is_mesh_two_manifold "$label.log")
      if [ "$status" -ne 0 ]; then
        fn=none
        nm="runner failed, status $status: $(head -n1 "$label.log.stderr")"
      fi
      printf '%-34s faces %6s of %6s  wall %5d ms  two-manifold: %s\n' \
        "$label" "${fn:-?}" "$faces_in" $(( (t1 - t0) / 1000000 )) "$nm" | tee -a table.txt
      eval "faces_$label=\${fn:-none}"
    }
    run_one baseline
    run_one meshbridge filter "$repair_filter"
    run_one meshlab_removing_faces filter meshing_repair_non_manifold_edges "method=Remove Faces"
    run_one meshlab_splitting_vertices filter meshing_repair_non_manifold_edges "method=Split Vertices"
    echo "(wall time of one runner call each, plugin loading and MeshLab's checks included;"
    echo " 'baseline' runs no repair)"
    expect_eq "MeshBridge keeps every face" "$faces_meshbridge" "$faces_in"
    grep -q "^meshbridge .*two-manifold: True" table.txt && pass "MeshBridge result is two-manifold" \
      || fail "MeshBridge result not two-manifold"
    ;;

  *)
    echo "unknown mode $mode"; exit 2 ;;
esac

finish_checks "$dir"
