#!/usr/bin/env bash
# README's main job: installs what is missing, builds everything (core, CLI, MeshLab plugin,
# bench, Python module; no tests) into build/release, and runs Debian's real meshlabserver
# (MeshLab 2020.09) with the MeshBridge plugin on the bundled 24-prism model (the paper's
# model 2): the detection report and the repair counts from MeshLab's log, the defect layer and
# the repaired mesh under out/. Then the same through the command-line tool and the Python module.
# Usage: bash scripts/demo.sh [MODEL.off]
set -euo pipefail
# MeshLab's log escapes < > & as HTML entities; print them as written.
unescape_html() { sed -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&amp;/\&/g'; }

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
model="${1:-resources/models/prisms24.off}"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_deps.sh
sdk="$(bash scripts/setup_meshlab_sdk.sh | tail -n 1)"
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=OFF \
  -DMESHBRIDGE_BUILD_CLI=ON -DMESHBRIDGE_BUILD_PLUGIN=ON -DMESHBRIDGE_BUILD_BENCH=ON \
  -DMESHBRIDGE_BUILD_PYTHON=ON -DMESHLAB_SDK_DIR="$sdk" >/dev/null
cmake --build build/release --parallel "$jobs" >/dev/null
tool=build/release/cli/meshbridge
# meshbridge on PATH: as root, a symbolic link /usr/local/bin/meshbridge to the built CLI (it
# finds its pictures module through the link); otherwise the line that puts it on PATH is printed
# at the end. An installed meshbridge that is not our link is left alone. MESHBRIDGE_BIN_DIR
# puts the link elsewhere (default /usr/local/bin).
link="${MESHBRIDGE_BIN_DIR:-/usr/local/bin}/meshbridge"
on_path="to put meshbridge on PATH: export PATH=\"$root/build/release/cli:\$PATH\""
if [ -w "$(dirname "$link")" ] && { [ ! -e "$link" ] || [ -L "$link" ]; }; then
  ln -sfn "$root/$tool" "$link"
  on_path="meshbridge is on PATH: $link -> $root/$tool"
fi
name="$(basename "${model%.*}")"
out="$root/out"
mkdir -p "$out"
meshlab_root="$root/build/release/meshlab-root"
bash scripts/meshlab_private_root.sh make "$meshlab_root" build/release/plugin/libfilter_meshbridge.so >/dev/null

echo "== meshlabserver: Detect Singular Defects (Bridged Half-Edge) on $model"
bash scripts/meshlab_private_root.sh run "$meshlab_root" -i "$model" \
  -o "$out/$name.defects.obj" -l x -m vc -s resources/scripts/detect.mlx \
  >"$out/$name.detect.log" 2>&1
grep -v "^LOG:" "$out/$name.detect.log" | grep -E "MeshBridge|singular|boundary|vertices|faces|self-intersect|components|watertight|Defect layer" | awk '!seen[$0]++' | unescape_html || true
echo
echo "== meshlabserver: Repair Singular Defects (Bridged Half-Edge) on $model"
bash scripts/meshlab_private_root.sh run "$meshlab_root" -i "$model" \
  -o "$out/$name.repaired.ply" -m vc fc fq -s resources/scripts/repair.mlx \
  >"$out/$name.repair.log" 2>&1
grep -v "^LOG:" "$out/$name.repair.log" | grep -E "MeshBridge|faces|vertices|sides|components|after|Layer now" | awk '!seen[$0]++' | unescape_html || true
echo "(MeshLab holds triangles only: it loads a polygon of n corners as n - 2 triangles, so its"
echo " face counts and the file it wrote count triangles, where meshbridge counts the polygons"
echo " of $model)"
echo
echo "== meshbridge check $out/$name.repaired.ply"
"$tool" check "$out/$name.repaired.ply" || [ $? -eq 1 ]
echo
echo "== meshbridge compare $model (OpenMesh's stock loader vs the bridged build)"
"$tool" compare "$model"
echo
echo "== meshbridge snapshot: the defects as a picture, before and after repair"
"$tool" snapshot "$model" "$out/$name.defects.png" || [ $? -eq 1 ]
"$tool" snapshot "$out/$name.repaired.ply" "$out/$name.repaired.png" || [ $? -eq 1 ]
echo
echo "== python: meshbridge.read + check + repair on numpy arrays (build/release/python)"
PYTHONPATH="$root/build/release/python" /usr/bin/python3 - "$model" <<'PYTHON'
import sys
import meshbridge

soup = meshbridge.read(sys.argv[1])
before = meshbridge.check(soup)
vertices, faces, report = meshbridge.repair(soup.vertices, soup.faces)
after = meshbridge.check(vertices, faces)
print(f"read {len(soup.faces)} faces: {before['singular_edges']} singular edges, "
      f"{before['singular_vertices']} singular vertices")
print(f"repaired: {report['faces_out']} faces, {report['vertices_out']} vertices "
      f"({report['vertices_split']} copies from split fans); after: {after['singular_edges']} "
      f"singular edges, {after['singular_vertices']} singular vertices")
PYTHON
echo
echo "wrote $out/$name.defects.obj (defect layer), $out/$name.repaired.ply (repaired mesh),"
echo "$out/$name.defects.png and $out/$name.repaired.png (pictures)"
echo "and the meshlabserver logs $out/$name.detect.log, $out/$name.repair.log"
echo
echo "$on_path"
