# Sourced by the benchmark scripts that time interleaved rounds: the build directory, the
# output directory, frames per render and rounds, each overridable from the environment
# (BUILD_DIR, OUT, ROUNDS; QUICK=1 for 5 frames in 1 round, a smoke test, not results).
BUILD_DIR=${BUILD_DIR:-build-bench}
OUT=${OUT:-docs/bench}
FRAMES=20
ROUNDS=${ROUNDS:-3}
if [ -n "${QUICK:-}" ]; then FRAMES=5 ROUNDS=1; fi
