"""The filters on a temporal input in pvbatch (on one process, and on 2 MPI ranks): a swirl whose
axis drifts, v = (-y, x - 0.2 t, 0.3), written as a .pvd of 5 steps t = 0, 0.25, ..., 1 by
paraview_reference unsteady_field, read by ParaView's PVD reader.

- The outputs have the data's time steps (the time controls play the data).
- The flow is sampled at the requested time, interpolated linearly between the steps: the
  surface's `velocity` array is v at that time (exact here, the swirl being linear in space and
  time, up to the files' float32).
- Flow-Aligned Surface follows the flow: the surface at time t is the library's surface aligned at
  the first step and re-aligned at each later step up to t (paraview_reference follow), to 1e-9
  of its size; it lies on the cylinder of radius 1 - 0.2 t about the axis of time t; playing the
  steps and jumping straight to a time give the same surface, bit for bit; a step followed once
  is not followed again; one factorization throughout.
- Stream Surface From Curve integrates the flow of the requested time: every vertex keeps the
  distance of its seed point to the axis of that time.
- Parametrize And Seed and Grow Boundary at a step's time give what they give on that step's
  own file read as a steady data set, and something else at the other end of the series.
- A path surface of one time step is refused, saying why.
- Through RedistributeDataSet and a Temporal Cache of every step (what the manual recommends for
  a time series spread over the ranks), a path surface is the one without the cache, bit for bit,
  its vertices on their path lines; a second Flow-Aligned Surface on the cache builds fewer
  velocity fields than without it (it takes those of the cached pieces that the first still
  holds), where each step comes from RedistributeDataSet anew; each filter there says once that a
  Temporal Cache would keep the steps.
"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import math
import os
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
pvd = setup.path("swirl.pvd")
if not os.path.exists(pvd):
    setup.run_reference("unsteady_field", pvd)
data = PVDReader(FileName=pvd)
times = list(data.TimestepValues)
if times != [0.0, 0.25, 0.5, 0.75, 1.0]:
    raise AssertionError("the swirl's time steps are %s" % times)
PATCH = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.6, 2000]
ITERATIONS = 100


def axis_x(time):
    return 0.2 * time


def follows_the_flow(flow=data):
    s = FlowAlignedSurface(Input=flow)
    s.Velocity = ["POINTS", "velocity"]
    s.Center, s.Normal, s.Size, s.NumberOfFaces = PATCH[0:3], PATCH[3:6], PATCH[6], PATCH[7]
    s.Alignment = "Tangential (stream surface)"
    s.NumberOfIterations = ITERATIONS
    return s


def expect_velocity_at(out, time, what):
    """The output's point array `velocity` is the swirl at `time`."""
    velocity = out.GetPointData().GetArray("velocity")
    worst = 0.0
    for i in range(out.GetNumberOfPoints()):
        x, y, z = out.GetPoint(i)
        exact = (-y, x - axis_x(time), 0.3)
        worst = max(worst, max(abs(velocity.GetComponent(i, c) - exact[c]) for c in range(3)))
    if not worst <= 1e-5:
        raise AssertionError("%s: the velocity differs from the flow at t = %g by %g" % (what, time, worst))


def largest_distance_from_cylinder(out, time, radius):
    return max(abs(math.hypot(out.GetPoint(i)[0] - axis_x(time), out.GetPoint(i)[1]) - radius)
               for i in range(out.GetNumberOfPoints()))


def points_of(out):
    return [out.GetPoint(i) for i in range(out.GetNumberOfPoints())]


# 1. Played step by step: each update follows one step more.
played = follows_the_flow()
played.UpdatePipeline(times[0])
if list(played.TimestepValues) != times:
    raise AssertionError("Flow-Aligned Surface's time steps are %s, not the data's" % list(played.TimestepValues))
for time in times:
    out = t.fetch(played, time)
    t.expect_spread_over_ranks(out, "played to t = %g" % time)
    if t.field_value(out, "time") != time or t.field_value(out, "time_steps_followed_in_update") != 1:
        raise AssertionError("played to t = %g: time %g, %g steps followed" % (
            time, t.field_value(out, "time"), t.field_value(out, "time_steps_followed_in_update")))
    expect_velocity_at(out, time, "played to t = %g" % time)
    d = largest_distance_from_cylinder(out, time, 1 - axis_x(time))
    if not d <= 2e-2:
        raise AssertionError("played to t = %g: a vertex is %g off the cylinder about the axis" % (time, d))
