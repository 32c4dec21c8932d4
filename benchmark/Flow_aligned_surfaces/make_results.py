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
import re
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

# bench_deformation labels its solver configurations; the default's configurations carry the
# label "supernodal_llt" of the class that Cholmod_LDLT_swept (internal/solver/) replaced.  The
# tables print the current names.
OLD_DEFAULT_LABEL = "supernodal_llt"
DEFAULT_LABEL = "cholmod_ldlt_swept"
DISPLAY = {
    DEFAULT_LABEL: "`Cholmod_LDLT_swept`",
    DEFAULT_LABEL + "_double_corrections": "double corrections",
    DEFAULT_LABEL + "_float": "float factor",
    DEFAULT_LABEL + "_parallel": "parallel sweeps",
    DEFAULT_LABEL + "_metis": "METIS ordering",
    "cholmod_simplicial_ldlt": "CHOLMOD simplicial LDLᵀ",
    "cholmod_supernodal": "CHOLMOD supernodal LLᵀ",
    "cholmod_auto_ldlt": "CHOLMOD's own choice",
    "eigen_simplicial_ldlt": "Eigen `SimplicialLDLT`",
    "warm_conjugate_gradient": "warm conjugate gradient",
}
# The peers of the default in the solver table, in this order; every other configuration is a
# variant of the default (the same factor, or the same solver with another ordering).
PEERS = ["cholmod_simplicial_ldlt", "cholmod_supernodal", "cholmod_auto_ldlt", "eigen_simplicial_ldlt",
         "warm_conjugate_gradient"]


def label(name):
    """A configuration's label under the current class names."""
    if name == OLD_DEFAULT_LABEL or name.startswith(OLD_DEFAULT_LABEL + "_"):
        return DEFAULT_LABEL + name[len(OLD_DEFAULT_LABEL):]
    return name


def display(name):
    name = label(name)
    return DISPLAY.get(name, f"`{name}`")


# What the configurations are today, where bench_deformation's own description is that of the
# class the default replaced.
DESCRIPTIONS = {
    DEFAULT_LABEL: "the package's default: CHOLMOD simplicial LDLᵀ (CHOLMOD's default ordering strategy), "
                   "CHOLMOD's solve below 3e6 nonzeros of the factor and supernodal sweeps of the factor "
                   "in place above, the iterations' corrections with a single-precision copy from 1e6 nonzeros",
}


def describe_solver(name, text):
    return DESCRIPTIONS.get(label(name), describe(text))


def describe(text):
    """A JSON description with the old class name and labels replaced by the current ones."""
    text = text.replace("the package's Supernodal_LLT: ", "the package's default: ")
    text = text.replace("the package's Cholmod_LDLT_swept: ", "the package's default: ")
    text = text.replace("Supernodal_LLT", "Cholmod_LDLT_swept")
    return re.sub(r"\bsupernodal_llt\w*", lambda m: display(m.group(0)).strip("`"), text)


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
    solver = display(sizes[0]["default_solver"]).strip("`") if sizes else "?"
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
    out.append("Targets: FACTOR ≤ paper/5, IT/s ≥ 3 × paper, NCONV ≤ paper (both alignments); ×: ours "
               "divided by the target.  The wall-clock rate times whole `step()` calls, which also write the "
               "positions back and measure the step; IT/s is the paper's 1000 / (GTRANSF + SOLVE).\n")
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
    return out


def convergence_section(data):
    out = ["### Convergence from the fixed starts\n"]
    setup = data["setup"]
    out.append(f'Field: {setup["field"]}.  Patch: {setup["patch"]}.  '
               f'Orthogonal start: {setup["start_orthogonal"]}.  Tangential start: {setup["start_tangential"]}.  '
               f'Convergence: {setup["convergence"]}; at most {setup["max_iterations"]} iterations.\n')
    out.append("| faces | orthogonal: NCONV, rule | f_n start → end | last rotation (rad) "
               "| tangential: NCONV, rule | f_n start → end | last rotation (rad) |")
    out.append("|---:|---|---|---:|---|---|---:|")
    for s in data["sizes"]:
        cells = []
        for name in ("orthogonal", "tangential"):
            a = s["by_alignment"][name]
            rule = a["rule"] if a["converged"] else "not converged"
            cells.append(f'{a["nconv"]}, {rule} | {a["initial_flux"]:.4f} → {a["final_flux"]:.6f} '
                         f'| {a["last_max_rotation_angle"]:.2e}')
        out.append(f'| {s["faces"]:,} | ' + " | ".join(cells) + " |")
    out.append("")
    return out


