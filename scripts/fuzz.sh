#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang, AddressSanitizer and UBSan in build/fuzz
# and runs each for SECONDS (default 60), seeded from tests/fuzz/corpus, resources/models and
# tests/data/realworld. Prints executions and findings per target; a finding (crash, leak,
# timeout, out-of-memory) is kept in build/fuzz/findings/<target>/ and makes the exit status 1.
# The working corpus in build/fuzz/corpus/<target> grows across runs: run longer campaigns with
# a larger SECONDS, e.g. `bash scripts/fuzz.sh 3600`. Installs clang if it is missing.
# Usage: bash scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: fuzz_repair fuzz_read)
#   FUZZ_EXTRA_FLAGS="-fno-sanitize=..." adds compiler flags, e.g. to get past a known finding.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_repair fuzz_read)
case "$seconds" in
  '' | *[!0-9]*) echo "fuzz.sh: SECONDS must be a whole number, got '$seconds'" >&2; exit 2 ;;
esac
jobs="$(nproc 2>/dev/null || echo 2)"

# Debian bookworm: clang 14 with libFuzzer and the sanitizer runtimes.
bash scripts/install_deps.sh clang libclang-rt-14-dev
export CC=clang CXX=clang++

build=build/fuzz
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
flags="$flags -fno-omit-frame-pointer -g ${FUZZ_EXTRA_FLAGS:-}"
cmake -S tests/fuzz -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS="$flags" >/dev/null
cmake --build "$build" --parallel "$jobs" --target "${targets[@]}" >"$build/build.log" 2>&1 || {
  cat "$build/build.log" >&2
  exit 2
}

# fuzz_read's first byte picks the extension: 0 obj, 1 off, 2 ply, 3 stl.
seeds="$build/seeds/fuzz_read"
rm -rf "$seeds"
mkdir -p "$seeds"
selector() {
  case "$(echo "${1##*.}" | tr '[:upper:]' '[:lower:]')" in
    obj) printf '\000' ;;
    off) printf '\001' ;;
    ply) printf '\002' ;;
    stl) printf '\003' ;;
  esac
}
for f in resources/models/* tests/data/realworld/*; do
  case "$f" in *.obj | *.off | *.ply | *.stl | *.STL) ;; *) continue ;; esac
  { selector "$f"; cat "$f"; } >"$seeds/$(basename "$f")"
done

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
status=0
printf '%-12s %12s %8s %10s  %s\n' target executions exec/s corpus findings
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  findings="$build/findings/$target"
  rm -rf "$findings"  # findings of this run only; the corpus keeps growing across runs
  mkdir -p "$corpus" "$findings"
  inputs=("$corpus" "tests/fuzz/corpus/$target")
  options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/")
  if [ "$target" = fuzz_read ]; then
    inputs+=("$seeds")
    options+=(-dict=tests/fuzz/fuzz_read.dict)
  fi
  log="$build/$target.log"
  "$build/$target" "${options[@]}" "${inputs[@]}" >"$log" 2>&1 || true
  executions="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -n 1)"
  speed="$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -n 1)"
  found=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
    -o -name 'oom-*' -o -name 'slow-unit-*' \) | wc -l)
  printf '%-12s %12s %8s %10s  %s\n' "$target" "${executions:-?}" "${speed:-?}" \
    "$(find "$corpus" -type f | wc -l)" "$found"
  if [ "$found" -gt 0 ] || [ -z "$executions" ]; then
    status=1
    echo "  $target: see $log and $findings/ (reproduce: $build/$target FILE)" >&2
    grep -m 5 -E 'ERROR|invariant violated|SUMMARY|deadly signal' "$log" | sed 's/^/  /' >&2 || true
  fi
done
exit "$status"