at_the_end = points_of(out)

# 2. Between two steps, and against the library.
for time in [0.6, 1.0]:
    out = t.fetch(played, time)
    expect_velocity_at(out, time, "t = %g" % time)
    reference = setup.path("followed_%g.vtp" % time)
    setup.run_reference("follow", pvd, reference, *PATCH, "planar", "tangential", ITERATIONS, time)
    t.expect_same_surface(out, t.read_polydata(reference), "followed to t = %g" % time)
if t.field_value(out, "number_of_factorizations") != 1:
    raise AssertionError("%g factorizations" % t.field_value(out, "number_of_factorizations"))

# 3. Jumping straight to the end follows every step in one update and gives the same surface;
# back to an earlier time, nothing is followed again.
jumped = follows_the_flow()
out = t.fetch(jumped, times[-1])
if t.field_value(out, "time_steps_followed_in_update") != len(times):
    raise AssertionError("the jump followed %g steps" % t.field_value(out, "time_steps_followed_in_update"))
if points_of(out) != at_the_end:
    raise AssertionError("jumping to t = 1 gives another surface than playing to it")
out = t.fetch(jumped, times[1])
if t.field_value(out, "time_steps_followed_in_update") != 0:
    raise AssertionError("going back followed %g steps" % t.field_value(out, "time_steps_followed_in_update"))
print("the surface at a time does not depend on how it was reached")

# 4. Stream Surface From Curve at t = 0.5: the helicoids about the axis of that time.
line = Line(Point1=[0.4, 0.0, 0.0], Point2=[0.9, 0.0, 0.0], Resolution=10)
stream = StreamSurfaceFromCurve(Input=data, Seeds=line)
stream.Velocity = ["POINTS", "velocity"]
stream.MaxTime = 2.0
stream.TimeLineStep = 0.1  # 20 time lines: on 2 ranks every particle's sample is an exchange
out = t.fetch(stream, 0.5)
if list(stream.TimestepValues) != times:
    raise AssertionError("Stream Surface From Curve's time steps are %s" % list(stream.TimestepValues))
u = out.GetPointData().GetArray("u")
worst = 0.0
for i in range(out.GetNumberOfPoints()):
    seed_radius = 0.4 + u.GetValue(i) - axis_x(0.5)
    p = out.GetPoint(i)
    worst = max(worst, abs(math.hypot(p[0] - axis_x(0.5), p[1]) - seed_radius))
if out.GetNumberOfCells() == 0 or not worst <= 1e-3:
    raise AssertionError("stream surface at t = 0.5: %d faces, a vertex %g off its seed's cylinder" % (
        out.GetNumberOfCells(), worst))
print("stream surface at t = 0.5: radii kept within %.2g on %d vertices" % (worst, out.GetNumberOfPoints()))

# 5. Path surfaces: the seed line released at t0 = 0.25 and integrated up to the view's time;
# every vertex is where the exact path line of its seed point is after its time t (the swirl's
# path lines: x = A cos s + B sin s + 0.2 s, y = A sin s - B cos s - 0.2, z = z0 + 0.3 (s - t0)).
def path_line_point(seed, t0, tau):
    X, Y = seed[0] - 0.2 * t0, seed[1] + 0.2
    A, B = X * math.cos(t0) + Y * math.sin(t0), X * math.sin(t0) - Y * math.cos(t0)
    s = t0 + tau
    return (A * math.cos(s) + B * math.sin(s) + 0.2 * s, A * math.sin(s) - B * math.cos(s) - 0.2, seed[2] + 0.3 * tau)


def path_surface_of(flow):
    p = StreamSurfaceFromCurve(Input=flow, Seeds=line)
    p.Velocity = ["POINTS", "velocity"]
    p.SurfaceType = "Path Surface"
    p.StartTime = 0.25
    p.TimeLineStep = 0.05
    return p


path = path_surface_of(data)
out = t.fetch(path, 0.25)
if out.GetNumberOfCells() != 0:
    raise AssertionError("a path surface at its start time has %d faces" % out.GetNumberOfCells())
