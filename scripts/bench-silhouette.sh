#!/usr/bin/env bash
# The silhouette-map table of docs/benchmarks.md: SHADOW_MAP against SILHOUETTE_MAP on the
# default, poles and spheres scenes at map sizes 256-2048, 1024x768. The sweep
# (osgsilhouette-bench, 20 frames after 3 warm-up frames per row) runs RUNS times (default
# 12); the table gives each cell's median frame times over the runs, the median of its per-run
# time ratios and their range: on a shared machine the load changes from minute to minute.
# Then one run of SILHOUETTE_MAP at 1024 against osgShadow's techniques at 4096.
# Writes docs/bench/silhouette.csv (every run's rows) and prints both tables (markdown).
#
#   scripts/bench-silhouette.sh            # build (into $BUILD_DIR, default build) and run
#   RUNS=2 scripts/bench-silhouette.sh     # fewer runs (a smoke test, not results)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
RUNS=${RUNS:-12}
OUT=${OUT:-docs/bench}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} >/dev/null
cmake --build "$BUILD_DIR" -j "${JOBS:-2}" --target osgsilhouette-bench >/dev/null
export OSG_LIBRARY_PATH="$PWD/$BUILD_DIR/lib"
export OSG_NOTIFY_LEVEL=${OSG_NOTIFY_LEVEL:-WARN}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$OUT"
CSV="$OUT/silhouette.csv"
# Each cell's two rows run back to back (one invocation per scene and size), so that each
# run's ratio compares frames taken seconds apart.
for ((k = 1; k <= RUNS; ++k)); do
  for scene in default poles spheres; do
    for size in 256 512 1024 2048; do
      dir="$TMP/run$k-$scene-$size"
      scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouette-bench" --scenes "$scene" \
        --techniques shadowmap,silhouette --sizes "$size" --frames 20 --warmup 3 \
        --out-dir "$dir" --no-plot >/dev/null 2>&1
      [ "$k$scene$size" = 1default256 ] && head -1 "$dir/benchmark.csv" | sed "s/^/run,/" > "$CSV"
      tail -n +2 "$dir/benchmark.csv" | sed "s/^/$k,/" >> "$CSV"
    done
  done
done
scripts/with-display.sh "$BUILD_DIR/bin/osgsilhouette-bench" --scenes default,poles,spheres \
  --techniques silhouette,osgShadow:ShadowMap,osgShadow:SoftShadowMap,osgShadow:LightSpacePerspectiveShadowMapCB,osgShadow:ViewDependentShadowMap,osgShadow:ParallelSplitShadowMap \
  --sizes 1024,4096 --frames 20 --warmup 3 --out-dir "$TMP/peers" --no-plot >/dev/null

# Columns after the run number: scene, technique, map_size, ..., frame_ms_median (8), ..., wrong_pct (12).
echo "| scene | map | shadowmap wrong % | silhouette wrong % | accuracy ratio | shadowmap ms | silhouette ms | time ratio (median of runs) | per-run ratios |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
tail -n +2 "$CSV" | sort -t, -k2,2 -k4,4n -k3,3 -k8,8n | awk -F, '
  function median(key,   n) { n = count[key]; return n % 2 ? v[key, (n + 1) / 2] : (v[key, n / 2] + v[key, n / 2 + 1]) / 2 }
  { key = $2 "," $4 "," $3; v[key, ++count[key]] = $8; wrong[key] = $12; ms[key, $1] = $8; runs[$1] = 1
    if (!(($2 "," $4) in seen)) { seen[$2 "," $4] = 1; order[++cells] = $2 "," $4 } }
  END {
    for (i = 1; i <= cells; ++i) {
      split(order[i], c, ","); sm = order[i] ",shadowmap"; sil = order[i] ",silhouette"
      n = 0
      for (r in runs) if ((sm, r) in ms && (sil, r) in ms) q[++n] = ms[sil, r] / ms[sm, r]
      for (a = 2; a <= n; ++a) for (b = a; b > 1 && q[b - 1] > q[b]; --b) { t = q[b]; q[b] = q[b - 1]; q[b - 1] = t }
      ratio = n % 2 ? q[(n + 1) / 2] : (q[n / 2] + q[n / 2 + 1]) / 2
      acc = wrong[sil] > 0 ? wrong[sm] / wrong[sil] : 0
      printf "| %s | %s | %.4f | %.4f | %s | %.1f | %.1f | %.2f | %.2f-%.2f |\n", c[1], c[2], wrong[sm], wrong[sil],
             (acc >= 10 ? sprintf("%.0fx", acc) : sprintf("%.1fx", acc)), median(sm), median(sil), ratio, q[1], q[n]
    } }'
echo
echo "| scene | silhouette 1024 | best peer at 4096 (by wrong %) | its wrong % | its ms | silhouette ms | time ratio |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
tail -n +2 "$TMP/peers/benchmark.csv" | awk -F, '
  $2 == "silhouette" && $3 == 1024 { silw[$1] = $11; silms[$1] = $7; if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } }
  $2 ~ /^osgShadow:/ && $3 == 4096 { if (!($1 in bestw) || $11 < bestw[$1]) { bestw[$1] = $11; best[$1] = $2; bestms[$1] = $7 } }
  END { for (i = 1; i <= n; ++i) { s = order[i]; sub(/^osgShadow:/, "", best[s])
          printf "| %s | %.4f%% | %s | %.4f%% | %.1f | %.1f | %.2f |\n", s, silw[s], best[s], bestw[s], bestms[s], silms[s], silms[s] / bestms[s] } }'
