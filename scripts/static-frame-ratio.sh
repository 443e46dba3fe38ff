#!/bin/sh
# Static-frame cost of each mode: the median frame time of a frame in which nothing moved
# (after warm-up), divided by the median frame time of the same frame rendered without any
# shadow technique (--mode none); and the frame time when light 0 turns by +-0.1 degree
# every frame (--moving-light: no depth, silhouette or list pass can be reused, extraction
# runs), which shows what the static-frame reuse saves. One run, modes interleaved per scene.
#
#   scripts/with-display.sh scripts/static-frame-ratio.sh [BUILD_DIR] [SCENES...]
#
# Defaults: build-sil, scenes "default cubes"; 1024x768, map 2048 (the renderer's default),
# 5 warm-up frames, 30 timed frames. Prints one line per scene and mode:
#   scene=default mode=shadowmap frame_ms_median=... none_ms_median=... ratio=... moving_ms_median=...
set -eu
BUILD=${1:-build-sil}
[ $# -gt 0 ] && shift
SCENES=${*:-"default cubes"}
RENDERER="$BUILD/bin/osgsilhouetteshadow"
[ -x "$RENDERER" ] || { echo "no $RENDERER (build the osgsilhouetteshadow target)" >&2; exit 1; }
WARMUP=${WARMUP:-5}
FRAMES=${FRAMES:-30}

median_ms() # scene mode [renderer options]
{
    _scene=$1 _mode=$2
    shift 2
    "$RENDERER" --scene "$_scene" --mode "$_mode" --offscreen --size 1024 768 --warmup "$WARMUP" --frames "$FRAMES" "$@" |
        sed -n 's/^frame_ms_median=//p'
}

for scene in $SCENES; do
    none=$(median_ms "$scene" none)
    for mode in shadowmap silhouette hybrid volume; do
        ms=$(median_ms "$scene" "$mode")
        moving=$(median_ms "$scene" "$mode" --moving-light)
        awk -v s="$scene" -v m="$mode" -v t="$ms" -v n="$none" -v v="$moving" \
            'BEGIN { printf "scene=%s mode=%s frame_ms_median=%.2f none_ms_median=%.2f ratio=%.2f moving_ms_median=%.2f\n", s, m, t, n, t / n, v }'
    done
done