def expect_on_path_lines(out, view_time, duration, what):
    """Every vertex of the path surface `out`, released at 0.25 and seen at `view_time`, is on the
    path line of its seed point, and the oldest have travelled `duration`."""
    if out.GetNumberOfCells() == 0 or t.field_value(out, "start_time") != 0.25:
        raise AssertionError("%s at %g: %d faces" % (what, view_time, out.GetNumberOfCells()))
    u, tau = out.GetPointData().GetArray("u"), out.GetPointData().GetArray("t")
    worst, longest = 0.0, 0.0
    for i in range(out.GetNumberOfPoints()):
        exact = path_line_point((0.4 + u.GetValue(i), 0.0, 0.0), 0.25, tau.GetValue(i))
        worst = max(worst, math.dist(out.GetPoint(i), exact))
        longest = max(longest, tau.GetValue(i))
    if not worst <= 1e-5 or abs(longest - duration) > 1e-9:
        raise AssertionError("%s at %g: a vertex %g off its path line, t up to %g" % (what, view_time, worst, longest))
    print("%s at %g: %d vertices on their path lines within %.2g" % (what, view_time, out.GetNumberOfPoints(), worst))


for view_time, duration in [(0.6, 0.35), (1.0, 0.75)]:
    expect_on_path_lines(t.fetch(path, view_time), view_time, duration, "path surface")

# 6. Flow Texture on the path surface at t = 1: with Path Surface on it follows the path lines
# (the flow at start_time + t of each point), so that its mask (the angle between the flow it
# measures against and the gradient of r) is smaller than in the flow of the view's time alone.
def mean_mask(path_surface_on):
    texture = FlowTexture(Input=data, Surface=path)
    texture.Velocity = ["POINTS", "velocity"]
    texture.PathSurface = path_surface_on
    texture.UpdatePipeline(1.0)
    out = servermanager.Fetch(texture, idx=0)
    mask = out.GetCellData().GetArray("texture_mask")
    return sum(mask.GetValue(i) for i in range(mask.GetNumberOfTuples())) / mask.GetNumberOfTuples()


along_paths, at_one_time = mean_mask(1), mean_mask(0)
print("Flow Texture on the path surface: mean mask %.3g along the path lines, %.3g in the flow of t = 1" % (
    along_paths, at_one_time))
if not along_paths < 0.9 * at_one_time:
    raise AssertionError("Flow Texture with Path Surface on does not follow the path lines better than the flow of t = 1")

# At the release time the path surface has no face yet: Flow Texture gives an empty surface and
# says nothing is wrong.
texture = FlowTexture(Input=data, Surface=path)
texture.Velocity = ["POINTS", "velocity"]
texture.PathSurface = 1
with t.Messages() as messages:
    texture.UpdatePipeline(0.25)
out = servermanager.Fetch(texture, idx=0)
if out.GetNumberOfCells() != 0 or "Flow Texture" in messages.text():
    raise AssertionError("Flow Texture at the release time: %d faces, messages %r" % (out.GetNumberOfCells(), messages.text()))


