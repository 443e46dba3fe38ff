#!/usr/bin/env bash
# Installs the build tree into a fresh prefix, checks the installed layout, builds the
# consumer project against it with find_package(osgShadowSilhouette) and runs it with only
# the prefix on OSG_LIBRARY_PATH (so the installed plugins are the ones used).
# Usage: install_and_consume.sh <build dir> <source dir> <work dir>
set -euo pipefail
BUILD=$1 SOURCE=$2 WORK=$3
PREFIX=$WORK/prefix
rm -rf "$WORK" && mkdir -p "$WORK"
cmake --install "$BUILD" --prefix "$PREFIX" >/dev/null
LIBDIR=$(ls -d "$PREFIX"/lib*/libosgShadowSilhouette.so | xargs dirname)
for f in include/osgShadowSilhouette/SilhouetteShadowTechnique \
         "${LIBDIR#$PREFIX/}/osgPlugins-3.6.5/osgdb_serializers_osgshadowsilhouette.so" \
         "${LIBDIR#$PREFIX/}/osgPlugins-3.6.5/osgdb_silhouette.so" bin/osgsilhouetteshadow \
         "${LIBDIR#$PREFIX/}/cmake/osgShadowSilhouette/osgShadowSilhouetteConfig.cmake" \
         "${LIBDIR#$PREFIX/}/cmake/osgShadowSilhouette/osgShadowSilhouetteTargets.cmake"; do
  [ -e "$PREFIX/$f" ] || { echo "missing after install: $f"; exit 1; }
done
if grep -q "$BUILD\|$SOURCE" "$LIBDIR"/cmake/osgShadowSilhouette/*.cmake; then
  echo "the installed package refers to the build or source tree"; exit 1
fi
cmake -S "$SOURCE/tests/ecosystem/consumer" -B "$WORK/consumer" -DCMAKE_PREFIX_PATH="$PREFIX" >/dev/null
cmake --build "$WORK/consumer" >/dev/null
unset LD_LIBRARY_PATH
export OSG_LIBRARY_PATH=$LIBDIR
"$WORK/consumer/consumer" --save "$WORK/saved.osgt"
# The installed renderer starts with nothing but its own RUNPATH to find the nodekit.
MODES=$("$PREFIX/bin/osgsilhouetteshadow" --list-modes)
[ "$(echo "$MODES" | wc -l)" -eq 4 ] || { echo "installed renderer: unexpected --list-modes output: $MODES"; exit 1; }
echo "installed into $PREFIX; consumer built and run"
