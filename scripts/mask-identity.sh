#!/usr/bin/env bash
# Renders every built-in scene in every mode (and HYBRID with each method) with two builds of
# the renderer and compares their shadow masks and colour images byte for byte: a
# refactoring that changes no behaviour leaves them identical.
#   scripts/mask-identity.sh OLD_RENDERER NEW_RENDERER [OUT_DIR]
# e.g. after building the commit before a change into build-old:
#   scripts/mask-identity.sh build-old/bin/osgsilhouetteshadow build/bin/osgsilhouetteshadow
# Prints one line per case and a summary; exits 1 when any image differs. Runs with an X
# display (scripts/with-display.sh: Xvfb when there is none).
set -euo pipefail
[[ $# -ge 2 ]] || { sed -n 2,9p "$0"; exit 2; }
OLD=$(realpath "$1")
NEW=$(realpath "$2")
OUT=${3:-$(mktemp -d)}
mkdir -p "$OUT/old" "$OUT/new"
if [[ -z "${OSS_MASK_IDENTITY_DISPLAY:-}" ]]; then
  OSS_MASK_IDENTITY_DISPLAY=1 exec "$(dirname "$0")/with-display.sh" "$0" "$1" "$2" "$OUT"
fi
export OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-FATAL}
# Away from a source tree: the nodekit reads osgShadowSilhouette/shaders/ from the working
# directory (and OSG_FILE_PATH) before its built-in copies, which would hand both builds the
# same shader files.
cd "$OUT"
unset OSG_FILE_PATH

scenes=(default spheres poles cubes tree bunny dueling grazing elephant ring foliage)
variants=("shadowmap" "silhouette" "volume" "hybrid --hybrid-method lists" "hybrid --hybrid-method stencil")
lights=("" "--light-pos 2 3 6")
same=0 differ=0 failed=0
for scene in "${scenes[@]}"; do
  for variant in "${variants[@]}"; do
    for light in "${lights[@]}"; do
      name="${scene}_$(echo "$variant $light" | tr -cs 'A-Za-z0-9' '_')"
      ok=1
      for side in old new; do
        bin=$OLD; [[ $side == new ]] && bin=$NEW
        # shellcheck disable=SC2086
        if ! "$bin" --offscreen --scene "$scene" --mode $variant $light --size 512 384 --frames 1 --warmup 2 \
            --mask "$OUT/$side/$name.mask.png" --out "$OUT/$side/$name.png" >"$OUT/$side/$name.log" 2>&1; then
          ok=0
        fi
      done
      if [[ $ok == 0 ]]; then
        echo "FAILED  $name (see $OUT/*/$name.log)"; failed=$((failed + 1))
      elif cmp -s "$OUT/old/$name.mask.png" "$OUT/new/$name.mask.png" && cmp -s "$OUT/old/$name.png" "$OUT/new/$name.png"; then
        echo "same    $name"; same=$((same + 1))
      else
        echo "DIFFERS $name"; differ=$((differ + 1))
      fi
    done
  done
done
echo "mask-identity: $same identical, $differ differ, $failed failed to render ($OUT)"
[[ $differ == 0 && $failed == 0 ]]
