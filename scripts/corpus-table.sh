#!/usr/bin/env bash
# corpus-table.sh CORPUS.csv MANIFEST: the markdown of the corpus run (scripts/corpus.sh):
# one row per model and light with each mode's wrong %, then every file not rendered, by
# reason. Reads the CSV columns by name.
set -euo pipefail
CSV=$1 MANIFEST=$2

awk -F, '
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
function v(name) { return $col[name] }
{
  key = v("model") SUBSEP v("light")
  if (!(key in seen)) { seen[key] = 1; order[++n] = key
    info[key] = sprintf("| %s | %s | %s | %s | %s | %s | %s | %s ", v("model"), v("triangles"), v("parts"),
                        v("open_edges"), v("nonmanifold_edges"), v("flipped_edges"), v("textured") ? "yes" : "", v("light")) }
  m = v("mode")
  pct[key, m] = v("status") == "ok" ? sprintf("%.3f", v("wrong_pct")) : v("status")
  ms[key, m] = v("frame_ms_median") == "" ? "-" : sprintf("%.0f", v("frame_ms_median"))
  if (v("coverage_mismatch") + 0 > cov[key]) cov[key] = v("coverage_mismatch") + 0
  gl[key] += v("gl_errors")
  if (v("status") != "ok") bad[key] = 1
  if (v("status") == "ok" && (m == "hybrid" || m == "volume")) {
    total[m]++; if (v("wrong_pct") + 0 <= 0.01) good[m]++ }
  models[v("model")] = 1
}
END {
  for (k in models) ++modelCount
  printf "%d models rendered; wrong pixels in %% of the geometry pixels per mode (shadowmap and\n", modelCount
  printf "silhouette at map size 2048, hybrid at 1024), coverage mismatch the largest of the four\n"
  printf "modes, GL errors summed over them, frame ms per mode in the same order.\n"
  printf "At most 0.01%%: hybrid %d of %d rows, volume %d of %d.\n\n", good["hybrid"], total["hybrid"], good["volume"], total["volume"]
  print "| model | triangles | parts | open edges | non-manifold edges | flipped edges | textured | light | shadowmap | silhouette | hybrid | volume | coverage mismatch | GL errors | ms |"
  print "| --- | ---: | ---: | ---: | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |"
  for (i = 1; i <= n; ++i) {
    k = order[i]
    printf "%s| %s | %s | %s | %s | %d | %d | %s/%s/%s/%s |\n", info[k], pct[k, "shadowmap"], pct[k, "silhouette"],
           pct[k, "hybrid"], pct[k, "volume"], cov[k], gl[k], ms[k, "shadowmap"], ms[k, "silhouette"],
           ms[k, "hybrid"], ms[k, "volume"]
  }
}' "$CSV"

echo
echo "Not rendered (every other file of the corpus directory, with the probe's verdict):"
echo
echo "| verdict | files |"
echo "| --- | --- |"
grep -v '^#' "$MANIFEST" | { grep -v 'status=ok' || true; } |
  sed -n 's/^\([^\t]*\)\tstatus=\([^ ]*\) reason="\([^"]*\)"$/\2: \3\t\1/p' |
  sort -t$'\t' -k1,1 -k2,2 |
  awk -F'\t' '{ if ($1 != last) { if (last != "") printf "| %s | %s |\n", last, files; last = $1; files = "`" $2 "`" }
               else files = files ", `" $2 "`" }
              END { if (last != "") printf "| %s | %s |\n", last, files }'
