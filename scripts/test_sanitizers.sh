#!/usr/bin/env bash
# Builds MeshBridge with AddressSanitizer and UndefinedBehaviorSanitizer (gcc) in build/asan and
# runs the unit and command-line tests through ctest; the first error of either sanitizer (a
# leak included) fails the test it happens in. The MeshLab plugin and the package test are left
# out (they load or build against code that is not instrumented).
# Usage: bash scripts/test_sanitizers.sh [extra ctest arguments]
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/install_deps.sh

build=build/asan
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# -O1 -g1 (line tables: enough for the sanitizers' stack traces): the build takes about half the
# time of -O2 -g (12 min there on 2 cores), and ASan recommends -O1 anyway.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DMESHBRIDGE_BUILD_TESTS=ON \
  -DMESHBRIDGE_BUILD_CLI=ON -DMESHBRIDGE_BUILD_PLUGIN=OFF -DMESHBRIDGE_BUILD_BENCH=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null

export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# lib3mf's libzip leaks a few blocks per process (tests/lsan_libzip.supp); nothing else is
# suppressed. The CLI tests that start Qt set their own list (tests/cli/lsan_qt_offscreen.supp).
# Hostile-input time limits x10: they catch blow-ups (quadratic work is ~1000x slower there), and
# ASan on a loaded 2-core machine is 20-40x slower than the release build.
export MESHBRIDGE_TIME_SCALE=10
export LSAN_OPTIONS="suppressions=$root/tests/lsan_libzip.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
cmake --build "$build" --parallel "$jobs"
# Everything but the package test (a downstream build) and the MeshLab/resource checks.
ctest --test-dir "$build" --output-on-failure --parallel "$jobs" \
  --exclude-regex '^(package|resources|meshlab)' "$@"
