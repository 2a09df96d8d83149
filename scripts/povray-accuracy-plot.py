# SPDX-License-Identifier: MIT
"""The plot and the Markdown tables of scripts/povray-accuracy-study.sh for one scene.

usage: /usr/bin/python3 scripts/povray-accuracy-plot.py SCENE.csv OUT.png TITLE JUDGE_FLOOR

Reads the scene's CSV (series, setting, cpu_s, relative_mse, net_relative_mse), draws the net
relative MSE (the judge's noise floor subtracted) against CPU time on log-log axes (pm's settings
as points joined along their Pareto front, sppm and the path tracer as curves over their budgets,
POV-Ray's presets as points, the floor as a dotted line: net errors near or below it are as
uncertain as the floor is large) and prints Markdown: photon's and POV-Ray's best net error within
10 and 100 CPU-s (the least error of any run that took at most that long, so no curve is
extrapolated), then every run.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

csv_file, png_file, title, floor = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
rows = list(csv.DictReader(open(csv_file)))
for r in rows:
    r["cpu_s"] = float(r["cpu_s"])
    r["raw"] = float(r["relative_mse"])
    r["relative_mse"] = float(r["net_relative_mse"])  # what is plotted and compared
dropped = [r for r in rows if r["relative_mse"] <= 0]  # within the judge's noise: no place on a log axis
rows = [r for r in rows if r["relative_mse"] > 0]


def pareto(points):
    """The runs no other run beats in both time and error, by time."""
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p["cpu_s"], p["relative_mse"])):
        if p["relative_mse"] < best:
            front.append(p)
            best = p["relative_mse"]
    return front


def best_within(points, seconds):
    inside = [p for p in points if p["cpu_s"] <= seconds]
    return min(inside, key=lambda p: p["relative_mse"]) if inside else None


style = {"pm": ("C0", "o"), "sppm": ("C1", "s"), "reference": ("C2", "^"), "povray": ("C3", "D")}
names = {"pm": "photon pm (settings; line: Pareto front)", "sppm": "photon sppm (passes)",
         "reference": "photon reference (spp)", "povray": "POV-Ray 3.7 radiosity presets"}
fig, ax = plt.subplots(figsize=(7, 4.6), dpi=100)
for series, (colour, marker) in style.items():
    points = [r for r in rows if r["series"] == series]
    if not points:
        continue
    ax.scatter([p["cpu_s"] for p in points], [p["relative_mse"] for p in points], color=colour, marker=marker,
               label=names[series], s=22, zorder=3)
    line = pareto(points) if series in ("pm", "povray") else sorted(points, key=lambda p: p["cpu_s"])
    ax.plot([p["cpu_s"] for p in line], [p["relative_mse"] for p in line], color=colour, lw=1,
            ls="--" if series == "povray" else "-")
    if series in ("pm", "povray"):
        for p in points:
            ax.annotate(p["setting"], (p["cpu_s"], p["relative_mse"]), fontsize=6, xytext=(3, 3),
                        textcoords="offset points", color=colour)
ax.axhline(floor, color="grey", lw=0.8, ls=":", label=f"judge's noise floor {floor:.2g}")
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("CPU time of the whole command (user + sys, s)")
ax.set_ylabel("relative MSE against the judge, its noise subtracted")
ax.set_title(f"{title}: error against CPU time, photon and POV-Ray")
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(png_file)

photon = [r for r in rows if r["series"] != "povray"]
povray = [r for r in rows if r["series"] == "povray"]


def cell(p):
    return f"{p['relative_mse']:.3g} ({p['series']} {p['setting']}, {p['cpu_s']:.1f} s)" if p else "none that fast"


print("| CPU-s budget | photon's least net relative MSE (run) | POV-Ray's least net relative MSE (run) |")
print("|---:|---|---|")
for seconds in (10, 100):
    print(f"| {seconds} | {cell(best_within(photon, seconds))} | {cell(best_within(povray, seconds))} |")
print()
print("| series | setting | CPU-s | relative MSE | net of the judge's noise |")
print("|---|---|---:|---:|---:|")
for r in rows + dropped:
    print(f"| {r['series']} | {r['setting']} | {r['cpu_s']:.2f} | {r['raw']:.3g} | {r['relative_mse']:.3g} |")