# 7. Parametrize And Seed and Grow Boundary sample the flow of the requested time: at a step's
# time each gives what it gives on that step's own file read as a steady data set, and at the
# other end of the series something else.  Their surface: the one Flow-Aligned Surface followed
# to t = 0.5, as a file.
surface_file = setup.path("followed_surface.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetFileName(surface_file)
writer.SetDataModeToAscii()  # (appended data: not read by ParaView's VTK with bookworm's expat)
writer.SetInputData(t.fetch(played, 0.5))
writer.Write()
surface = XMLPolyDataReader(FileName=[surface_file])


def expect_the_steps_flow(make, values, what):
    """`make(input)` is a filter of `surface` in the flow of `input`: on the series at t = 0.25 and
    t = 1, `values(output)` (a list of numbers) is what it is on the step's file, and differs
    between the two times."""
    temporal = make(data)
    at_steps = {}
    for time, step_file in [(0.25, "swirl_1.vti"), (1.0, "swirl_4.vti")]:
        at_steps[time] = values(t.fetch(temporal, time))
        on_step = values(t.fetch(make(XMLImageDataReader(FileName=[setup.path(step_file)]))))
        if len(on_step) != len(at_steps[time]) or max(abs(a - b) for a, b in zip(on_step, at_steps[time])) > 1e-9:
            raise AssertionError("%s at t = %g differs from its output on %s" % (what, time, step_file))
    early, late = at_steps[0.25], at_steps[1.0]
    difference = max([abs(a - b) for a, b in zip(early, late)] + [float(len(early) != len(late))])
    print("%s at t = 0.25 and t = 1: the steps' own outputs; they differ by %.3g" % (what, difference))
    if not difference > 1e-4:  # far above the 1e-9 of the comparison with the steps
        raise AssertionError("%s gives the same output at t = 0.25 and t = 1" % what)
    if list(temporal.TimestepValues) != times:
        raise AssertionError("%s's time steps are %s" % (what, list(temporal.TimestepValues)))


def parametrize(flow):
    p = ParametrizeAndSeed(Input=flow, Surface=surface)
    p.Velocity = ["POINTS", "velocity"]
    return p


def grow(flow):
    g = GrowBoundary(Input=flow, Surface=surface)
    g.Velocity = ["POINTS", "velocity"]
    g.Alignment = "Tangential (stream surface)"
    g.GrowthMode = "Across the flow"
    g.Distance = 0.1
    g.NumberOfIterations = 20
    return g


expect_the_steps_flow(parametrize, lambda out: [v[0] for v in t.array_values(out, "r")], "Parametrize And Seed")
expect_the_steps_flow(grow, lambda out: [x for p in points_of(out) for x in p], "Grow Boundary")

# 8. A path surface of a single time step (one step's own file) is refused, saying why.
single = StreamSurfaceFromCurve(Input=XMLImageDataReader(FileName=[setup.path("swirl_1.vti")]), Seeds=line)
single.Velocity = ["POINTS", "velocity"]
single.SurfaceType = "Path Surface"
with t.Messages() as messages:
    single.UpdatePipeline()
t.expect_message(messages, ["Surface Type is Path Surface, but the Input has no time steps"],
                 "a path surface of one time step")


# 9. The manual's pipeline for a time series over MPI ("Distributed Data (MPI)"):
# RedistributeDataSet (the pieces become unstructured grids, new ones at every step asked for)
# followed by a Temporal Cache of every step.
spread = RedistributeDataSet(Input=data)
cached = TemporalCache(Input=spread, CacheSize=len(times))


on_spread = t.fetch(path_surface_of(spread), 1.0)
first_on_cache = path_surface_of(cached)
on_cache = t.fetch(first_on_cache, 1.0)
if on_cache.GetNumberOfCells() == 0 or points_of(on_cache) != points_of(on_spread):
    raise AssertionError("the path surface through the Temporal Cache (%d faces) is not the one without it" %
                         on_cache.GetNumberOfCells())
expect_on_path_lines(on_cache, 1.0, 0.75, "path surface through RedistributeDataSet and the cache")


def fields_built_by_a_second_follower(flow):
    """The velocity fields a Flow-Aligned Surface following `flow` to t = 1 builds while another
    one that did the same is still there."""
    first = follows_the_flow(flow)
    t.fetch(first, 1.0)
    return t.field_value(t.fetch(follows_the_flow(flow), 1.0), "number_of_velocity_fields_built")


# A filter that follows the steps of a Redistribute DataSet says, once, that a Temporal Cache
# would keep them; not on the cache.
with t.Messages() as on_spread_messages:
    built_on_spread = fields_built_by_a_second_follower(spread)
with t.Messages() as on_cache_messages:
    built_on_cache = fields_built_by_a_second_follower(cached)
hint = "a Temporal Cache (Filters > Temporal) right after it would keep them"
if on_spread_messages.text().count(hint) != 2 or hint in on_cache_messages.text():
    raise AssertionError("the note on a Temporal Cache, once for each of two filters on RedistributeDataSet and "
                         "not on the cache: without the cache %r, with it %r" % (
                             on_spread_messages.text(), on_cache_messages.text()))
t.expect_message(on_spread_messages, ["Flow-Aligned Surface: the input is a Redistribute DataSet"],
                 "the note on a Temporal Cache")
print("a second Flow-Aligned Surface built %g velocity fields without the cache, %g with it" % (
    built_on_spread, built_on_cache))
if not built_on_cache < built_on_spread:
    raise AssertionError("on the Temporal Cache a second Flow-Aligned Surface built %g fields, without it %g" %
                         (built_on_cache, built_on_spread))
