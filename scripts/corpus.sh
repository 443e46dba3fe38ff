#!/usr/bin/env bash
# The real-world corpus run (docs/corpus.md): every model of Debian's assimp-testmodels that
# OSG 3.6.5's own plugins read, put on a ground (--ground), lit by a directional and a point
# light at once, rendered in every mode and scored per light against the exact reference.
#
#   scripts/corpus.sh                  # the whole corpus: writes tests/corpus/manifest.txt,
#                                      # docs/bench/corpus.csv and the corpus table of
#                                      # docs/benchmarks.md
#   scripts/corpus.sh --models 5       # the first 5 loadable models only       } subsets:
#   scripts/corpus.sh --only 'OBJ/'    # models whose path matches the regex     } results go
#   scripts/corpus.sh --dir /some/dir  # the models of another directory         } to $OUT only
#   FRAMES=1 WARMUP=1 scripts/corpus.sh --models 3   # accuracy only (frame times meaningless)
#   scripts/corpus.sh --probe-only     # the manifest alone (tests/corpus/manifest.txt), in ~1 min
#
# Each model is probed first in a subprocess with a time limit (osgsilhouette-corpus-probe),
# so a plugin that crashes or hangs is reported in the manifest instead of ending the run.
# Each renderer run scores its masks against the exact reference (--reference; see render()
# for why the reference is not read back from its PNG).
set -euo pipefail
cd "$(dirname "$0")/.."
# One display (Xvfb when there is none) for the whole run, not one per renderer run.
if [ -z "${CORPUS_DISPLAY:-}" ]; then CORPUS_DISPLAY=1 exec scripts/with-display.sh "$0" "$@"; fi
BUILD_DIR=${BUILD_DIR:-build}
FRAMES=${FRAMES:-20}
WARMUP=${WARMUP:-3}
SIZE=(512 384)
DIR=/usr/share/assimp/models
LIGHTS=(--light-dir 0.5 -0.6 0.6 --light-pos -3 -4 9)
# mode:map size
MODES=(shadowmap:2048 silhouette:2048 hybrid:1024 volume:2048)
MODELS=0 ONLY="" SUBSET=0 PROBE_ONLY=0
while [ $# -gt 0 ]; do
  case $1 in
    --probe-only) PROBE_ONLY=1; shift ;;
    --models) MODELS=$2 SUBSET=1; shift 2 ;;
    --only) ONLY=$2 SUBSET=1; shift 2 ;;
    --dir) DIR=$2 SUBSET=1; shift 2 ;;
    *) echo "corpus.sh: unknown option $1" >&2; exit 1 ;;
  esac
done
OUT=${OUT:-$BUILD_DIR/corpus}
if [ ! -d "$DIR" ]; then
  echo "corpus.sh: $DIR is missing (Debian: apt-get install assimp-testmodels)" >&2
  exit 1
fi

if [ -z "${NO_BUILD:-}" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo} >/dev/null
  cmake --build "$BUILD_DIR" -j "${JOBS:-2}" --target osgsilhouetteshadow osgsilhouette-corpus-probe >/dev/null
fi
BIN=$PWD/$BUILD_DIR/bin
export OSG_LIBRARY_PATH="$PWD/$BUILD_DIR/lib"
export OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-WARN}
mkdir -p "$OUT/logs" "$OUT/img"

# Files that only accompany a model (textures, buffers, materials, shaders, notes).
is_companion() {
  case "${1,,}" in
    *.png|*.jpg|*.jpeg|*.tga|*.bmp|*.dds|*.bin|*.txt|*.md|*.mtl|*.material|*.glsl|*.vert|*.frag) return 0 ;;
    */readme|*/license) return 0 ;;
  esac
  return 1
}

# probe FILE: prints "status<TAB>reason-or-statistics" (the probe's key=value line).
probe() {
  local line rc=0
  line=$(timeout 60 "$BIN/osgsilhouette-corpus-probe" "$1" 2>/dev/null | tail -1) || rc=$?
  case $rc in
    0|2|3|4) printf '%s\n' "$line" ;;
    124) echo 'status=timeout reason="loading took over 60 s"' ;;
    *) if [ $rc -gt 128 ]; then echo "status=crash reason=\"the plugin crashed (signal $((rc - 128)))\""
       else echo "status=error reason=\"probe exit status $rc\""; fi ;;
  esac
}

field() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<<"$2" | head -1; }
reason() { sed -n 's/.*reason="\([^"]*\)".*/\1/p' <<<"$1"; }

# render REL FILE MODE MAP_SIZE FIRST: one renderer run; the first run writes the references.
render() {
  local rel=$1 file=$2 mode=$3 size=$4 first=$5 tag log refopt
  tag=$(tr '/ ' '__' <<<"$rel")
  log="$OUT/logs/$tag.$mode.log"
  # The first run ray casts the references; the others read them back. A reference read
  # from its PNG has lost its grazing band, which the comparison leaves out, so every mode
  # is scored against a reference computed in its own run (cheap at this size): the PNG of
  # the first run is kept for inspection only, unless REUSE_REFERENCE=1.
  if [ "$first" = 1 ] || [ -z "${REUSE_REFERENCE:-}" ]; then refopt=(--reference "$OUT/img/$tag.ref.png")
  else refopt=(--compare "$OUT/img/$tag.ref.png"); fi
  local rc=0
  timeout 600 "$BIN/osgsilhouetteshadow" "$file" --ground --offscreen --size "${SIZE[@]}" \
    "${LIGHTS[@]}" --mode "$mode" --map-size "$size" --frames "$FRAMES" --warmup "$WARMUP" \
    --mask "$OUT/img/$tag.$mode.png" --diff "$OUT/img/$tag.$mode.diff.png" "${refopt[@]}" >"$log" 2>&1 || rc=$?
  echo "$rc"
}

