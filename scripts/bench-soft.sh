#!/usr/bin/env bash
# The soft-shadow benchmark: every mode, SHADOW_MAP under each of its filters (property Filter)
# and SILHOUETTE_MAP under FILTER_SILHOUETTE,
# against the exact visibility of a directional light with a size (MEASURE.md, "Soft
# shadows"), per scene and angular radius, at 512x384, with the frame time of each run. The
# hard modes answer 0 or 1, so their vis_mae_penumbra is what a soft filter has to lower.
# Writes docs/bench/soft.csv (MEASURE.md's benchmark columns and the soft ones after notes)
# and rewrites the generated block of docs/benchmarks.md.
#
#   scripts/bench-soft.sh                 # build (into $BUILD_DIR, default build-bench) and run
#   SCENES="default" SIZES="0 2" FRAMES=5 scripts/bench-soft.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/replace-block.sh
source scripts/bench-rounds.sh
SCENES=${SCENES:-"default bunny cubes"}
SIZES=${SIZES:-"0 1 3"} # angular radius of the light, degrees
# mode:map size[:filter[:FilterWindow]]
MODES=${MODES:-"shadowmap:2048 shadowmap:2048:pcf:5 shadowmap:2048:pcss silhouette:1024 silhouette:1024:silhouette silhouette:2048:silhouette hybrid:512 volume:0"}
FRAMES=${FRAMES:-10}
LIGHT=${LIGHT:-"1 0.6 2"} # toward the light
W=512 H=384

bench_setup osgsilhouetteshadow
CSV="$OUT/soft.csv"
echo "scene,technique,map_size,width,height,frames,frame_ms_median,gpu_ms_median,geometry_pixels,wrong_pixels,wrong_pct,coverage_mismatch,silhouette_pixel_pct,notes,light_size,filter,vis_mae,vis_mae_penumbra,vis_p99_penumbra,penumbra_pixels" > "$CSV"
value() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" "$2" | head -1; }
for scene in $SCENES; do
  for size in $SIZES; do
    for entry in $MODES; do
      IFS=: read -r mode map filter window <<< "$entry"
      [ "$map" = 0 ] && map=512 # SHADOW_VOLUME has no map
      filter=${filter:-pcf2x2}
      # SHADOW_MAP's filters, and SILHOUETTE_MAP's own; the other modes render hard.
      [ "$mode" = shadowmap ] || { [ "$mode" = silhouette ] && [ "$filter" = silhouette ]; } || filter=none
      label=$filter
      [ -n "$window" ] && label="$filter$window"
      log="$TMP/$scene-$size-$mode-$label.txt"
      scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouetteshadow" --offscreen --scene "$scene" \
        --mode "$mode" --map-size "$map" --light-dir $LIGHT --size $W $H --frames "$FRAMES" --warmup 3 \
        ${filter:+$([ "$filter" != none ] && echo --filter "$filter")} ${window:+--filter-window "$window"} \
        --reference "$TMP/ref.png" --visibility "$TMP/vis.png" \
        --reference-visibility "$TMP/refvis-$scene-$size.png" --light-size "$size" > "$log"
      echo "$scene,$mode,$map,$W,$H,$FRAMES,$(value frame_ms_median "$log"),$(value gpu_ms_median "$log"),$(value geometry_pixels "$log"),$(value wrong_pixels "$log"),$(value wrong_pct "$log"),$(value coverage_mismatch "$log"),,light-dir $LIGHT,$size,$label,$(value vis_mae "$log"),$(value vis_mae_penumbra "$log"),$(value vis_p99_penumbra "$log"),$(value penumbra_pixels "$log")" >> "$CSV"
      echo "$scene light_size=$size $mode $label: $(grep vis_mae "$log") $(grep frame_ms "$log")"
    done
  done
done
TABLE="$TMP/table.md"
{
  echo "| scene | light size (deg) | mode | filter | map | vis_mae | vis_mae_penumbra | vis_p99_penumbra | penumbra pixels | wrong_pct (hard mask, hard reference) | frame ms |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$CSV" | awk -F, '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $15, $2, $16, ($2 == "volume" ? "-" : $3), $17, $18, $19, $20, $11, $7 }'
  echo
  echo "Measured $(date -u +%Y-%m-%d) with \`scripts/bench-soft.sh\` ($W x $H, light toward ($LIGHT), median of $FRAMES frames on a shared machine: compare frame times within a scene)."
} > "$TABLE"
replace_block docs/benchmarks.md soft "$TABLE"
echo "wrote $CSV and the soft block of docs/benchmarks.md"
