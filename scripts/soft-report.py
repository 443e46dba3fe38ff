#!/usr/bin/env python3
"""Reports the soft-shadow benchmark (scripts/bench-soft.sh) from its CSV.

    scripts/soft-report.py docs/bench/soft.csv docs/bench "how it was measured" [--no-docs]

Writes, from the rows of the CSV:
- the generated block `soft` of docs/benchmarks.md: every row, grouped by scene and light;
- the block `soft-goals` of docs/benchmarks.md: per scene, light, size and map size, the
  goals for FILTER_SILHOUETTE (SILHOUETTE_MAP's seed filter) measured side by side:
  its vis_mae_penumbra against binary SHADOW_MAP's (size 0: at most half), against PCSS's and
  half of osgShadow SoftShadowMap's (sized lights), and its frame time against SHADOW_MAP's
  2x2 PCF (at most 2x) and PCSS's (at most 1x);
- the block `soft-headline` of README.md: the largest size of each light at the largest map;
- OUT/soft-<scene>-<light>.gp and, with gnuplot, .png: frame time against vis_mae_penumbra at
  the light's largest size, one line per technique through its map sizes.
With --no-docs (a subset run) the three blocks go to OUT/soft.md instead.
"""
import csv
import os
import shutil
import subprocess
import sys
from collections import defaultdict


# One colour per technique in the plots (the labels' series would shift gnuplot's own cycle).
PALETTE = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22",
           "#17becf"]


def replace_block(path, name, body):
    """Replaces the lines between <!-- BEGIN name --> and <!-- END name --> (appends the block
    when the markers are missing), as scripts/replace-block.sh does."""
    begin, end = f"<!-- BEGIN {name} -->", f"<!-- END {name} -->"
    lines = open(path).read().split("\n") if os.path.exists(path) else []
    if begin not in lines:
        lines += ["", begin, end]
    out, skip = [], False
    for line in lines:
        if line == begin:
            out.append(line)
            out.extend(body.rstrip("\n").split("\n"))
            skip = True
        elif line == end:
            skip = False
            out.append(line)
        elif not skip:
            out.append(line)
    open(path, "w").write("\n".join(out))


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def label(row):
    """The technique as the tables name it: mode and filter."""
    mode = row["technique"].replace("osgShadow:", "")
    return mode if row["filter"] in ("none", "") else f"{mode} {row['filter']}"


def light_of(row):
    return row["notes"].split(" ")[0]


def fmt(value, digits=4):
    return "-" if value is None else f"{value:.{digits}f}"


