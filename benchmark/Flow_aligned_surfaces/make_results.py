#!/usr/bin/env python3
# Copyright (c) 2026 The Flow_aligned_surfaces developers.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the generated part of RESULTS.md from the benchmarks' JSON output.

    make_results.py --table1 table1.json [--variant LABEL=table1.json ...]
                    [--grid grid_sampling.json] [--command CMD] [--grid-command CMD]
                    [--results RESULTS.md]

table1.json is bench_deformation's output, grid_sampling.json Google Benchmark's
(--benchmark_out_format=json) for bench_grid_sampling.  Only the text between the markers
<!-- BEGIN GENERATED --> and <!-- END GENERATED --> is replaced, so the hand-written analysis
around it stays; a missing file is created with the markers.  Standard library only.
"""

import argparse
import json
import os
import sys

BEGIN = "<!-- BEGIN GENERATED -->"
END = "<!-- END GENERATED -->"

# Table 1 of the paper (Intel Core i7-2600 3.4 GHz, single-threaded, CHOLMOD) and the targets.
PAPER = {
    "faces": [8e2, 5e3, 2e4, 8e4, 3.2e5],
    "factor_ms": [0.5, 2.3, 13.2, 932, 8000],
    "gtransf_ms": [0.26, 1.5, 6.4, 24.2, 91.1],
    "solve_ms": [0.16, 0.25, 0.83, 4.5, 23.0],
    "its_per_s": [2300, 570, 130, 35, 9],
    "nconv": [5, 9, 16, 19, 22],
}
FACTOR_DIVISOR = 5.0  # FACTOR <= paper / 5
ITS_FACTOR = 3.0      # IT/s >= 3 x paper


def fmt(x, digits=3):
    """A number with about `digits` significant digits, no exponent for table-sized values."""
    if x is None:
        return "–"
    if x == 0:
        return "0"
    if float(x).is_integer() and abs(x) < 1e15:
        return f"{int(x):,}"
    a = abs(x)
    if a >= 10 ** digits:
        return f"{x:,.0f}"
    decimals = max(0, digits - 1 - int(f"{a:e}".split("e")[1]))
    return f"{x:,.{decimals}f}"


def paper_index(target_faces):
    best = min(range(len(PAPER["faces"])), key=lambda i: abs(PAPER["faces"][i] - target_faces) / PAPER["faces"][i])
    return best if abs(PAPER["faces"][best] - target_faces) / PAPER["faces"][best] < 0.25 else None


def mark(ok):
    return "**met**" if ok else "missed"


def table1_section(data, label=None):
    out = []
    sizes = data["sizes"]
    solver = sizes[0]["default_solver"] if sizes else "?"
    title = "Table 1" if label is None else f"Table 1, variant: {label}"
    out.append(f"### {title}\n")
    overlay = data["machine"].get("include_overlay", "")
    out.append(f"Solver: `{solver}` (the package's default in this build)"
               + (f"; headers overlaid from `{overlay}`" if overlay else "") + ".  "
               "Medians over the repetitions (per run: median over its iterations); "
               "ours / paper.  The constructor column (checks, operators and FACTOR) has no "
               "counterpart in the paper.\n")
    out.append("| faces (target) | faces | reps | FACTOR ms | GTRANSF ms | SOLVE ms | IT/s | NCONV orth / tang | constructor ms |")
    out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in sizes:
        i = paper_index(s["target_faces"])
        p = (lambda key: PAPER[key][i]) if i is not None else (lambda key: None)
        by = s["by_alignment"]
        nconv = f'{by["orthogonal"]["nconv"]} / {by["tangential"]["nconv"]}'
        out.append(
            f'| {fmt(s["target_faces"])} | {s["faces"]:,} | {s["repetitions"]} '
            f'| {fmt(s["factor_ms"])} / {fmt(p("factor_ms"))} '
            f'| {fmt(s["gtransf_ms"])} / {fmt(p("gtransf_ms"))} '
            f'| {fmt(s["solve_ms"])} / {fmt(p("solve_ms"))} '
            f'| {fmt(s["its_per_s"])} / {fmt(p("its_per_s"))} '
            f'| {nconv} / {fmt(p("nconv"))} | {fmt(s.get("construct_ms"))} |')
    out.append("")
    out.append("Targets: FACTOR ≤ paper/5, IT/s ≥ 3 × paper, NCONV ≤ paper (both alignments).\n")
    out.append("| faces | FACTOR ≤ | | IT/s ≥ | | NCONV ≤ | | wall-clock step() rate |")
    out.append("|---:|---:|---|---:|---|---:|---|---:|")
    for s in sizes:
        i = paper_index(s["target_faces"])
        if i is None:
            continue
        factor_target = PAPER["factor_ms"][i] / FACTOR_DIVISOR
        its_target = PAPER["its_per_s"][i] * ITS_FACTOR
        by = s["by_alignment"]
        nconv = max(by["orthogonal"]["nconv"], by["tangential"]["nconv"])
        converged = by["orthogonal"]["converged"] and by["tangential"]["converged"]
        out.append(
            f'| {s["faces"]:,} '
            f'| {fmt(factor_target)} ms | {mark(s["factor_ms"] <= factor_target)} ({fmt(s["factor_ms"] / factor_target, 2)}×) '
            f'| {fmt(its_target)} | {mark(s["its_per_s"] >= its_target)} ({fmt(s["its_per_s"] / its_target, 2)}×) '
            f'| {PAPER["nconv"][i]} | {mark(converged and nconv <= PAPER["nconv"][i])} ({nconv}) '
            f'| {fmt(s["its_per_s_wall"])} it/s |')
    out.append("")
    out.append("(×: ours divided by the target.  The wall-clock rate times whole `step()` calls, which "
               "also write the positions back and measure the step; IT/s is the paper's "
               "1000 / (GTRANSF + SOLVE).)\n")
    return out


def convergence_section(data):
    out = ["### Convergence from the fixed starts\n"]
    setup = data["setup"]
    out.append(f'- Field: {setup["field"]}.')
    out.append(f'- Patch: {setup["patch"]}.')
    out.append(f'- Orthogonal start: {setup["start_orthogonal"]}.')
    out.append(f'- Tangential start: {setup["start_tangential"]}.')
    out.append(f'- Convergence: {setup["convergence"]}; at most {setup["max_iterations"]} iterations.\n')
    out.append("| faces | alignment | NCONV | rule | f_n start → end | last requested rotation (rad) |")
    out.append("|---:|---|---:|---|---|---:|")
    for s in data["sizes"]:
        for name in ("orthogonal", "tangential"):
            a = s["by_alignment"][name]
            rule = a["rule"] if a["converged"] else "not converged"
            out.append(f'| {s["faces"]:,} | {name} | {a["nconv"]} | {rule} '
                       f'| {a["initial_flux"]:.4f} → {a["final_flux"]:.6f} | {a["last_max_rotation_angle"]:.2e} |')
    out.append("")
    return out


def solver_section(data):
    out = ["### Sparse Cholesky solvers on the same matrix L + W\n"]
    out.append(f'FACTOR = symbolic analysis + numeric factorization (wall clock; thread CPU time beside it); '
               f'SOLVE = median of {data["setup"]["solver_steps"]} iterations (the three coordinates at once).  '
               'nnz(L) and flops are CHOLMOD\'s counts from the analysis.\n')
    out.append("| faces | solver | ordering | FACTOR ms | analyze | numeric | FACTOR cpu | SOLVE ms | nnz(L) | MB per solve | flops |")
    out.append("|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in data["sizes"]:
        best_factor = min(c["factor_ms"] for c in s["solvers"])
        best_solve = min(c["solve_ms"] for c in s["solvers"])
        for c in s["solvers"]:
            f = fmt(c["factor_ms"])
            if c["factor_ms"] == best_factor:
                f = f"**{f}**"
            sv = fmt(c["solve_ms"])
            if c["solve_ms"] == best_solve:
                sv = f"**{sv}**"
            default = " (default)" if c["name"] == s["default_solver"] else ""
            flops = fmt(c["flops"]) if c.get("flops") not in (None, -1) else "–"
            mb = fmt(c["bytes_per_solve"] / 1e6) if c.get("bytes_per_solve", -1) not in (None, -1) else "–"
            nnz = fmt(c["nnz_L"]) if c.get("nnz_L", -1) not in (None, -1) else "–"
            out.append(f'| {s["faces"]:,} | `{c["name"]}`{default} | {c["ordering"]} | {f} | {fmt(c["analyze_ms"])} '
                       f'| {fmt(c["numeric_ms"])} | {fmt(c["factor_cpu_ms"])} | {sv} | {nnz} | {mb} | {flops} |')
    out.append("")
    out.append("Solvers: " + "; ".join(f'`{c["name"]}`: {c["description"].replace(" (package default)", "")}' for c in data["sizes"][0]["solvers"]) + ".\n"
               if data["sizes"] else "")
    return out


def limits_section(data):
    """The bytes a solve streams against the bandwidth measured in the same run, and
    the rate on every core (use_parallelism) beside the single-threaded one."""
    m = data["machine"]
    bandwidth = m.get("read_bandwidth_gb_s_1_thread")
    if bandwidth is None:
        return []
    after = data["run"].get("read_bandwidth_gb_s_1_thread_after")
    out = ["### The physical limit of SOLVE, and both cores\n"]
    out.append(f'Read bandwidth measured in this run (one thread streaming 256 MiB, median of 5): '
               f'{fmt(bandwidth)} GB/s before the sizes, {fmt(after)} GB/s after; '
               f'{fmt(m.get("read_bandwidth_gb_s_all_threads"))} GB/s on all {m["hardware_threads"]} threads.  '
               'Bytes: the factor read by the two sweeps of one solve (values and row indices), the '
               'least any direct solve with this factor must stream; bound = bytes / bandwidth.  '
               'The parallel columns repeat the orthogonal run with `use_parallelism(true)` '
               '(TBB over the faces and over independent subtrees of the elimination tree).\n')
    out.append("| faces | solver | nnz(L) | MB per solve | bound ms | SOLVE ms | SOLVE / bound "
               "| parallel GTRANSF ms | parallel SOLVE ms | parallel IT/s | parallel / serial IT/s |")
    out.append("|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in data["sizes"]:
        default = next((c for c in s["solvers"] if c["name"] == s["default_solver"]), None)
        if default is None or default.get("bytes_per_solve", -1) in (None, -1):
            continue
        mb = default["bytes_per_solve"] / 1e6
        bound = default["bytes_per_solve"] / (bandwidth * 1e6)
        par = s.get("parallel")
        par_cells = (f'| {fmt(par["gtransf_ms"])} | {fmt(par["solve_ms"])} | {fmt(par["its_per_s"])} '
                     f'| {fmt(par["its_per_s"] / s["its_per_s"], 2)}× |') if par else "| – | – | – | – |"
        out.append(f'| {s["faces"]:,} | `{default["name"]}` | {fmt(default["nnz_L"])} | {fmt(mb)} | {fmt(bound)} '
                   f'| {fmt(s["solve_ms"])} | {fmt(s["solve_ms"] / bound, 2)}× {par_cells}')
    out.append("")
    return out


def grid_section(grid, command):
    out = ["### Grid sampling (bench_grid_sampling)\n"]
    if command:
        out.append(f"Command: `{command}`\n")
    ctx = grid.get("context", {})
    build = ctx.get("library_build_type", "")
    out.append(f'Google Benchmark ({build} build of the library{": its own overhead is included" if build == "debug" else ""}), '
               f'{ctx.get("num_cpus", "?")} CPUs at {ctx.get("mhz_per_cpu", "?")} MHz, load average '
               f'{", ".join(f"{x:.2f}" for x in ctx.get("load_avg", []))}.  One iteration is '
               'one query on a 128³ grid sampled from the ABC flow; 7 repetitions; target ≤ 50 ns at coherent positions.\n')
    rows = {}
    for b in grid.get("benchmarks", []):
        if b.get("run_type") != "aggregate":
            continue
        name = b["run_name"] if "run_name" in b else b["name"].rsplit("_", 1)[0]
        rows.setdefault(name, {})[b["aggregate_name"]] = b
    out.append("| benchmark | median ns/query | mean | cv | inside |")
    out.append("|---|---:|---:|---:|---:|")
    for name, agg in rows.items():
        med, mean, cv = agg.get("median"), agg.get("mean"), agg.get("cv")
        unit = (med or mean or {}).get("time_unit", "ns")
        scale = {"ns": 1, "us": 1e3, "ms": 1e6}.get(unit, 1)
        inside = (med or {}).get("inside")
        cv_text = f'{100 * cv["real_time"]:.1f} %' if cv else "–"
        out.append(f'| {name} | {fmt(med["real_time"] * scale) if med else "–"} '
                   f'| {fmt(mean["real_time"] * scale) if mean else "–"} | {cv_text} '
                   f'| {fmt(inside, 3) if inside is not None else "–"} |')
    out.append("")
    return out


def machine_section(data, command):
    m, run = data["machine"], data["run"]
    out = ["### Run\n"]
    if command:
        out.append(f"- Command: `{command}`")
    out.append(f'- Machine: {m["cpu_model"]}, {m["hardware_threads"]} hardware threads; load average before '
               f'`{m["loadavg_before"]}`, after `{run["loadavg_after"]}`; run {run["wall_s"]:.1f} s wall, '
               f'{run["cpu_s"]:.1f} s CPU ('
               + ("CPU ≈ wall: one thread, rarely preempted" if run["cpu_s"] >= 0.9 * run["wall_s"]
                  else "CPU < wall: the process waited for a core; figures are noisier") + ').')
    out.append(f'- Software: GCC {m["compiler"]}, CGAL {m["cgal"]}, Eigen {m["eigen"]}, CHOLMOD {m["cholmod"]}; '
               f'NDEBUG {m["ndebug"]}; OMP_NUM_THREADS={m["omp_num_threads"]}, '
               f'OMP_THREAD_LIMIT={m.get("omp_thread_limit", "?")}, OPENBLAS_NUM_THREADS={m.get("openblas_num_threads", "?")}.')
    out.append(f'- Libraries loaded: `{m.get("libraries", "")}`')
    if m.get("include_overlay"):
        out.append(f'- Header overlay: `{m["include_overlay"]}`')
    out.append("")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--table1", required=True)
    parser.add_argument("--variant", action="append", default=[], metavar="LABEL=JSON")
    parser.add_argument("--grid")
    parser.add_argument("--command", default="")
    parser.add_argument("--grid-command", default="")
    parser.add_argument("--results", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "RESULTS.md"))
    args = parser.parse_args()

    with open(args.table1) as f:
        data = json.load(f)
    lines = [BEGIN, "", f'_Generated by make_results.py from {os.path.basename(args.table1)}; '
                        'do not edit by hand between the markers._', ""]
    lines += table1_section(data)
    for variant in args.variant:
        label, _, path = variant.partition("=")
        with open(path) as f:
            lines += table1_section(json.load(f), label)
    lines += convergence_section(data)
    lines += solver_section(data)
    lines += limits_section(data)
    lines += machine_section(data, args.command)
    if args.grid:
        with open(args.grid) as f:
            lines += grid_section(json.load(f), args.grid_command)
    lines.append(END)
    generated = "\n".join(lines) + "\n"

    if os.path.exists(args.results):
        with open(args.results) as f:
            text = f.read()
        if BEGIN in text and END in text:
            head, rest = text.split(BEGIN, 1)
            tail = rest.split(END, 1)[1]
            text = head + generated.rstrip("\n") + tail
        else:
            text = text.rstrip("\n") + "\n\n" + generated
    else:
        text = "# Benchmark results\n\n" + generated
    with open(args.results, "w") as f:
        f.write(text)
    print(f"make_results.py: wrote {args.results}", file=sys.stderr)


if __name__ == "__main__":
    main()
