#!/usr/bin/env python3
"""Prints the tables of docs/BENCHMARKS.md, "Speed against accuracy", from the CSVs that
`./handsim tradeoff --out docs/tradeoff` writes (so the figures there are this run's)."""
import csv, json, sys
from pathlib import Path

d = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent / "docs" / "tradeoff")

def rows(name):
    with open(d / name) as f:
        return list(csv.DictReader(f))

def t(s):
    if s == "":
        return "–"   # not defined (an empty cell)
    s = float(s)
    return f"{s*1e6:.3g} µs" if s < 1e-3 else f"{s*1e3:.3g} ms" if s < 1 else f"{s:.3g} s"

def e(v):
    return f"{float(v):.2g}" if v != "" else "–"

j = json.load(open(d / "tradeoff.json"))
print("total", round(j["wall_time_s"], 1), "s;", " / ".join(f"{v['wall_time_s']:.1f}" for v in j["studies"].values()), "s\n")

r = [x for x in rows("1-dt.csv") if x["series"].startswith("tau32 trace")]
print("| dt | " + " | ".join(x["setting"] for x in r) + " |")
print("|---|" + "---:|" * len(r))
print("| wall per simulated second | " + " | ".join(t(x["wall_s_per_sim_s"]) for x in r) + " |")
print("| τ32 trace RMS / peak | " + " | ".join(e(x["rel_error"]) for x in r) + " |")
others = [x for x in rows("1-dt.csv") if not x["series"].startswith("tau32 trace")]
print("largest relative error of breakaway time, peak τ32, peak force:", max(float(x["rel_error"]) for x in others), "\n")

print("| shape | divisions | triangles | query | centre error | centre / radius | normal error |")
print("|---|---:|---:|---:|---:|---:|---:|")
for x in rows("2-tessellation.csv"):
    if not x["series"].endswith("centre") or x["setting"] not in ("1", "12", "24", "32", "128"):
        continue
    if x["series"].startswith("cube") and x["setting"] not in ("1", "32"):
        continue
    b = "**" if x["default"] == "true" else ""
    print(f"| {x['series'].split()[0]} | {b}{x['setting']}{b} | {int(float(x['triangles']))} | {t(x['query_s'])} | "
          f"{float(x['centre_error_m'])*1e3:.3g} mm | {float(x['centre_error_rel']):.2g} | {float(x['normal_error_rad'])*57.29577951308232:.3g}° |")
print()

k = rows("3-kdop.csv")
objs = []
for x in k:
    if x["series"] not in objs:
        objs.append(x["series"])
print("| object | triangles | k = 6 | k = 14 | **k = 18** | k = 26 | brute force |")
print("|---|---:|---:|---:|---:|---:|---:|")
for o in objs:
    cells = []
    for x in [y for y in k if y["series"] == o]:
        cells.append(f"{t(x['query_s'])}, {int(float(x['triangle_tests']))}")
    print(f"| {o} | {int(float(k[[y['series'] for y in k].index(o)]['object_triangles']))} | " + " | ".join(cells) + " |")
print()

g = rows("4-integrators.csv")
print("| dt | explicit Euler | semi-implicit Euler | RK4 |")
print("|---|---:|---:|---:|")
for dt in ("10 ms", "1 ms", "0.1 ms", "0.01 ms"):
    cells = []
    for m in ("explicit Euler", "semi-implicit Euler", "RK4"):
        x = [y for y in g if y["series"] == m and y["setting"] == dt]
        cells.append(f"{e(x[0]['drift'])}, {t(x[0]['wall_s'])}" if x else "–")
    print(f"| {dt} | " + " | ".join(cells) + " |")
for x in g:
    if x["series"].startswith("Dormand"):
        print("dopri", x["setting"], x["steps"], x["evaluations"], e(x["drift"]), t(x["wall_s"]))
