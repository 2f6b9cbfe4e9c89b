#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Screenshots of the real MeshLab GUI (Debian's /usr/bin/meshlab, 2020.09) showing the defect
# layer of the MeshBridge plugin over a bundled model: singular edges red, boundary edges green.
#
#  1. meshlabserver (private root, see scripts/meshlab_private_root.sh) runs
#     resources/scripts/detect.mlx on the model and saves the defect layer as OBJ (OBJ keeps the
#     edges and their per-vertex colours; meshlabserver's PLY writer drops edges);
#  2. a MeshLab project (.mlp) opens the model and its defect layer together, both turned by
#     the same matrix for a 3/4 view, with rendering options: model solid light grey with its
#     triangle wireframe, defect layer as thick edges (and singular-vertex points) in their
#     vertex colours;
#  3. the GUI runs from a second private root (the GUI finds its plugins like meshlabserver:
#     <root>/bin/meshlab -> <root>/lib/<multiarch>/meshlab/plugins, so it loads the freshly
#     built plugin and nothing is installed system-wide) under Xvfb; xdotool sizes the window
#     and hides the trackball (Shift+H); ImageMagick's `import` grabs the window.
#  4. one more shot opens Filters > Cleaning and Repairing to show the plugin's two filters.
#
# Usage: scripts/meshlab_screenshot.sh [OUT_DIR] [MODEL[:AZIMUTH:ELEVATION] ...]
#   OUT_DIR defaults to docs/images; models default to prisms24 and t_junction_rib (bundled
#   resources/models/<name>.off, or a path to an .off file). Writes OUT_DIR/meshlab_<name>.png
#   and OUT_DIR/meshlab_filters_menu.png. Work files (defect layers, .mlp projects, logs) and the two
#   private roots go to build/release/meshlab-screenshot/.
# Environment: PLUGIN (default build/release/plugin/libfilter_meshbridge.so, built if missing),
#   SIZE (screen and window size, default 1200x800), WIRE_WIDTH / POINT_SIZE (defect edges and
#   vertex markers, default 7 / 11 px), LIFT (see rotation_matrices, default 0.01), ZOOM_STEPS
#   (mouse-wheel steps, default 1).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
caller_dir="$PWD"
cd "$repo"
die() { echo "meshlab_screenshot: $*" >&2; exit 1; }
from_caller() { case "$1" in /*) echo "$1" ;; *) echo "$caller_dir/$1" ;; esac; }

out_dir="docs/images"
[ $# -gt 0 ] && out_dir=$(from_caller "$1")
[ $# -gt 0 ] && shift
models=("$@")
[ ${#models[@]} -gt 0 ] || models=(prisms24:30:30 t_junction_rib:-30:35)
size="${SIZE:-1200x800}"
plugin="${PLUGIN:-$repo/build/release/plugin/libfilter_meshbridge.so}"
base="$repo/build/release/meshlab-screenshot"
work="$base/work"
server_root="$base/server-root"
gui_root="$base/gui-root"
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
lib_dir="/usr/lib/${multiarch}/meshlab"
# ImageMagick's tools by absolute path (/usr/bin/import in the driver below): something else
# may shadow `convert` on PATH.
im_convert=/usr/bin/convert

# --- dependencies (idempotent: installs only what is missing) --------------------------------
bash scripts/install_deps.sh meshlab xvfb xauth imagemagick xdotool
if [ ! -f "$plugin" ]; then
  echo "meshlab_screenshot: building the plugin"
  sdk="$(bash scripts/setup_meshlab_sdk.sh | tail -n 1)"
  cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=OFF \
    -DMESHBRIDGE_BUILD_PLUGIN=ON -DMESHLAB_SDK_DIR="$sdk" >/dev/null
  cmake --build build/release --parallel "$(nproc 2>/dev/null || echo 2)" --target filter_meshbridge >/dev/null
fi
[ -f "$plugin" ] || die "no plugin $plugin"
mkdir -p "$work" "$out_dir"
out_dir="$(cd "$out_dir" && pwd)"

# --- private roots ---------------------------------------------------------------------------
bash scripts/meshlab_private_root.sh make "$server_root" "$plugin" >/dev/null
make_gui_root() {
  local rel="lib/${multiarch}/meshlab" p
  mkdir -p "$gui_root/bin" "$gui_root/$rel/plugins" "$gui_root/config"
  # A copy, not a link: Qt's applicationDirPath() resolves symlinks to /usr/bin.
  cmp -s /usr/bin/meshlab "$gui_root/bin/meshlab" || cp -f /usr/bin/meshlab "$gui_root/bin/meshlab"
  ln -sfn "$lib_dir/libmeshlab-common.so" "$gui_root/$rel/libmeshlab-common.so"
  find "$gui_root/$rel/plugins" -mindepth 1 -maxdepth 1 -name '*.so' -delete
  for p in io_base decorate_base filter_clean filter_select filter_meshing filter_measure filter_layer; do
    ln -sfn "$lib_dir/plugins/lib${p}.so" "$gui_root/$rel/plugins/lib${p}.so"
  done
  ln -sfn "$(cd "$(dirname "$plugin")" && pwd)/$(basename "$plugin")" "$gui_root/$rel/plugins/$(basename "$plugin")"
  # Fresh GUI settings every time (no window geometry or recent files from a previous run).
  rm -rf "$gui_root/config"
  mkdir -p "$gui_root/config"
}
make_gui_root

# --- MeshLab project ---------------------------------------------------------------------------
# RenderingOption text = MeshLab 2020.09's MLRenderingData::serialize(): 4 chars primitive mask
# (solid, wire triangles, wire edges, points), 4 x 9 chars of per-primitive attributes
# (points, wire edges, wire triangles, solid: vertex position, vertex normal, face normal,
# vertex colour, face colour, vertex texcoord, wedge texcoord, vertex indices, edge indices),
# then 32 chars of per-view options (MLPerViewGLOptions::serialize, char i = option i).
glopts() {  # glopts I...: the 32-char option string with options I set
  local s=() i
  for i in $(seq 0 31); do s[$i]=0; done
  for i in "$@"; do s[$i]=1; done
  local IFS=
  echo "${s[*]}"
}
# options: 0 visible, 8 edge-wire ("faux") mode, 9 wire on, 11 single-side lighting,
# 15/16 vertex/face selection shown, 18 bbox fixed colour, 20 wire user colour,
# 21 solid user colour, 27 points unshaded, 28 wire unshaded, 31 point attenuation.
# Model: solid (flat: face normals) + triangle wireframe in a user colour.
mesh_opts="1100""000000000""000000000""101000000""101000000""$(glopts 0 9 11 15 16 18 20 21 28 31)"
# Defect layer: edges + points, both in vertex colour (red / green / magenta), unlit.
defect_opts="0011""100100000""100100001""000000000""000000000""$(glopts 0 8 9 11 15 16 18 27 28)"

# rotation_matrices OFF AZ EL: two MLMatrix44 texts, separated by a line "--".
# The model's: R = Rx(EL - 90) * Rz(AZ), a 3/4 view of a Z-up model from azimuth AZ and
# elevation EL (MeshLab's default view looks down -Z with Y up). The defect layer's: the same R,
# then scaled by 1 - LIFT about MeshLab's eye point, which moves the edges LIFT of the way
# towards the eye without moving them on screen, so the solid faces next to an edge do not hide
# half of its thick line (an edge in a concave corner, like the T-junction, would otherwise be
# drawn one pixel wide). MeshLab 2020.09 (GLArea::resetTrackBall, setView) puts the eye at the
# document's box centre + (0, 0, 1.75 / tan(30 deg) * diag / 3), box = union of the layers'
# boxes, each with its 8 corners transformed by its layer's matrix.
rotation_matrices() {
  awk -v az="$2" -v el="$3" -v lift="${LIFT:-0.01}" '
    function min(a, b) { return a < b ? a : b }
    function max(a, b) { return a > b ? a : b }
    /^[ \t]*(#|$)/ { next }
    header == 0 { header = 1; if ($1 ~ /^OFF/) { if (NF > 1) { nv = $2; header = 2 } next } }
    header == 1 { nv = $1; header = 2; next }
    header == 2 && seen < nv {
      for (i = 1; i <= 3; i++) {
        lo[i] = seen ? min(lo[i], $i) : $i; hi[i] = seen ? max(hi[i], $i) : $i
      }
      seen++
    }
    END {
      pi = atan2(0, -1); a = az * pi / 180; e = (el - 90) * pi / 180
      ca = cos(a); sa = sin(a); ce = cos(e); se = sin(e)
      r[0,0] = ca;      r[0,1] = -sa;     r[0,2] = 0
      r[1,0] = ce * sa; r[1,1] = ce * ca; r[1,2] = -se
      r[2,0] = se * sa; r[2,1] = se * ca; r[2,2] = ce
      for (k = 0; k < 8; k++) {
        p[1] = (k % 2) ? hi[1] : lo[1]; p[2] = (int(k / 2) % 2) ? hi[2] : lo[2]; p[3] = (int(k / 4) % 2) ? hi[3] : lo[3]
        for (i = 0; i < 3; i++) {
          q = r[i,0] * p[1] + r[i,1] * p[2] + r[i,2] * p[3]
          bl[i] = k ? min(bl[i], q) : q; bh[i] = k ? max(bh[i], q) : q
        }
      }
      diag = sqrt((bh[0] - bl[0])^2 + (bh[1] - bl[1])^2 + (bh[2] - bl[2])^2)
      for (i = 0; i < 3; i++) eye[i] = (bl[i] + bh[i]) / 2
      eye[2] += 1.75 / (sin(pi / 6) / cos(pi / 6)) * diag / 3
      s = 1 - lift
      for (i = 0; i < 3; i++) printf "%.7f %.7f %.7f 0 \n", r[i,0], r[i,1], r[i,2]
      printf "0 0 0 1 \n--\n"
      for (i = 0; i < 3; i++) printf "%.7f %.7f %.7f %.7f \n", s * r[i,0], s * r[i,1], s * r[i,2], (1 - s) * eye[i]
      printf "0 0 0 1 \n"
    }' "$1"
}

write_project() {  # write_project NAME AZ EL: $work/NAME.mlp over NAME.off and NAME.defects.obj
  local name=$1 m d
  m=$(rotation_matrices "$work/$name.off" "$2" "$3")
  d=${m#*--$'\n'}
  m=${m%$'\n'--*}
  cat >"$work/$name.mlp" <<EOF
<!DOCTYPE MeshLabDocument>
<MeshLabProject>
 <MeshGroup>
  <MLMesh label="$name" filename="$name.off" visible="1">
   <MLMatrix44>
$m
</MLMatrix44>
   <RenderingOption solidColor="225 225 225 255" wireColor="110 110 110 255" boxColor="234 234 234 255" pointColor="255 255 255 255" wireWidth="1" pointSize="3">$mesh_opts</RenderingOption>
  </MLMesh>
  <MLMesh label="$name defects" filename="$name.defects.obj" visible="1">
   <MLMatrix44>
$d
</MLMatrix44>
   <RenderingOption solidColor="255 255 255 255" wireColor="64 64 64 255" boxColor="234 234 234 255" pointColor="255 255 255 255" wireWidth="${WIRE_WIDTH:-7}" pointSize="${POINT_SIZE:-11}">$defect_opts</RenderingOption>
  </MLMesh>
 </MeshGroup>
 <RasterGroup/>
</MeshLabProject>
EOF
}

# --- the GUI under Xvfb ----------------------------------------------------------------------
# gui_shot PNG MODE ARGS...: starts meshlab with ARGS on a fresh Xvfb, grabs its window into PNG.
# MODE "view": trackball hidden; MODE "menu": Filters > Cleaning and Repairing opened.
gui_shot() {
  local png=$1 mode=$2; shift 2
  local driver="$work/gui_driver.sh"
  cat >"$driver" <<'EOF'
#!/usr/bin/env bash
# Runs inside xvfb-run: $1 root, $2 raw png, $3 size, $4 mode, $5 log, then meshlab's arguments.
set -u
root=$1 raw=$2 size=$3 mode=$4 log=$5; shift 5
export XDG_CONFIG_HOME="$root/config"
"$root/bin/meshlab" "$@" >"$log" 2>&1 &
pid=$!
wid=$(timeout 60 xdotool search --sync --onlyvisible --name "^MeshLab 20" | head -n 1)
[ -n "$wid" ] || { echo "no MeshLab window"; kill "$pid"; exit 1; }
xdotool windowmove "$wid" 0 0 windowsize "$wid" "${size%x*}" "${size#*x}" windowfocus --sync "$wid"
sleep 2
# Shift+H: View > Show Trackball (on by default); hide it so the edges stand alone. Then a few
# mouse-wheel steps over the 3D view to zoom in (MeshLab's fit leaves a wide margin).
xdotool mousemove 390 380 key shift+h
sleep 0.5
for _ in $(seq 1 "${ZOOM_STEPS:-1}"); do xdotool click "${ZOOM_BUTTON:-5}"; sleep 0.3; done
if [ "$mode" = menu ]; then
  xdotool key alt+l  # Filters (its mnemonic: Fi&lters)
  sleep 1
  # Walk the Filters menu down to "Cleaning and Repairing" and open that submenu.
  for _ in $(seq 1 "${MENU_STEPS:-2}"); do xdotool key Down; sleep 0.2; done
  xdotool key Right
  sleep 0.5
  # ... and highlight "Detect Singular Defects (Bridged Half-Edge)" (third, alphabetical order).
  for _ in $(seq 1 "${SUBMENU_STEPS:-2}"); do xdotool key Down; sleep 0.2; done
  sleep 1
fi
sleep 3
/usr/bin/import -window root "$raw"
status=$?
kill "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
exit $status
EOF
  local stem attempt status=0
  stem="$work/$(basename "$png" .png)"
  for attempt in 1 2 3; do
    status=0
    xvfb-run -a -s "-screen 0 ${size}x24 -nolisten tcp" \
      bash "$driver" "$gui_root" "$stem.raw.png" "$size" "$mode" "$stem.gui.log" "$@" || status=$?
    [ "$status" -eq 0 ] && break
    sleep "$attempt"
  done
  [ "$status" -eq 0 ] || { cat "$stem.gui.log" >&2; die "meshlab GUI screenshot failed ($png)"; }
  # Only the window (it sits at 0,0), as a palette PNG: small enough to commit.
  "$im_convert" "$stem.raw.png" -crop "${size}+0+0" +repage -colors 256 -define png:compression-level=9 \
    -strip "$png"
  rm -f "$stem.raw.png"
}

for spec in "${models[@]}"; do
  IFS=: read -r model az el <<<"$spec"
  az=${az:-30}; el=${el:-30}
  case "$model" in
    *.off) src=$(from_caller "$model") ;;
    *) src="resources/models/$model.off" ;;
  esac
  [ -f "$src" ] || die "no model $src (meshlabserver 2020.09 needs OFF or PLY input)"
  name=$(basename "$src" .off)
  cp -f "$src" "$work/$name.off"
  rm -f "$work/$name.defects.obj"
  echo "== $name: meshlabserver detect.mlx -> $work/$name.defects.obj"
  bash scripts/meshlab_private_root.sh run "$server_root" -i "$work/$name.off" \
    -o "$work/$name.defects.obj" -l x -m vc -s resources/scripts/detect.mlx >"$work/$name.detect.log" 2>&1 \
    || { cat "$work/$name.detect.log" >&2; die "meshlabserver failed on $name"; }
  grep -h "^Defect layer" "$work/$name.detect.log" | head -n 1
  [ -f "$work/$name.defects.obj" ] || die "no defect layer for $name (nothing to show?)"
  write_project "$name" "$az" "$el"
  png="$out_dir/meshlab_$name.png"
  echo "== $name: meshlab $work/$name.mlp -> $png"
  gui_shot "$png" view "$work/$name.mlp"
  echo "   $(du -k "$png" | cut -f1) KB"
done

png="$out_dir/meshlab_filters_menu.png"
first=$(basename "${models[0]%%:*}" .off)
echo "== Filters > Cleaning and Repairing -> $png"
gui_shot "$png" menu "$work/$first.mlp"
echo "   $(du -k "$png" | cut -f1) KB"
