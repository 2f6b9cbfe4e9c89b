#!/usr/bin/env bash
# README's main job: installs what is missing, builds, and runs MeshBridge on the bundled
# 24-prism model (the paper's model 2). Results go to out/.
# Usage: bash scripts/demo.sh [MODEL]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
model="${1:-resources/models/prisms24.obj}"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_deps.sh
cmake -S . -B build/release -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=OFF >/dev/null
cmake --build build/release --parallel "$jobs" >/dev/null
tool=build/release/cli/meshbridge
name="$(basename "${model%.*}")"
mkdir -p out

echo "== meshbridge check $model"
"$tool" check "$model" || [ $? -eq 1 ]
echo
echo "== meshbridge compare $model"
"$tool" compare "$model"
echo
echo "== meshbridge repair $model out/$name.repaired.obj"
"$tool" repair "$model" "out/$name.repaired.obj" --report "out/$name.repair.json"
echo
echo "== meshbridge check out/$name.repaired.obj"
"$tool" check "out/$name.repaired.obj" || [ $? -eq 1 ]
echo
echo "wrote out/$name.repaired.obj and out/$name.repair.json"
