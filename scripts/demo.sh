#!/usr/bin/env bash
# Set-up and first look: installs the dependencies, builds, renders the default scene in
# every available mode at two map sizes, and prints mode, map size, frame time and the
# share of wrong pixels against the exact ray-cast reference.
# Images go to out/demo/: <mode>_<size>.png (colour), _mask.png, _diff.png, reference.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
OUT=out/demo
mkdir -p "$OUT"
BIN=build/bin/osgsilhouetteshadow
RUN="scripts/with-display.sh"
export OSG_LIBRARY_PATH=$PWD/build/lib OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-WARN}

$RUN "$BIN" --offscreen --mode none --frames 1 --warmup 0 --reference "$OUT/reference.png" >/dev/null
printf '%-12s %8s %10s %10s %9s\n' mode map_size frame_ms gpu_ms wrong_%
for mode in $($BIN --list-modes); do
  for size in 1024 2048; do
    log=$($RUN "$BIN" --offscreen --mode "$mode" --map-size "$size" \
          --out "$OUT/${mode}_${size}.png" --mask "$OUT/${mode}_${size}_mask.png" \
          --compare "$OUT/reference.png" --diff "$OUT/${mode}_${size}_diff.png")
    value() { echo "$log" | tr ' ' '\n' | sed -n "s/^$1=//p" | head -n 1; }
    printf '%-12s %8s %10s %10s %9s\n' "$mode" "$size" "$(value frame_ms_median)" "$(value gpu_ms_median)" "$(value wrong_pct)"
  done
done
echo "images: $OUT/"
