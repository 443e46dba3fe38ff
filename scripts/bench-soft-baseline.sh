#!/usr/bin/env bash
# The soft-shadow baseline: how far today's hard modes are from the exact visibility of a
# directional light with a size (MEASURE.md, "Soft shadows"), per scene, mode and angular
# radius, at 512x384. The hard modes answer 0 or 1, so their vis_mae_penumbra is what a soft
# filter has to lower. Writes docs/bench/soft-baseline.csv (MEASURE.md's benchmark columns and
# the soft ones after notes) and rewrites the generated block of docs/benchmarks.md.
#
#   scripts/bench-soft-baseline.sh                 # build (into $BUILD_DIR, default build-bench) and run
#   SCENES="default" SIZES="0 2" scripts/bench-soft-baseline.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/replace-block.sh
source scripts/bench-rounds.sh
SCENES=${SCENES:-"default bunny cubes"}
SIZES=${SIZES:-"0 1 3"} # angular radius of the light, degrees
MODES=${MODES:-"shadowmap:2048 silhouette:1024 hybrid:512 volume:0"}
LIGHT=${LIGHT:-"1 0.6 2"} # toward the light
W=512 H=384

bench_setup osgsilhouetteshadow
CSV="$OUT/soft-baseline.csv"
echo "scene,technique,map_size,width,height,frames,frame_ms_median,gpu_ms_median,geometry_pixels,wrong_pixels,wrong_pct,coverage_mismatch,silhouette_pixel_pct,notes,light_size,filter,vis_mae,vis_mae_penumbra,vis_p99_penumbra,penumbra_pixels" > "$CSV"
value() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" "$2" | head -1; }
for scene in $SCENES; do
  for size in $SIZES; do
    for entry in $MODES; do
      mode=${entry%%:*}
      map=${entry##*:}
      [ "$map" = 0 ] && map=512 # SHADOW_VOLUME has no map
      log="$TMP/$scene-$size-$mode.txt"
      # One frame: the masks are the result; times belong to the other benchmarks.
      scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouetteshadow" --offscreen --scene "$scene" \
        --mode "$mode" --map-size "$map" --light-dir $LIGHT --size $W $H --frames 1 --warmup 1 \
        --reference "$TMP/ref.png" --visibility "$TMP/vis.png" \
        --reference-visibility "$TMP/refvis-$scene-$size.png" --light-size "$size" > "$log"
      echo "$scene,$mode,$map,$W,$H,1,$(value frame_ms_median "$log"),$(value gpu_ms_median "$log"),$(value geometry_pixels "$log"),$(value wrong_pixels "$log"),$(value wrong_pct "$log"),$(value coverage_mismatch "$log"),,light-dir $LIGHT,$size,none,$(value vis_mae "$log"),$(value vis_mae_penumbra "$log"),$(value vis_p99_penumbra "$log"),$(value penumbra_pixels "$log")" >> "$CSV"
      echo "$scene light_size=$size $mode: $(grep vis_mae "$log")"
    done
  done
done
TABLE="$TMP/table.md"
{
  echo "| scene | light size (deg) | mode | map | vis_mae | vis_mae_penumbra | vis_p99_penumbra | penumbra pixels | wrong_pct (hard reference) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$CSV" | awk -F, '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $15, $2, ($2 == "volume" ? "-" : $3), $17, $18, $19, $20, $11 }'
  echo
  echo "Measured $(date -u +%Y-%m-%d) with \`scripts/bench-soft-baseline.sh\` ($W x $H, light toward ($LIGHT))."
} > "$TABLE"
replace_block docs/benchmarks.md soft-baseline "$TABLE"
echo "wrote $CSV and the soft-baseline block of docs/benchmarks.md"
