#!/usr/bin/env bash
# The soft filters' frame times side by side: SHADOW_MAP's 2x2 PCF and PCSS, SILHOUETTE_MAP
# hard and under FILTER_SILHOUETTE (at map $MAP), HYBRID hard (size 0) and with its shadow
# rays (map 512, SoftSamples 64), per scene at one light size, in interleaved
# rounds (every technique once per round, so that a shared machine's load falls on all of
# them), without the exact reference. The median over the rounds of each run's median frame
# time, and its ratio to the 2x2 PCF's and to PCSS's, go to the generated block soft-time of
# docs/benchmarks.md (or $OUT/soft-time.md when OUT is not docs/bench).
#
#   scripts/bench-soft-time.sh
#   SCENES="default tree" MAP=1024 ROUNDS=5 scripts/bench-soft-time.sh
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/replace-block.sh
source scripts/bench-rounds.sh
SCENES=${SCENES:-"default cubes tree bunny poles"}
MAP=${MAP:-2048}
SIZE=${SIZE:-3} # the sun's angular radius, degrees
SUN=${SUN:-"1 0.6 2"}
# mode:filter[:light size, default $SIZE]
ENTRIES="shadowmap:pcf2x2 shadowmap:pcss silhouette:none silhouette:silhouette hybrid:none:0 hybrid:none"
W=512 H=384

bench_setup osgsilhouetteshadow
for round in $(seq "$ROUNDS"); do
  for scene in $SCENES; do
    for entry in $ENTRIES; do
      IFS=: read -r mode filter size <<< "$entry"
      filterarg=()
      [ "$filter" = none ] || filterarg=(--filter "$filter")
      map=$MAP
      [ "$mode" = hybrid ] && map=512
      scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouetteshadow" --offscreen --scene "$scene" --mode "$mode" \
        "${filterarg[@]}" --map-size "$map" --light-dir $SUN --light-size "${size:-$SIZE}" --size $W $H \
        --frames "$FRAMES" --warmup 3 | sed -n "s/^frame_ms_median=/$scene $entry /p" >> "$TMP/times.txt"
    done
  done
  echo "round $round of $ROUNDS done"
done

TABLE="$TMP/table.md"
{
  echo "| scene | SHADOW_MAP 2x2 PCF ms | PCSS ms | SILHOUETTE_MAP ms | FILTER_SILHOUETTE ms | FILTER_SILHOUETTE / 2x2 PCF (goal <= 2) | FILTER_SILHOUETTE / PCSS (goal <= 1) | HYBRID hard ms | HYBRID 64 rays ms | rays / hard (goal <= 3) |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
  awk -v scenes="$SCENES" '
    { key = $1 " " $2; t[key, ++n[key]] = $3 }
    function median(key,   k, i, j, v, tmp) {
      k = n[key]; for (i = 1; i <= k; ++i) v[i] = t[key, i]
      for (i = 1; i <= k; ++i) for (j = i + 1; j <= k; ++j) if (v[j] < v[i]) { tmp = v[i]; v[i] = v[j]; v[j] = tmp }
      return k % 2 ? v[(k + 1) / 2] : (v[k / 2] + v[k / 2 + 1]) / 2
    }
    END {
      split(scenes, s, " ")
      for (i = 1; s[i] != ""; ++i) {
        pcf = median(s[i] " shadowmap:pcf2x2"); pcss = median(s[i] " shadowmap:pcss")
        sil = median(s[i] " silhouette:none"); fil = median(s[i] " silhouette:silhouette")
        hh = median(s[i] " hybrid:none:0"); hs = median(s[i] " hybrid:none")
        printf "| %s | %.1f | %.1f | %.1f | %.1f | %.2f | %.2f | %.1f | %.1f | %.2f |\n", s[i], pcf, pcss, sil, fil, fil / pcf, fil / pcss, hh, hs, hs / hh
      }
    }' "$TMP/times.txt"
  echo
  echo "Measured $(date -u +%Y-%m-%d) with \`scripts/bench-soft-time.sh\` ($W x $H, a sun of $SIZE degrees toward ($SUN), map $MAP (HYBRID 512), median of $ROUNDS interleaved rounds of $FRAMES-frame medians)."
} > "$TABLE"
if [ "$OUT" = docs/bench ]; then
  replace_block docs/benchmarks.md soft-time "$TABLE"
  echo "wrote the soft-time block of docs/benchmarks.md"
else
  replace_block "$OUT/soft-time.md" soft-time "$TABLE"
  echo "wrote $OUT/soft-time.md"
fi
