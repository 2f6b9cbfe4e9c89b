#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the comparison benchmark of DESIGN.md section 9 and writes its markdown report.
#
#  1. installs what is missing (idempotent): the build tools, OpenMesh, Eigen 3, CGAL 5.5
#     (Debian libcgal-dev) and, unless vcglib is already there, MeshLab 2020.09's source through
#     scripts/setup_meshlab_sdk.sh (only its header-only vcglib is used: no Qt, no MeshLab library);
#  2. builds meshbridge-bench in Release in build/benchmark (-DMESHBRIDGE_BUILD_BENCH=ON; not
#     build/bench, which is the bench/ subfolder of a build in build/);
#  3. runs `meshbridge-bench suite` (1M and 5M tables with clean controls, vcglib's quadratic
#     split, MeshBridge scaling 1M -> 10M, the paper's experiments, the goals) and writes
#     bench/results.md, which it also prints. About 3-5 minutes on 2 cores.
#
#  4. with --io (or --io-only: instead of 2 and 3), the whole-process benchmark
#     scripts/bench_io.sh (every tool reading/writing the same files as its own process:
#     OpenMesh, meshbridge check/repair, meshlabserver, the mmap + from_chars floor), appended to
#     the report. About 30 minutes on 2 cores (the 5M files dominate); --quick: 1M, PLY and STL.
#
# Usage: scripts/bench.sh [--quick] [--io | --io-only] [--out FILE] [other suite options]
# Environment: BUILD_DIR (default build/benchmark), MESHLAB_SDK_DIR (folder holding vcglib/).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
build_dir="${BUILD_DIR:-$root/build/benchmark}"
log() { echo "bench: $*" >&2; }

# --- 1. dependencies -------------------------------------------------------------------------
packages=(build-essential cmake pkg-config libopenmesh-dev libeigen3-dev libcgal-dev time)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { log "need root or sudo to install: ${missing[*]}"; exit 1; }
    sudo_cmd=(sudo)
  fi
  log "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update -qq
  "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

sdk_dir="${MESHLAB_SDK_DIR:-}"
if [ -z "$sdk_dir" ]; then
  for candidate in "$root"/third_party/meshlab-sdk/*/vcglib; do
    if [ -f "$candidate/vcg/complex/complex.h" ]; then
      sdk_dir="$(dirname "$candidate")"
      break
    fi
  done
fi
if [ -z "$sdk_dir" ]; then
  log "fetching MeshLab 2020.09's source for vcglib (scripts/setup_meshlab_sdk.sh)"
  sdk_dir="$(bash scripts/setup_meshlab_sdk.sh | tail -n1)"
fi
if [ ! -f "$sdk_dir/vcglib/vcg/complex/complex.h" ]; then
  log "no vcglib in '$sdk_dir': the vcglib rows will be missing"
fi

io=0
for a in "$@"; do
  case "$a" in
    --io) io=1 ;;
    --io-only) io=2 ;;
  esac
done

# --- 2. build --------------------------------------------------------------------------------
log "building meshbridge-bench in $build_dir"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DMESHBRIDGE_BUILD_BENCH=ON \
  -DMESHBRIDGE_BUILD_TESTS=OFF -DMESHBRIDGE_BUILD_CLI="$([ "$io" -gt 0 ] && echo ON || echo OFF)" \
  -DMESHLAB_SDK_DIR="$sdk_dir" "${launcher[@]}" \
  | grep "meshbridge-bench" >&2 || true
targets=(meshbridge-bench)
[ "$io" -gt 0 ] && targets+=(meshbridge meshbridge-io-bench meshbridge-parse-bench)
cmake --build "$build_dir" --target "${targets[@]}" --parallel "$(nproc)" >/dev/null

# --- 3. run ----------------------------------------------------------------------------------
out="$root/bench/results.md"
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift 2 ;;
    --io | --io-only) shift ;;
    *) args+=("$1"); shift ;;
  esac
done
label="commit $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
log "running the suite (progress below, the report on stdout and in $out)"
quick=""
for a in "${args[@]}"; do
  [ "$a" = --quick ] && quick=--quick
done
if [ "$io" -lt 2 ]; then
  "$build_dir/bench/meshbridge-bench" suite --out "$out" --label "$label" "${args[@]}"
fi
if [ "$io" -gt 0 ]; then
  log "running the whole-process benchmark (scripts/bench_io.sh)"
  io_out="$build_dir/results_io.md"
  bash "$root/scripts/bench_io.sh" "$build_dir" "$io_out" $quick >/dev/null
  { echo; cat "$io_out"; } >>"$out"
  cat "$io_out"
fi
