#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (OSS_BUILD_FUZZERS=ON, ASan + UBSan) in a
# build directory of their own and runs each for SECONDS seconds (default 60), starting
# from the seeds in fuzz/corpus/<target>. New inputs go to <build>/corpus/<target>, crashes
# to <build>/crashes/<target>-*; a crash fails the run. Prints libFuzzer's final stats.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]   Environment: FUZZ_BUILD_DIR (build-fuzz), JOBS (2).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-60}
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=(fuzz_osgt_technique fuzz_mesh_cache)
scripts/install-deps.sh
BUILD=${FUZZ_BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}
cmake -S . -B "$BUILD" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DOSS_BUILD_FUZZERS=ON -DOSS_BUILD_TESTS=OFF \
  -DOSS_BUILD_EXAMPLES=OFF -DOSS_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build "$BUILD" -j "$JOBS" --target "${TARGETS[@]}"

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
for t in "${TARGETS[@]}"; do
  mkdir -p "$BUILD/corpus/$t" "$BUILD/crashes"
  echo "== $t: ${SECONDS_PER_TARGET} s"
  if ! "$BUILD/bin/$t" -max_total_time="$SECONDS_PER_TARGET" -max_len=4096 -timeout=20 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$BUILD/crashes/$t-" "$BUILD/corpus/$t" "fuzz/corpus/$t" \
      >"$BUILD/$t.log" 2>&1; then
    status=1
    echo "$t FAILED; its log:"
  fi
  # The final statistics and the last progress line (coverage, features, corpus).
  grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE)|^stat::|ERROR|SUMMARY' "$BUILD/$t.log" | grep -vE 'NEW|REDUCE|pulse' | tail -15
done
exit $status
