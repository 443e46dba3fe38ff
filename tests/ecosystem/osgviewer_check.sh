#!/usr/bin/env bash
# Runs the stock osgviewer headless on a scene file, as the README shows, and checks that the
# technique was active: the file is opened through the .silhouette pseudo-loader, whose
# Report= option writes the technique's statistics of every frame. A plain run of the file
# (without the pseudo-loader) must load the technique too: osgviewer must not report a
# missing wrapper. Either run fails on a GLSL compile or link error: the statistics count
# passes, not pixels, so a broken program must not pass unseen.
# Usage: osgviewer_check.sh <OSG_LIBRARY_PATH> <scene file> <work dir>
set -euo pipefail
LIBS=$1 FILE=$2 WORK=$3
mkdir -p "$WORK"
export OSG_LIBRARY_PATH=$LIBS OSG_RUN_FRAME_COUNT=5 OSG_NOTIFY_LEVEL=NOTICE
REPORT=$WORK/$(basename "$FILE").report

check_log() {
  if echo "$1" | grep -qi "unsupported wrapper\|could not find wrapper\|no data loaded"; then
    echo "$1"; echo "osgviewer did not load $FILE with its technique"; exit 1
  fi
  if echo "$1" | grep -q "glCompileShader.*FAILED\|glLinkProgram.*FAILED"; then
    echo "$1"; echo "a shader of the technique failed"; exit 1
  fi
}

LOG=$(osgviewer --stencil --window 0 0 640 480 "$FILE" 2>&1) || { echo "$LOG"; exit 1; }
check_log "$LOG"

rm -f "$REPORT"
LOG=$(osgviewer --stencil --window 0 0 640 480 "$FILE.silhouette" -O "Report=$REPORT" 2>&1) || { echo "$LOG"; exit 1; }
check_log "$LOG"
[ -s "$REPORT" ] || { echo "no statistics written"; exit 1; }
LAST=$(tail -n 1 "$REPORT")
echo "last frame: $LAST"
echo "$LAST" | grep -q "lightsShadowed=[1-9]" || { echo "no light shadowed"; exit 1; }
echo "$LAST" | grep -q "shadowPasses=[1-9]" || { echo "no shadow pass"; exit 1; }
