#!/usr/bin/env bash
# Runs a command with an X display: the current one if it works, else a virtual one (Xvfb).
set -euo pipefail
if [ -n "${DISPLAY:-}" ] && command -v xdpyinfo >/dev/null 2>&1 && xdpyinfo >/dev/null 2>&1; then
  exec "$@"
fi
# -noreset: Xvfb otherwise resets when its last client disconnects, and a test that
# connects during that reset cannot open the display.
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
