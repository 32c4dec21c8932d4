#!/usr/bin/env python3
# Copyright (c) 2026 The Flow_aligned_surfaces developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Prints the field tables from the files run_field_benchmarks.sh keeps in results/:

    field_benchmarks_summary.py RESULTS_DIR

Google Benchmark medians (real and CPU time) per benchmark, and for point location the ratio
of the package to its AABB_tree peers in the same run.  Standard library only.
"""

import json
import os
import sys


def medians(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b["aggregate_name"] in ("median", "cv"):
            rows.setdefault(b["run_name"], {})[b["aggregate_name"]] = b
    return data["context"], rows


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "results"
    ctx, rows = medians(os.path.join(out, "fields_grid_sampling.json"))
    print(f"Grid sampling (load {ctx.get('load_avg')}):\n")
    print("| benchmark | median ns/query (wall) | CPU | cv (wall) |")
    print("|---|---:|---:|---:|")
    for name, r in rows.items():
        m = r["median"]
        print(f"| {name} | {m['real_time']:.1f} | {m['cpu_time']:.1f} | {100 * r['cv']['real_time']:.1f} % |")
    ctx, rows = medians(os.path.join(out, "fields_point_location.json"))
    print(f"\nPoint location (load {ctx.get('load_avg')}):\n")
    print("| mesh | queries | variant | median ns/query (wall) | CPU | cv (wall) | package / this (wall, CPU) |")
    print("|---|---|---|---:|---:|---:|---:|")
    by = {}
    for name, r in rows.items():
        mesh, queries, variant = name.split("/")[1].split("_", 2)
        by[(mesh, queries, variant)] = r
    order = {"Package": 0, "AABB_hint": 1, "AABB": 2}
    for (mesh, queries, variant), r in sorted(by.items(), key=lambda kv: (kv[0][0], kv[0][1], order[kv[0][2]])):
        m = r["median"]
        p = by[(mesh, queries, "Package")]["median"]
        ratio = "–" if variant == "Package" else \
            f"{p['real_time'] / m['real_time']:.2f}, {p['cpu_time'] / m['cpu_time']:.2f}"
        print(f"| {mesh} | {queries} | {variant} | {m['real_time']:.0f} | {m['cpu_time']:.0f} "
              f"| {100 * r['cv']['real_time']:.1f} % | {ratio} |")


if __name__ == "__main__":
    main()
