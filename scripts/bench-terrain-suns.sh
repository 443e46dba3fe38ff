#!/usr/bin/env bash
# The exact modes on a terrain under suns from low to high (docs/outdoor.md, "Suns from 5 to
# 60 degrees"): the "outdoor" scene (1.2 km terrain of 5 m cells, open at its borders, 1500
# trees, 60 buildings) seen from its first walk view at 1024 x 768, the sun turned about the
# same azimuth to each elevation, every mode (map 2048, HYBRID 1024) scored against the exact
# reference on one frame: wrong_pct and the frame time (median of $FRAMES frames; accuracy is
# the point, times are for orientation).
# Writes docs/bench/terrain-suns.csv and rewrites the generated block of docs/outdoor.md.
#
#   scripts/bench-terrain-suns.sh                       # build (into $BUILD_DIR) and run
#   ELEVATIONS="5 60" MODES="hybrid:1024" scripts/bench-terrain-suns.sh   # a subset
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench-rounds.sh
source scripts/replace-block.sh
ELEVATIONS=${ELEVATIONS:-"5 10 20 40 60"}
MODES=${MODES:-"shadowmap:2048 silhouette:2048 hybrid:1024 volume:2048"}
FRAMES=${FRAMES_OVERRIDE:-5}
bench_setup osgsilhouetteshadow
BIN="$BUILD_DIR/bin/osgsilhouetteshadow"
CSV="$OUT/${CSV_NAME:-terrain-suns.csv}"
echo "sun_elevation_deg,technique,map_size,wrong_pixels,wrong_pct,geometry_pixels,frame_ms_median" > "$CSV"

# value KEY FILE: the first KEY=number of FILE.
value() { { grep -o "\b$1=[-0-9.e]*" "$2" || true; } | head -1 | cut -d= -f2; }

for e in $ELEVATIONS; do
  # The scene's own sun azimuth (OutdoorScene.cpp: toward (0.98, -0.2) in the ground plane).
  dir=$(awk -v e="$e" 'BEGIN { r = e * atan2(0, -1) / 180; n = sqrt(0.98 * 0.98 + 0.04);
                               printf "%.9f %.9f %.9f", 0.98 / n * cos(r), -0.2 / n * cos(r), sin(r) }')
  for entry in $MODES; do
    mode=${entry%:*} map=${entry#*:}
    log="$TMP/run.txt"
    # shellcheck disable=SC2086
    "$BIN" --scene outdoor --offscreen --size 1024 768 --mode "$mode" --map-size "$map" --light-dir $dir \
      --frames "$FRAMES" --warmup 2 --reference "$TMP/ref.png" > "$log" 2>&1 || { echo "failed: $mode $e" >&2; cat "$log" >&2; exit 1; }
    echo "$e,$mode,$map,$(value wrong_pixels "$log"),$(value wrong_pct "$log"),$(value geometry_pixels "$log"),$(value frame_ms_median "$log")" | tee -a "$CSV"
  done
done

table=$(awk -F, 'NR > 1 { key = $1; if (!(key in seen)) { order[++n] = key; seen[key] = 1 }
                          cell[key, $2] = sprintf("%s (%d)", $5, $4); modes[$2] = 1 }
  END {
    split("shadowmap silhouette hybrid volume", m, " ")
    printf "| sun elevation | SHADOW_MAP 2048 | SILHOUETTE_MAP 2048 | HYBRID 1024 | SHADOW_VOLUME |\n| --- | --- | --- | --- | --- |\n"
    for (i = 1; i <= n; ++i) {
      printf "| %s deg |", order[i]
      for (j = 1; j <= 4; ++j) printf " %s |", ((order[i], m[j]) in cell) ? cell[order[i], m[j]] : "-"
      printf "\n"
    }
  }' "$CSV")
if [ -z "${CSV_NAME:-}" ]; then
  {
    echo "$table"
    echo
    echo "wrong_pct (wrong pixels) of the first walk view at 1024 x 768, measured $(date -u +%Y-%m-%d) with" \
      "\`scripts/bench-terrain-suns.sh\` ([terrain-suns.csv](bench/terrain-suns.csv))."
  } > "$TMP/block.md"
  replace_block docs/outdoor.md osgsilhouette-terrain-suns "$TMP/block.md"
fi
rm -rf "$TMP"
