#!/usr/bin/env bash
# Installs the dependencies, builds, and runs the whole test suite: CPU tests and GL tests
# (under a virtual display when there is none). Extra arguments go to ctest, e.g. -L cpu.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
export OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-WARN}
scripts/with-display.sh ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j 2 "$@"
