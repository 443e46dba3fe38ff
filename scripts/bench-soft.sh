#!/usr/bin/env bash
# The soft-shadow benchmark: every mode, SHADOW_MAP under each of its filters (property Filter),
# SILHOUETTE_MAP hard and under FILTER_SILHOUETTE, and osgShadow's SoftShadowMap, against the
# exact visibility (MEASURE.md, "Soft shadows") of a directional light (angular radius in
# degrees) and of a point light (radius in scene units), per scene, light size and map size,
# at 512x384, with the frame time of each run. The hard modes answer 0 or 1, so their
# vis_mae_penumbra is what a soft filter has to lower. The exact visibility is cast once per
# scene, light and size (--reference-visibility) and read back by the other runs
# (--compare-visibility).
# Writes docs/bench/soft.csv (MEASURE.md's benchmark columns and the soft ones after notes;
# notes names the light), a plot per scene and light of frame time against vis_mae_penumbra at
# the largest size (docs/bench/soft-<scene>-<light>.png, with gnuplot), and rewrites the
# generated blocks of docs/benchmarks.md (soft, soft-goals) and README.md (soft-headline).
#
#   scripts/bench-soft.sh                          # 5 scenes, maps 1024 and 2048 (about 25 min)
#   MAPS="512 1024 2048 4096" scripts/bench-soft.sh # the full map-size sweep
#   SCENES="default" LIGHTS=sun SUN_SIZES="0 2" MAPS=2048 OUT=/tmp/soft scripts/bench-soft.sh
#   MAPPED="" UNMAPPED="hybrid:512" REF_DIR=/tmp/tmp.X OUT=/tmp/hybrid scripts/bench-soft.sh
#   MAPPED="" UNMAPPED="hybrid:512 hybrid:512:256" SUN_SIZES="1 3" POINT_SIZES="0.1 0.3" OUT=/tmp/rays \
#     scripts/bench-soft.sh   (HYBRID's shadow rays at 64 and 256 per penumbra pixel)
#     (OUT other than docs/bench: a subset; the tables go to $OUT/soft.md, docs stay alone)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/replace-block.sh
source scripts/bench-rounds.sh
SCENES=${SCENES:-"default cubes tree bunny poles"}
LIGHTS=${LIGHTS:-"sun point"}
SUN_SIZES=${SUN_SIZES:-"0 1 3"}       # angular radius, degrees
POINT_SIZES=${POINT_SIZES:-"0 0.1 0.3"} # radius, scene units
MAPS=${MAPS:-"1024 2048"}
# technique[:filter[:FilterWindow]], each at every map size; hybrid and volume once, as
# mode:map[:SoftSamples] (hybrid:512:256: 256 shadow rays per penumbra pixel, filter column
# "rays256"; without it, the default 64 and "none").
# SoftShadowMap: osgShadow's, at its default softness (it has no light size).
MAPPED=${MAPPED-"shadowmap:pcf2x2 shadowmap:pcf:5 shadowmap:pcss silhouette:none silhouette:silhouette SoftShadowMap"}
UNMAPPED=${UNMAPPED-"hybrid:512 volume:512"}
FRAMES=${FRAMES:-20}
REF_DIR=${REF_DIR:-} # exact visibilities of an earlier run (its refvis-*.png) to read instead of casting
SUN=${SUN:-"1 0.6 2"} # toward the sun
W=512 H=384

# A point light above and beside each scene's casters (its ground is at z = 0).
point_position() {
  case $1 in
  cubes) echo "-4 -7 17" ;;
  tree) echo "-3 -4 10" ;;
  bunny) echo "-2 -3 7" ;;
  poles) echo "2 -4 8" ;;
  *) echo "-3 -4 9" ;;
  esac
}

