#!/bin/bash
# Writes the README's table of properties from the technique's table of properties
# (osgShadowSilhouette/Properties), between its markers. Run after changing a row; the test
# cpu_properties fails while the two differ.
#   scripts/update-properties-table.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target cpu_properties >/dev/null
OSS_SOURCE_DIR=$PWD OSS_UPDATE_PROPERTIES_TABLE=1 "$build/bin/cpu_properties" \
    --gtest_filter='Properties.TheReadmeTableIsTheTables' >/dev/null
git diff --stat -- README.md
