#!/usr/bin/env bash
# What a caster deformed on the CPU every frame costs each mode: osgsilhouette-deforming-bench
# renders the bunny (69,666 triangles) and a 1M-triangle torus on a ground under one sun, in
# every mode, "still" and "deforming" (an update callback writes a wave into the vertex array
# and dirty()s it) back to back in alternating order, ROUNDS rounds, 512x384, map 1024. Prints
# the table of docs/benchmarks.md's "Deforming casters" (medians over rounds; the deltas'
# range over rounds says how noisy the machine was) and writes docs/bench/deforming.csv
# (every round's rows).
#
#   scripts/bench-deforming.sh                       # build (into $BUILD_DIR, default build-bench) and run
#   ROUNDS=5 scripts/bench-deforming.sh              # rounds (default 3)
#   CASTERS=bunny QUICK=1 scripts/bench-deforming.sh # 5 frames, 1 round (a smoke test, not results)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench-rounds.sh
CASTERS=${CASTERS:-bunny,torus1m}

bench_setup osgsilhouette-deforming-bench
trap 'rm -rf "$TMP"' EXIT
LOAD_BEFORE=$(uptime | sed 's/.*load average: //')
START=$(date +%s)
scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouette-deforming-bench" --casters "$CASTERS" \
  --techniques shadowmap,silhouette,volume,hybrid --size 512 384 --map-size 1024 \
  --frames "$FRAMES" --warmup 3 --rounds "$ROUNDS" --out-dir "$TMP" >"$TMP/table.md"
cp "$TMP/deforming.csv" "$OUT/deforming.csv"
echo "$(($(date +%s) - START)) s; load average before: $LOAD_BEFORE, after: $(uptime | sed 's/.*load average: //')"
echo
cat "$TMP/table.md"
