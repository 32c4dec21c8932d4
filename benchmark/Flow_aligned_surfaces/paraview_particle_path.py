"""ParaView's own particle tracer, ParticlePath (vtkPParticlePathFilter), on the seeds and data of
bench_path_surface, measured against the same reference path lines: the ParaView side of
"Path surfaces beside ParaView's ParticlePath" in RESULTS.md.

    pvbatch paraview_particle_path.py REFERENCE.txt [runs (7)] [BENCH_PATH_SURFACE]

With BENCH_PATH_SURFACE (the built program) the script first runs it (`runs` runs), which writes
REFERENCE.txt and prints our rows, and at the end times both sides in alternation; without it,
REFERENCE.txt must have been written by `bench_path_surface RUNS REFERENCE.txt`.

REFERENCE.txt holds the series, its time range, the seeds and each seed's path line integrated by
integrate_pathline() at tolerance 1e-12 at every step time of the series.  ParticlePath releases
the same seeds (double points, which are exact in float too) at the first step and runs to the
last (TerminationTime); it interpolates the image series trilinearly in space and linearly in
time, as our Unsteady_flow_field_3 does, and integrates with VTK's fixed-step RK4 at half a
data interval (vtkParticleTracerBase's IntegrationStep 0.5, not exposed in ParaView).  Its
output is one point per particle and data step, in float.

Rows, the median of `runs` runs each, wall time and the process's CPU time (all threads):
- PVDReader: reading the 34 steps alone (UpdatePipeline at every step time);
- ParticlePath on the PVDReader, its defaults: what a user pays, the reading included (the
  reader holds one step, so every run reads the series again);
- ParticlePath on a TemporalCache of all steps, filled before: the tracing alone, the figure
  to set beside our integration time (bench_path_surface times the integration with the series
  already in memory);
- the same with MeshOverTime Static and ComputeVorticity off, which suit a fixed grid and keep
  its path lines (the drift is the same).
A new ParticlePath proxy each run, so nothing is kept between runs.

The two programs cannot share a process, so on a shared machine their separate medians may come
from different spells of load.  The alternation puts them in the same spell: `runs` times, one
bench_path_surface with 3 runs (its medians) then one ParticlePath on the cache; the ratios
ParticlePath / ours of each pair, median and range, are printed last.

Drift: the distance of each output point after the release (ParticleAge > 0) to its seed's
reference at the point's SimulationTime, relative to the data's diagonal; median and max.
Float output rounds positions by up to 6e-8 (2.3e-8 of the diagonal): that is ParticlePath's
floor here.  No rendering, so no X server.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import builtins
import math
import os
import statistics
import subprocess
import sys
import time

SEED_SCRIPT = """
from vtkmodules.vtkCommonCore import vtkPoints, VTK_DOUBLE
from vtkmodules.vtkCommonDataModel import vtkCellArray
points = vtkPoints()
points.SetDataType(VTK_DOUBLE)
vertices = vtkCellArray()
for p in %r:
    vertices.InsertNextCell(1)
    vertices.InsertCellPoint(points.InsertNextPoint(p))
out = self.GetPolyDataOutput()
out.SetPoints(points)
out.SetVerts(vertices)
"""


def read_reference(path):
    r = {"seeds": [], "reference": {}}
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w or w[0].startswith("#"):
                continue
            if w[0] == "series":
                r["series"] = line.split(None, 1)[1].strip()
            elif w[0] in ("start", "end", "diagonal"):
                r[w[0]] = float(w[1])
            elif w[0] == "seed":
                r["seeds"].append(tuple(float(x) for x in w[2:5]))
            elif w[0] == "reference":
                r["reference"].setdefault(int(w[1]), []).append((float(w[2]), tuple(float(x) for x in w[3:6])))
    return r


def run_ours(program, runs, output):
    """bench_path_surface's output, and its rows by name: (wall ms, CPU ms)."""
    done = subprocess.run([program, str(runs), output], capture_output=True, text=True, check=True)
    rows = {}
    for line in done.stdout.splitlines():
        if line.startswith("path "):
            w = line[40:].split()
            rows[line[:40].strip()] = (float(w[0]), float(w[1]))
    return done.stdout, rows


def timed(f):
    w, c = time.perf_counter(), time.process_time()
    out = f()
    return 1e3 * (time.perf_counter() - w), 1e3 * (time.process_time() - c), out


def median_time(f, runs):
    results = [timed(f) for run in range(runs)]
    return (statistics.median(r[0] for r in results), statistics.median(r[1] for r in results), results[-1][2])