def read_rows(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        r["light"] = light_of(r)
        r["size"] = num(r["light_size"])
        r["map"] = int(r["map_size"] or 0)
        r["ms"] = num(r["frame_ms_median"])
        r["pen"] = num(r["vis_mae_penumbra"])
        r["label"] = label(r)
    return rows


def full_table(rows, how):
    head = ("| scene | light | size | technique | map | vis_mae | vis_mae_penumbra | vis_p99_penumbra "
            "| penumbra pixels | wrong_pct (hard) | frame ms |\n" + "|---" * 11 + "|\n")
    body = "".join(
        f"| {r['scene']} | {r['light']} | {r['light_size']} | {r['label']} | {r['map'] or '-'} | "
        f"{r['vis_mae'] or '-'} | {r['vis_mae_penumbra'] or '-'} | {r['vis_p99_penumbra'] or '-'} | "
        f"{r['penumbra_pixels'] or '-'} | {r['wrong_pct'] or '-'} | {r['frame_ms_median'] or '-'} |\n"
        for r in rows)
    return head + body + f"\nMeasured with `scripts/bench-soft.sh` ({how}); sun sizes are angular radii in " \
        "degrees, point-light sizes radii in scene units. Compare frame times within a scene and light.\n"


def groups(rows):
    """(scene, light, size, map) -> {label: row}; hybrid and volume (one run) join every map."""
    out = defaultdict(dict)
    maps = sorted({r["map"] for r in rows if r["technique"] not in ("hybrid", "volume")})
    for r in rows:
        for m in (maps if r["technique"] in ("hybrid", "volume") else [r["map"]]):
            out[(r["scene"], r["light"], r["size"], m)][r["label"]] = r
    return out


def ratio(a, b):
    return None if a is None or b in (None, 0) else a / b


def goal_cell(value, limit):
    if value is None or limit is None:
        return "-"
    return f"{value:.2f} {'yes' if value <= limit else 'no'}"


def goals_table(rows):
    head = ("| scene | light | size | map | FILTER_SILHOUETTE vis_mae_penumbra | SHADOW_MAP 2x2 | PCSS | SoftShadowMap "
            "| goal: error ratio (size 0: to 2x2, <= 0.5; sized: to PCSS, <= 1) | to half SoftShadowMap's (<= 1) "
            "| frame to 2x2 (<= 2) | frame to PCSS (<= 1) |\n" + "|---" * 12 + "|\n")
    body, met, total = "", 0, 0
    for (scene, light, size, m), g in sorted(groups(rows).items()):
        sil, pcf, pcss, ssm = (g.get(k) for k in ("silhouette silhouette", "shadowmap pcf2x2", "shadowmap pcss",
                                                  "SoftShadowMap"))
        if not sil:
            continue
        val = lambda r, key: r[key] if r else None
        e = ratio(val(sil, "pen"), val(pcf if size == 0 else pcss, "pen"))
        h = None if size == 0 else ratio(val(sil, "pen"), 0.5 * val(ssm, "pen") if val(ssm, "pen") else None)
        f2, fp = ratio(val(sil, "ms"), val(pcf, "ms")), ratio(val(sil, "ms"), val(pcss, "ms"))
        checks = [(e, 0.5 if size == 0 else 1.0), (h, 1.0), (f2, 2.0), (fp, 1.0)]
        met += sum(1 for v, lim in checks if v is not None and v <= lim)
        total += sum(1 for v, _ in checks if v is not None)
        body += (f"| {scene} | {light} | {size:g} | {m} | {fmt(val(sil, 'pen'))} | {fmt(val(pcf, 'pen'))} | "
                 f"{fmt(val(pcss, 'pen'))} | {fmt(val(ssm, 'pen'))} | {goal_cell(e, checks[0][1])} | "
                 f"{goal_cell(h, 1.0)} | {goal_cell(f2, 2.0)} | {goal_cell(fp, 1.0)} |\n")
    return head + body + f"\n{met} of {total} goal checks met.\n"


def headline(rows):
    """The largest size of each light at the largest map size, one line per scene and light."""
    techs = ["shadowmap pcf2x2", "shadowmap pcss", "silhouette silhouette", "SoftShadowMap", "hybrid", "volume"]
    names = ["SHADOW_MAP 2x2 PCF", "SHADOW_MAP PCSS", "SILHOUETTE_MAP FILTER_SILHOUETTE", "osgShadow SoftShadowMap",
             "HYBRID (shadow rays, SoftSamples 64)", "SHADOW_VOLUME (hard)"]
    top_map = max(r["map"] for r in rows)
    head = "| scene | light | " + " | ".join(names) + " |\n" + "|---" * (2 + len(names)) + "|\n"
    body = ""
    for (scene, light, size, m), g in sorted(groups(rows).items()):
        sizes = [r["size"] for r in rows if r["scene"] == scene and r["light"] == light]
        if m != top_map or size != max(sizes):
            continue
        unit = f"{size:g} deg" if light == "sun" else f"r {size:g}"
        cells = [f"{fmt(g[t]['pen'], 3)} @ {fmt(g[t]['ms'], 1)} ms" if t in g and g[t]["pen"] is not None else "-"
                 for t in techs]
        body += f"| {scene} | {light}, {unit} | " + " | ".join(cells) + " |\n"
    return (f"vis_mae_penumbra (mean error of the visibility in the exact penumbra) @ frame time, map {top_map}, "
            "512x384 on llvmpipe ([every size, map and goal](docs/benchmarks.md#soft-shadows)):\n\n" + head + body)


def plots(rows, out):
    for scene, light in sorted({(r["scene"], r["light"]) for r in rows}):
        sel = [r for r in rows if r["scene"] == scene and r["light"] == light]
        size = max(r["size"] for r in sel)
        sel = [r for r in sel if r["size"] == size and r["pen"] is not None and r["ms"] is not None]
        base = os.path.join(out, f"soft-{scene}-{light}")
        gp = [f"set terminal pngcairo size 900,600 noenhanced font ',10'", f"set output '{base}.png'",
              f"set title '{scene}, {light} of size {size:g}: frame time against penumbra error (512x384)'",
              "set logscale xy", "set xlabel 'vis_mae_penumbra (log)'", "set ylabel 'frame time, ms (median, log)'",
              "set grid", "set key outside right top"]
        series = []
        for i, t in enumerate(sorted({r["label"] for r in sel})):
            pts = sorted((r for r in sel if r["label"] == t), key=lambda r: r["map"])
            gp.append(f"$t{i} << EOD")
            gp += [f"{max(r['pen'], 1e-4)} {r['ms']} {r['map'] or ''}" for r in pts]
            gp.append("EOD")
            colour = PALETTE[i % len(PALETTE)]
            series.append(f"$t{i} using 1:2 with linespoints pt 7 lc rgb '{colour}' title '{t}', "
                          f"$t{i} using 1:2:3 with labels offset 1,0.5 tc rgb '{colour}' notitle")
        gp.append("plot " + ", ".join(series))
        open(base + ".gp", "w").write("\n".join(gp) + "\n")
        if shutil.which("gnuplot"):
            subprocess.run(["gnuplot", base + ".gp"], check=False)


def main():
    path, out, how = sys.argv[1], sys.argv[2], sys.argv[3]
    rows = read_rows(path)
    if not rows:
        sys.exit("soft-report: no rows in " + path)
    subset = "--no-docs" in sys.argv[4:]
    docs, readme = (os.path.join(out, "soft.md"),) * 2 if subset else ("docs/benchmarks.md", "README.md")
    replace_block(docs, "soft", full_table(rows, how))
    replace_block(docs, "soft-goals", goals_table(rows))
    replace_block(readme, "soft-headline", headline(rows))
    plots(rows, out)


if __name__ == "__main__":
    main()
