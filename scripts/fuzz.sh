#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang, AddressSanitizer and UBSan in build/fuzz
# and runs each for SECONDS (default 60), seeded from tests/fuzz/corpus, resources/models and
# tests/data/realworld. Prints executions and findings per target; a finding (crash, leak,
# timeout, out-of-memory) is kept in build/fuzz/findings/<target>/ and makes the exit status 1.
# The working corpus in build/fuzz/corpus/<target> grows across runs: run longer campaigns with
# a larger SECONDS, e.g. `bash scripts/fuzz.sh 3600`. Installs clang if it is missing.
# Usage: bash scripts/fuzz.sh [SECONDS] [TARGET...]   (targets: fuzz_repair fuzz_read)
#   FUZZ_EXTRA_FLAGS="-fno-sanitize=..." adds compiler flags, e.g. to get past a known finding.
#   FUZZ_RUNS=N makes the run reproducible (what scripts/test.sh, i.e. CI, does): N executions per
#   target from seed FUZZ_SEED (default 1), starting from the committed corpus and the seeds only
#   (a fresh working corpus in build/fuzz/repro/), with no time limit. The same commit then gives
#   the same inputs on every machine (fuzz_repair exactly; fuzz_read for at least its first 20000
#   executions, then nearly), so CI runs what a local run of the same command runs. New bugs are
#   hunted by the timed, randomly seeded campaigns. Address space
#   randomisation is turned off for these runs (setarch -R; libstdc++ takes address-dependent
#   branches, which changes coverage); where the kernel refuses that, the run says it is not
#   reproducible and goes on.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_repair fuzz_read)
runs="${FUZZ_RUNS:-}"
seed="${FUZZ_SEED:-1}"
for number in "$seconds" "$runs" "$seed"; do
  case "$number" in
    *[!0-9]*) echo "fuzz.sh: SECONDS, FUZZ_RUNS and FUZZ_SEED are whole numbers, got '$number'" >&2; exit 2 ;;
  esac
done
[ -n "$seconds" ] || seconds=60
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
launcher=()
if [ -n "$runs" ]; then
  if setarch "$(uname -m)" -R true 2>/dev/null; then
    launcher=(setarch "$(uname -m)" -R)
  else
    echo "fuzz.sh: cannot turn off address space randomisation here: this run is not reproducible" >&2
  fi
fi
status=0
printf '%-12s %12s %8s %10s  %s\n' target executions exec/s corpus findings
for target in "${targets[@]}"; do
  findings="$build/findings/$target"
  rm -rf "$findings"  # findings of this run only
  options=(-timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 -max_len=65536
    -print_final_stats=1 -artifact_prefix="$findings/")
  if [ -n "$runs" ]; then
    corpus="$build/repro/$target"  # reproducible: starts empty every time
    rm -rf "$corpus"
    options+=(-runs="$runs" -seed="$seed" -reload=0)
    export MESHBRIDGE_FUZZ_SCRATCH_ID="repro_$target"  # fuzz_read's file names: no pid
  else
    corpus="$build/corpus/$target"  # campaigns: keeps growing across runs
    options+=(-max_total_time="$seconds")
  fi
  mkdir -p "$corpus" "$findings"
  inputs=("$corpus" "tests/fuzz/corpus/$target")
  if [ "$target" = fuzz_read ]; then
    inputs+=("$seeds")
    options+=(-dict=tests/fuzz/fuzz_read.dict)
  fi
  log="$build/$target.log"
  "${launcher[@]}" "$build/$target" "${options[@]}" "${inputs[@]}" >"$log" 2>&1 || true
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