bench_setup osgsilhouetteshadow
CSV="$OUT/soft.csv"
echo "scene,technique,map_size,width,height,frames,frame_ms_median,gpu_ms_median,geometry_pixels,wrong_pixels,wrong_pct,coverage_mismatch,silhouette_pixel_pct,notes,light_size,filter,vis_mae,vis_mae_penumbra,vis_p99_penumbra,penumbra_pixels" > "$CSV"
value() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" "$2" | head -1; }

# run SCENE LIGHT SIZE MODE MAP FILTER WINDOW: one render scored against the exact visibility.
run() {
  local scene=$1 light=$2 size=$3 mode=$4 map=$5 filter=$6 window=$7 place label log ref
  if [ "$light" = sun ]; then place="--light-dir $SUN"; else place="--light-pos $(point_position "$scene")"; fi
  label=$filter
  [ -n "$window" ] && label="$filter$window"
  log="$TMP/run.txt"
  ref="${REF_DIR:-$TMP}/refvis-$scene-$light-$size.png"
  local refarg=(--compare-visibility "$ref")
  [ -f "$ref" ] || refarg=(--reference-visibility "$ref")
  # SHADOW_MAP's filters and SILHOUETTE_MAP's own; the other modes and the peer render as they are.
  local filterarg=()
  case $mode:$filter in shadowmap:* | silhouette:silhouette) filterarg=(--filter "$filter") ;; esac
  # HYBRID's shadow rays per penumbra pixel (SoftSamples) ride in the window field.
  if [ "$mode" = hybrid ] && [ -n "$window" ]; then
    filterarg=(--soft-samples "$window")
    label="rays$window" window=""
  fi
  scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouetteshadow" --offscreen --scene "$scene" \
    --mode "$mode" --map-size "$map" $place --size $W $H --frames "$FRAMES" --warmup 3 \
    "${filterarg[@]}" ${window:+--filter-window "$window"} --light-size "$size" \
    --reference "$TMP/ref.png" --visibility "$TMP/vis.png" "${refarg[@]}" > "$log" || true
  local technique=$mode mapcol=$map
  [ "$mode" = volume ] && mapcol=0
  echo "$scene,$technique,$mapcol,$W,$H,$FRAMES,$(value frame_ms_median "$log"),$(value gpu_ms_median "$log"),$(value geometry_pixels "$log"),$(value wrong_pixels "$log"),$(value wrong_pct "$log"),$(value coverage_mismatch "$log"),,$light ${place#--},$size,$label,$(value vis_mae "$log"),$(value vis_mae_penumbra "$log"),$(value vis_p99_penumbra "$log"),$(value penumbra_pixels "$log")" >> "$CSV"
  echo "$scene $light size=$size $mode $label $map: $(grep vis_mae "$log" || echo 'no score') $(grep frame_ms "$log")"
}

for scene in $SCENES; do
  for light in $LIGHTS; do
    sizes=$SUN_SIZES
    [ "$light" = point ] && sizes=$POINT_SIZES
    for size in $sizes; do
      for entry in $UNMAPPED; do
        IFS=: read -r mode map samples <<< "$entry"
        run "$scene" "$light" "$size" "$mode" "$map" none "${samples:-}"
      done
      for map in $MAPS; do
        for entry in $MAPPED; do
          IFS=: read -r mode filter window <<< "$entry"
          [ "$mode" = SoftShadowMap ] && mode=osgShadow:SoftShadowMap
          run "$scene" "$light" "$size" "$mode" "$map" "${filter:-none}" "${window:-}"
        done
      done
    done
  done
done

how="$W x $H, sun toward ($SUN), median of $FRAMES frames, $(date -u +%Y-%m-%d)"
if [ "$OUT" = docs/bench ]; then
  python3 scripts/soft-report.py "$CSV" "$OUT" "$how"
  echo "wrote $CSV, the soft plots and the soft blocks of docs/benchmarks.md and README.md"
else
  python3 scripts/soft-report.py "$CSV" "$OUT" "$how" --no-docs
  echo "wrote $CSV, the soft plots and $OUT/soft.md"
fi