CSV_HEADER=model,format,triangles,parts,open_edges,nonmanifold_edges,flipped_edges,textured,light,mode,map_size,width,height,frames,frame_ms_median,geometry_pixels,wrong_pixels,wrong_pct,coverage_mismatch,gl_errors,status
CSV="$OUT/corpus.csv"
MANIFEST="$OUT/manifest.txt"
echo "$CSV_HEADER" >"$CSV"
{
  echo "# The corpus: every file of $DIR that is not a texture, buffer, material or note,"
  echo "# one a line: path (relative to that directory), then the probe's verdict."
  echo "# Written by scripts/corpus.sh; models with status=ok are rendered."
} >"$MANIFEST"

# measure REL FILE STATS: renders every mode and appends the CSV rows of both lights.
measure() {
  local rel=$1 file=$2 stats=$3 first=1 entry mode size rc log light line
  local common
  common="$rel,${rel##*.},$(field triangles "$stats"),$(field parts "$stats"),$(field open_edges "$stats"),$(field nonmanifold_edges "$stats"),$(field flipped_edges "$stats"),$(field textured "$stats")"
  for entry in "${MODES[@]}"; do
    mode=${entry%%:*} size=${entry##*:}
    rc=$(render "$rel" "$file" "$mode" "$size" $first)
    first=0
    log="$OUT/logs/$(tr '/ ' '__' <<<"$rel").$mode.log"
    local ms gl
    ms=$(sed -n 's/^frame_ms_median=//p' "$log" | head -1)
    gl=$(sed -n 's/^gl_errors=//p' "$log" | head -1)
    for light in 0 1; do
      line=$(grep "^light=$light geometry_pixels=" "$log" | head -1 || true)
      local status=ok
      [ "$rc" = 0 ] || status="exit_$rc"
      [ -n "$line" ] || { [ "$status" = ok ] && status=no_mask; }
      echo "$common,$([ $light = 0 ] && echo directional || echo point),$mode,$size,${SIZE[0]},${SIZE[1]},$FRAMES,$ms,$(field geometry_pixels "$line"),$(field wrong_pixels "$line"),$(field wrong_pct "$line"),$(field coverage_mismatch "$line"),$gl,$status" >>"$CSV"
    done
  done
}

START=$(date +%s)
LOAD_BEFORE=$(uptime | sed 's/.*load average: //')
rendered=0
while IFS= read -r file; do
  rel=${file#"$DIR"/}
  is_companion "$rel" && continue
  [ -n "$ONLY" ] && ! grep -Eq -- "$ONLY" <<<"$rel" && continue
  result=$(probe "$file")
  status=$(field status "$result")
  if [ "$status" = ok ]; then
    printf '%s\t%s\n' "$rel" "${result}" >>"$MANIFEST"
    if [ "$PROBE_ONLY" = 0 ] && { [ "$MODELS" = 0 ] || [ $rendered -lt "$MODELS" ]; }; then
      echo "corpus: $rel ($(field triangles "$result") triangles)" >&2
      measure "$rel" "$file" "$result"
      rendered=$((rendered + 1))
    fi
  else
    why=$(reason "$result")
    [ "$status" = no_triangles ] && why="read, but holds no triangle (lines, points, cameras, lights or animation only)"
    printf '%s\tstatus=%s reason="%s"\n' "$rel" "$status" "$why" >>"$MANIFEST"
  fi
done < <(find "$DIR" -type f | LC_ALL=C sort)
WALL=$(( $(date +%s) - START ))
echo "corpus wall time: $((WALL / 60))m$((WALL % 60))s ($rendered models rendered)" >&2

if [ "$PROBE_ONLY" = 1 ]; then
  [ "$SUBSET" = 0 ] && cp "$MANIFEST" tests/corpus/manifest.txt
  echo "probed: wrote $MANIFEST$([ "$SUBSET" = 0 ] && echo " and tests/corpus/manifest.txt")"
  exit 0
fi
scripts/corpus-table.sh "$CSV" "$MANIFEST" >"$OUT/corpus.md"
if [ "$SUBSET" = 1 ]; then
  echo "subset run: wrote $CSV, $MANIFEST, $OUT/corpus.md (docs/ and tests/corpus/ left as committed)"
  exit 0
fi
source scripts/replace-block.sh
cp "$CSV" docs/bench/corpus.csv
cp "$MANIFEST" tests/corpus/manifest.txt
GEN=$(mktemp)
{
  echo "Generated by \`scripts/corpus.sh\` on $(date -u +%Y-%m-%d) (wall time $((WALL / 60)) min $((WALL % 60)) s,"
  echo "$FRAMES timed frames after $WARMUP warm-up frames; $(nproc) cores; load average before the run"
  echo "$LOAD_BEFORE, after it $(uptime | sed 's/.*load average: //'))."
  echo "CSV: [bench/corpus.csv](bench/corpus.csv); manifest: [tests/corpus/manifest.txt](../tests/corpus/manifest.txt)."
  echo
  cat "$OUT/corpus.md"
} >"$GEN"
replace_block docs/benchmarks.md corpus "$GEN"
rm -f "$GEN"
echo "wrote docs/bench/corpus.csv, tests/corpus/manifest.txt and the corpus table of docs/benchmarks.md"