def solver_section(data):
    """One row per mesh: the default, its variants and its peers side by side."""
    sizes = data["sizes"]
    if not sizes:
        return []
    names = [label(c["name"]) for c in sizes[0]["solvers"]]
    default = label(sizes[0]["default_solver"])
    peers = [n for n in PEERS if n in names and n != default]
    variants = [n for n in names if n != default and n not in peers]
    first = {label(c["name"]): c for c in sizes[0]["solvers"]}
    # A variant that keeps the default's ordering has the default's factor: only its SOLVE differs.
    same_factor = {n for n in variants if default in first and first[n]["ordering"] == first[default]["ordering"]}
    out = ["### Sparse Cholesky solvers on the same matrix L + W\n"]
    out.append('Cells: FACTOR / SOLVE ms (FACTOR = symbolic analysis + numeric factorization, wall clock; '
               f'SOLVE = median of {data["setup"]["solver_steps"]} iterations, the three coordinates at once); '
               "SOLVE only for the default's variants that keep its factor.  nnz(L), flops and the "
               "analysis time are the default's (CHOLMOD's counts).  Fastest FACTOR and SOLVE of a row in bold.\n")
    columns = [default] + variants + peers
    out.append("| faces | nnz(L) | flops | analysis ms | " + display(default) + " (default) | "
               + " | ".join(display(n) for n in columns[1:]) + " |")
    out.append("|---:|---:|---:|---:|" + "---:|" * len(columns))
    for s in sizes:
        c = {label(x["name"]): x for x in s["solvers"]}
        present = [n for n in columns if n in c]
        best_factor = min(c[n]["factor_ms"] for n in present if n not in same_factor)
        best_solve = min(c[n]["solve_ms"] for n in present)

        def cell(n):
            if n not in c:
                return "–"
            sv = fmt(c[n]["solve_ms"])
            sv = f"**{sv}**" if c[n]["solve_ms"] == best_solve else sv
            if n in same_factor:
                return sv
            f = fmt(c[n]["factor_ms"])
            f = f"**{f}**" if c[n]["factor_ms"] == best_factor else f
            return f"{f} / {sv}"

        d = c.get(default, {})
        nnz = fmt(d["nnz_L"]) if d.get("nnz_L", -1) not in (None, -1) else "–"
        flops = fmt(d["flops"]) if d.get("flops", -1) not in (None, -1) else "–"
        out.append(f'| {s["faces"]:,} | {nnz} | {flops} | {fmt(d.get("analyze_ms"))} | '
                   + " | ".join(cell(n) for n in columns) + " |")
    out.append("")
    out.append("Solvers: " + "; ".join(
        f'{display(n)}: {describe_solver(n, first[n]["description"]).replace(" (package default)", "")}'
        for n in columns) + ".\n")
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
    default_name = display(data["sizes"][0]["default_solver"]) if data["sizes"] else "?"
    out.append(f'Read bandwidth measured in this run (one thread streaming 256 MiB, median of 5): '
               f'{fmt(bandwidth)} GB/s before the sizes, {fmt(after)} GB/s after; '
               f'{fmt(m.get("read_bandwidth_gb_s_all_threads"))} GB/s on all {m["hardware_threads"]} threads.  '
               f'Bytes: the factor of {default_name} read by the two sweeps of one solve (values and row '
               'indices), the least any direct solve with this factor must stream; bound = bytes / bandwidth.  '
               'The parallel columns repeat the orthogonal run with `use_parallelism(true)` '
               '(TBB over the faces and over independent subtrees of the elimination tree).\n')
    out.append("| faces | nnz(L) | MB per solve | bound ms | SOLVE ms | SOLVE / bound "
               "| parallel GTRANSF ms | parallel SOLVE ms | parallel IT/s | parallel / serial IT/s |")
    out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for s in data["sizes"]:
        default = next((c for c in s["solvers"] if c["name"] == s["default_solver"]), None)
        if default is None or default.get("bytes_per_solve", -1) in (None, -1):
            continue
        mb = default["bytes_per_solve"] / 1e6
        bound = default["bytes_per_solve"] / (bandwidth * 1e6)
        par = s.get("parallel")
        par_cells = (f'| {fmt(par["gtransf_ms"])} | {fmt(par["solve_ms"])} | {fmt(par["its_per_s"])} '
                     f'| {fmt(par["its_per_s"] / s["its_per_s"], 2)}× |') if par else "| – | – | – | – |"
        out.append(f'| {s["faces"]:,} | {fmt(default["nnz_L"])} | {fmt(mb)} | {fmt(bound)} '
                   f'| {fmt(s["solve_ms"])} | {fmt(s["solve_ms"] / bound, 2)}× {par_cells}')
    out.append("")
    return out


def grid_section(grid, command):
    out = ["### Grid sampling (bench_grid_sampling)\n"]
    ctx = grid.get("context", {})
    build = ctx.get("library_build_type", "")
    out.append(f'Google Benchmark ({build} build of the library{": its own overhead is included" if build == "debug" else ""}), '
               f'{ctx.get("num_cpus", "?")} CPUs at {ctx.get("mhz_per_cpu", "?")} MHz, load average '
               f'{", ".join(f"{x:.2f}" for x in ctx.get("load_avg", []))}.  One iteration is '
               'one query on a 128³ grid sampled from the ABC flow; 7 repetitions; target ≤ 50 ns at coherent positions.'
               + (f'  Command: `{command}`.' if command else "") + "\n")
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
                  else "CPU < wall: the process waited for a core; figures are noisier") + ').  '
               f'GCC {m["compiler"]}, CGAL {m["cgal"]}, Eigen {m["eigen"]}, CHOLMOD {m["cholmod"]}; '
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
