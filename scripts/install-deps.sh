#!/usr/bin/env bash
# Installs everything osgShadowSilhouette needs on Debian 12 (bookworm), from Debian's
# packages only. Safe to run again: apt-get skips what is installed.
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
PACKAGES=(
  build-essential cmake git ca-certificates pkg-config
  libopenscenegraph-dev openscenegraph      # OSG 3.6.5, osgviewer, osgconv
  libopenmesh-dev libglm-dev                 # half-edge meshes, math
  libembree-dev                              # exact reference (tests and benchmark)
  libgtest-dev libbenchmark-dev              # tests, benchmarks
  libgl1-mesa-dri libgl-dev xvfb xauth x11-utils  # OpenGL (llvmpipe without a GPU), virtual display
  glmark2-data                               # bunny.obj: a real scanned mesh for benchmarks
  assimp-testmodels                          # the real-world corpus (scripts/corpus.sh, ctest -L corpus)
  gnuplot-nox python3                        # benchmark plots and reports
  clang libclang-rt-dev                      # fuzz targets: clang with libFuzzer, ASan, UBSan runtimes
)
# Strip the comments above into a clean list.
LIST=$(printf '%s\n' "${PACKAGES[@]}" | sed 's/#.*//' | tr -s ' \n' ' ')
export DEBIAN_FRONTEND=noninteractive
if ! dpkg -s $LIST >/dev/null 2>&1; then
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq $LIST >/dev/null
fi
# Without its recommends (Qt): libcgal-demo ships the elephant mesh of the lights benchmark.
if ! dpkg -s libcgal-demo >/dev/null 2>&1; then
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends libcgal-demo >/dev/null
fi
echo "dependencies: installed"
