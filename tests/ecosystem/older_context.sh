#!/usr/bin/env bash
# Every mode on an OpenGL 4.1 context (Mesa's MESA_GL_VERSION_OVERRIDE): the GLSL 4.30 shaders
# (HYBRID's list term, the stencil modes' screen visibility) must stay out of the programs,
# which then link, and the masks must match the exact reference. HYBRID must have fallen back
# to stencil volumes (triangle_lists=0), which shows that the override took effect.
#   older_context.sh RENDERER WORKDIR
set -u
renderer=$1
work=$2
mkdir -p "$work"
export MESA_GL_VERSION_OVERRIDE=4.1COMPAT MESA_GLSL_VERSION_OVERRIDE=410 OSG_NOTIFY_LEVEL=WARN
status=0
for entry in shadowmap:0.1 silhouette:0.01 hybrid:0.01 volume:0.01; do
  mode=${entry%%:*}
  bound=${entry##*:}
  out=$("$renderer" --offscreen --mode "$mode" --size 256 192 --frames 2 --warmup 0 \
    --mask "$work/$mode-mask.png" --reference "$work/$mode-ref.png" 2>&1)
  pct=$(sed -n 's/.* wrong_pct=\([0-9.]*\).*/\1/p' <<<"$out")
  errors=$(sed -n 's/^gl_errors=//p' <<<"$out")
  if grep -q "failed to link" <<<"$out"; then
    echo "$mode: a program failed to link on a GL 4.1 context"; status=1
  fi
  if [ -z "$pct" ] || ! awk -v p="$pct" -v b="$bound" 'BEGIN { exit !(p < b) }'; then
    echo "$mode: wrong_pct=${pct:-none}, bound $bound"; status=1
  fi
  if [ "${errors:-x}" != 0 ]; then echo "$mode: gl_errors=${errors:-none}"; status=1; fi
  if [ "$mode" = hybrid ] && ! grep -q "triangle_lists=0" <<<"$out"; then
    echo "hybrid: triangle lists on a GL 4.1 context (was the version override ignored?)"; status=1
  fi
  echo "$mode: wrong_pct=${pct:-none} (bound $bound) gl_errors=${errors:-none}"
done
[ "$status" = 0 ] || echo "$out"
exit $status