def particle_path(upstream, seeds, end, tuned):
    def run():
        tracer = ParticlePath(Input=upstream, SeedSource=seeds)
        tracer.SelectInputVectors = ["POINTS", "velocity"]
        tracer.TerminationTime = end
        if tuned:
            tracer.MeshOverTime = "Static"
            tracer.ComputeVorticity = 0
        tracer.UpdatePipeline(end)
        out = servermanager.Fetch(tracer)
        Delete(tracer)
        return out
    return run


def drift(paths, ref):
    ids = paths.GetPointData().GetArray("InjectedPointId")
    ages = paths.GetPointData().GetArray("ParticleAge")
    simulation_time = paths.GetPointData().GetArray("SimulationTime")
    d = []
    for i in range(paths.GetNumberOfPoints()):
        if ages.GetValue(i) <= 0:
            continue
        t = simulation_time.GetValue(i)
        ref_t, p = builtins.min(ref["reference"][int(ids.GetValue(i))], key=lambda r: abs(r[0] - t))
        if abs(ref_t - t) > 1e-9:
            raise AssertionError("no reference at t = %.9g (nearest %.9g)" % (t, ref_t))
        d.append(math.dist(paths.GetPoint(i), p) / ref["diagonal"])
    d.sort()
    return d


# Everything in functions, and the builtins named: in pvbatch the Programmable Source runs its
# script in this script's globals and leaves names there (min, ...) that replace ours.
def main():
    if len(sys.argv) < 2:
        raise RuntimeError("usage: pvbatch paraview_particle_path.py REFERENCE.txt [runs] [BENCH_PATH_SURFACE]")
    path = sys.argv[1]
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    program = sys.argv[3] if len(sys.argv) > 3 else None
    if program:
        stdout, _ = run_ours(program, runs, path)
        print(stdout, end="")
    ref = read_reference(path)

    seeds = ProgrammableSource(OutputDataSetType="vtkPolyData")
    seeds.Script = SEED_SCRIPT % (ref["seeds"],)
    reader = PVDReader(FileName=ref["series"])
    times = list(reader.TimestepValues)
    cache = TemporalCache(Input=reader)
    cache.CacheSize = len(times)
    for t in times:  # fills the cache (and the page cache) before any timing
        cache.UpdatePipeline(t)

    def read_all():
        for t in times:
            reader.UpdatePipeline(t)

    print("%s: %d steps, t = %.6f ... %.6f; %d seeds; median of %d runs" % (
        ref["series"], len(times), ref["start"], ref["end"], len(ref["seeds"]), runs))
    print("%-48s %9s %9s %8s %11s %11s %11s %8s" % ("tracer", "wall_ms", "cpu_ms", "points", "points/s", "drift_med",
                                                   "drift_max", "compared"))
    wall, cpu, _ = median_time(read_all, runs)
    print("%-48s %9.1f %9.1f" % ("PVDReader, the 34 steps (reading alone)", wall, cpu))
    for name, upstream, tuned in [("ParticlePath on PVDReader (reading included)", reader, False),
                                  ("ParticlePath on TemporalCache (tracing alone)", cache, False),
                                  ("ParticlePath, Static mesh, no vorticity, cached", cache, True)]:
        wall, cpu, paths = median_time(particle_path(upstream, seeds, ref["end"], tuned), runs)
        d = drift(paths, ref)
        n = paths.GetNumberOfPoints()
        print("%-48s %9.1f %9.1f %8d %11.4g %11.3g %11.3g %8d" % (name, wall, cpu, n, n / (wall * 1e-3),
                                                                d[len(d) // 2], d[-1], len(d)))
    if not program:
        return

    # Alternation: ParticlePath (tracing alone, defaults) over our rows, pair by pair.
    ratios = {}
    for run in range(runs):
        _, ours = run_ours(program, 3, os.devnull)
        wall, cpu, _ = timed(particle_path(cache, seeds, ref["end"], False))
        for name, (our_wall, our_cpu) in ours.items():
            ratios.setdefault(name, []).append((wall / our_wall, cpu / our_cpu))
    print("ParticlePath on TemporalCache / ours, %d alternating pairs: median (range)" % runs)
    for name, r in ratios.items():
        w = sorted(x[0] for x in r)
        c = sorted(x[1] for x in r)
        print("  / %-40s wall %6.2f (%.2f ... %.2f)   CPU %6.2f (%.2f ... %.2f)" % (
            name, statistics.median(w), w[0], w[-1], statistics.median(c), c[0], c[-1]))


main()
