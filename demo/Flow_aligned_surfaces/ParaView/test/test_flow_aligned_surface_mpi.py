"""Flow-Aligned Surface on 2 MPI ranks (mpiexec -n 2 pvbatch --mpi, see CMakeLists.txt): with the
input spread over the ranks the surface is the library's (the serial filter's reference) to 1e-9
of its diagonal; rank 0 holds it, rank 1 outputs nothing (the fetched output would otherwise hold
its points twice).  Pieces: the reader's own image pieces (split at x = 0, which the patch
crosses; a patch in rank 0's piece alone costs no exchange), RedistributeDataSet's unstructured
pieces, and the bad inputs "a rank holds no cells" (a correct result), "no rank holds cells" and
"a rank's piece has no velocity" (a clear message, the previous output kept, no hang), and
Abort."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
ranks = t.number_of_ranks()
if ranks != 2:
    raise AssertionError("run on 2 ranks (mpiexec -n 2 pvbatch --mpi), not %d" % ranks)

# A patch across the plane x = 0 where the reader splits the image between the ranks; it needs
# about 20 iterations (every one a collective exchange) before it converges.
CENTER, NORMAL, SIZE, FACES, ITERATIONS = [0.0, 1.6, 0.1], [1.0, 0.3, 0.2], 0.8, 800, 25


def reference(name, alignment, iterations, center=CENTER):
    vtp = setup.path(name + ".vtp")
    setup.run_reference("align", setup.field(), vtp, *center, *NORMAL, SIZE, FACES, "planar", alignment,
                        iterations)
    return t.read_polydata(vtp)


def surface_of(source, alignment, center=CENTER):
    surface = FlowAlignedSurface(Input=source)
    surface.Velocity = ["POINTS", "velocity"]
    surface.Center = center
    surface.Normal = NORMAL
    surface.Size = SIZE
    surface.NumberOfFaces = FACES
    surface.Alignment = alignment
    surface.NumberOfIterations = ITERATIONS
    return surface


def expect_field_value(out, name, expected, what):
    value = t.field_value(out, name)
    if value != expected:
        raise AssertionError("%s: %s is %g, expected %g" % (what, name, value, expected))


tangential = reference("tangential", "tangential", ITERATIONS)
reader = XMLImageDataReader(FileName=[setup.field()])

# 1. The reader's image pieces: both ranks hold cells and both supply samples of the final surface.
surface = surface_of(reader, "Tangential (stream surface)")
out = t.fetch(surface, ITERATIONS)
t.expect_same_surface(out, tangential, "2 ranks, image pieces, iteration %d" % ITERATIONS)
expect_field_value(out, "number_of_ranks", 2, "image pieces")
expect_field_value(out, "number_of_ranks_with_cells", 2, "image pieces")
expect_field_value(out, "number_of_sampling_ranks", 2, "image pieces")
if not t.field_value(out, "iterations_computed") >= 10:
    raise AssertionError("expected at least 10 iterations (exchanges), got %g" % t.field_value(out, "iterations_computed"))
print("exchange %.3g ms, step %.3g ms per iteration" % (
    t.field_value(out, "exchange_ms_per_iteration"), t.field_value(out, "step_ms_per_iteration")))
# A time step played back: kept iterations, only the output's samples are exchanged.
t.expect_same_surface(t.fetch(surface, 3), reference("tangential_3", "tangential", 3),
                      "2 ranks, image pieces, iteration 3 (time step 3)")
# Orthogonal: the potential's level set through x = 0 is the plane x = 0, the very plane where
# the two image pieces meet (samples found on both ranks).
surface.Alignment = "Orthogonal (seeding surface)"
t.expect_same_surface(t.fetch(surface, ITERATIONS), reference("orthogonal", "orthogonal", ITERATIONS),
                      "2 ranks, image pieces, orthogonal")
Delete(surface)

# A patch in rank 0's piece alone (x < 0, 1.1 away from the cut): rank 0 samples it itself, so
# neither the iterations nor the output cost an exchange, and the surface is the library's.
LEFT = [-1.5, 1.6, 0.1]
surface = surface_of(reader, "Tangential (stream surface)", LEFT)
out = t.fetch(surface, ITERATIONS)
t.expect_same_surface(out, reference("left", "tangential", ITERATIONS, LEFT), "2 ranks, in rank 0's piece alone")
expect_field_value(out, "number_of_exchanges", 0, "in rank 0's piece alone")
expect_field_value(out, "number_of_sampling_ranks", 1, "in rank 0's piece alone")
Delete(surface)

# 2. RedistributeDataSet's pieces (unstructured grids: the cell-locator sampler), tangential.
redistributed = RedistributeDataSet(Input=reader)
surface = surface_of(redistributed, "Tangential (stream surface)")
out = t.fetch(surface, ITERATIONS)
t.expect_same_surface(out, tangential, "2 ranks, redistributed, tangential")
expect_field_value(out, "number_of_ranks_with_cells", 2, "redistributed")
expect_field_value(out, "number_of_sampling_ranks", 2, "redistributed")
Delete(surface)

# 3. Bad input: a rank holds no cells.  Rank 0 (which holds the surface) has none and rank 1
# the whole image: every sample comes from rank 1, and the result is still the library's.
pieces = ProgrammableSource(OutputDataSetType="vtkUnstructuredGrid")
pieces.Script = t.flow_on_one_rank(1, "all", setup.field())
surface = surface_of(pieces, "Tangential (stream surface)")
out = t.fetch(surface, ITERATIONS)
t.expect_same_surface(out, tangential, "rank 0 holds no cells")
expect_field_value(out, "number_of_ranks_with_cells", 1, "rank 0 holds no cells")
expect_field_value(out, "number_of_sampling_ranks", 1, "rank 0 holds no cells")

# 4. Bad input: no rank holds cells, then a rank whose piece has no velocity array: a message
# that says so, and the previous output kept.
for mode, expected_message in [("none", "the input has no cells on any of the 2 ranks"),
                               ("no velocity", "rank 1: ")]:
    pieces.Script = t.flow_on_one_rank(1, mode, setup.field())
    with t.Messages() as messages:
        kept = t.fetch(surface, ITERATIONS)
    t.expect_message(messages, [expected_message, "the previous output is kept"], mode)
    t.expect_same_surface(kept, tangential, "%s: the previous output" % mode)

# And the data back on rank 1: the surface again.
pieces.Script = t.flow_on_one_rank(1, "all", setup.field())
t.expect_same_surface(t.fetch(surface, ITERATIONS), tangential, "data back on rank 1")
Delete(surface)

# 5. Abort (ParaView's Abort button sets it on rank 0's filter; here a progress observer does):
# rank 0 stops after the iteration in progress and releases rank 1, the output is the library's
# surface of that iteration, and the next time step asked for goes on from there.
surface = surface_of(reader, "Tangential (stream surface)")
with t.AbortOnce(surface, lambda progress: progress > 0.3) as abort, t.Messages() as messages:
    cancelled = t.fetch(surface, ITERATIONS)
aborts = abort.progress
t.expect_message(messages, ["cancelled after iteration"], "abort on 2 ranks")
stopped_at = int(t.field_value(cancelled, "iteration"))
if not 1 <= stopped_at < ITERATIONS:
    raise AssertionError("abort at progress %s on 2 ranks: the output shows iteration %d" % (aborts, stopped_at))
t.expect_same_surface(cancelled, reference("tangential_stopped", "tangential", stopped_at),
                      "2 ranks, aborted at iteration %d" % stopped_at)
t.expect_same_surface(t.fetch(surface, ITERATIONS - 1),
                      reference("tangential_after_stop", "tangential", ITERATIONS - 1), "2 ranks, after the abort")
print("Flow-Aligned Surface on 2 ranks: all checks passed (abort stopped at iteration %d)" % stopped_at)
