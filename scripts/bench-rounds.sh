# Sourced by the benchmark scripts that time interleaved rounds: the build directory, the
# output directory, frames per render and rounds, each overridable from the environment
# (BUILD_DIR, OUT, ROUNDS; QUICK=1 for 5 frames in 1 round, a smoke test, not results), and
# bench_setup, which builds what a benchmark runs.
BUILD_DIR=${BUILD_DIR:-build-bench}
OUT=${OUT:-docs/bench}
FRAMES=20
ROUNDS=${ROUNDS:-3}
if [ -n "${QUICK:-}" ]; then FRAMES=5 ROUNDS=1; fi
# bench_setup TARGET: configures $BUILD_DIR (Release unless BUILD_TYPE says otherwise), builds
# TARGET, points OSG at the build's plugins, creates $OUT and a scratch directory $TMP.
bench_setup() {
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} >/dev/null
  cmake --build "$BUILD_DIR" -j "${JOBS:-2}" --target "$1" >/dev/null
  export OSG_LIBRARY_PATH="$PWD/$BUILD_DIR/lib"
  export OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-WARN}
  mkdir -p "$OUT"
  TMP=$(mktemp -d)
}
