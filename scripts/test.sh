#!/usr/bin/env bash
# README's test command: installs what is missing (Debian packages), builds everything with
# tests and runs them all through ctest. Usage: bash scripts/test.sh
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_deps.sh

build=build/test
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_TESTS=ON \
  -DMESHBRIDGE_BUILD_CLI=ON
cmake --build "$build" --parallel "$jobs"
ctest --test-dir "$build" --output-on-failure --parallel "$jobs"
