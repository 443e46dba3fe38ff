#!/bin/sh
# Static-frame cost of each mode: the median frame time of a frame in which nothing moved
# (after warm-up), divided by the median frame time of the same frame rendered without any
# shadow technique (--mode none). One run, the same machine, modes interleaved per scene.
#
#   scripts/with-display.sh scripts/static-frame-ratio.sh [BUILD_DIR] [SCENES...]
#
# Defaults: build-sil, scenes "default cubes"; 1024x768, map 2048 (the renderer's default),
# 5 warm-up frames, 30 timed frames. Prints one line per scene and mode:
#   scene=default mode=shadowmap frame_ms_median=... none_ms_median=... ratio=...
set -eu
BUILD=${1:-build-sil}
[ $# -gt 0 ] && shift
SCENES=${*:-"default cubes"}
RENDERER="$BUILD/bin/osgsilhouetteshadow"
[ -x "$RENDERER" ] || { echo "no $RENDERER (build the osgsilhouetteshadow target)" >&2; exit 1; }
WARMUP=${WARMUP:-5}
FRAMES=${FRAMES:-30}

median_ms() # scene mode
{
    "$RENDERER" --scene "$1" --mode "$2" --offscreen --size 1024 768 --warmup "$WARMUP" --frames "$FRAMES" |
        sed -n 's/^frame_ms_median=//p'
}

for scene in $SCENES; do
    none=$(median_ms "$scene" none)
    for mode in shadowmap silhouette hybrid volume; do
        ms=$(median_ms "$scene" "$mode")
        awk -v s="$scene" -v m="$mode" -v t="$ms" -v n="$none" \
            'BEGIN { printf "scene=%s mode=%s frame_ms_median=%.2f none_ms_median=%.2f ratio=%.2f\n", s, m, t, n, t / n }'
    done
done
