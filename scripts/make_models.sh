#!/usr/bin/env bash
# Regenerates the bundled canonical models resources/models/<name>.obj with
# meshbridge-make-models (built from models/). Usage: scripts/make_models.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash scripts/install_deps.sh
cmake -S . -B build/make-models -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=OFF \
  -DMESHBRIDGE_BUILD_CLI=OFF >/dev/null
cmake --build build/make-models --target meshbridge-make-models --parallel "$(nproc)" >/dev/null
build/make-models/models/meshbridge-make-models "$root/resources/models"
