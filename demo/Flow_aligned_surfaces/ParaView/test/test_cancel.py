"""Abort (ParaView's Cancel) in Grow Boundary and Stream Surface From Curve, on one process and on
2 ranks: the filter stops with its message and shows what it computed so far, the ranks that
were serving it are released (never a hang: ctest gives this script 120 s, the whole run takes a
few), and the next update, without an abort, gives the full output again, the same as before.
On 2 ranks rank 0 runs the algorithm and the other rank answers its sample exchanges until rank
0 stops: the abort (set on rank 0's filter, as ParaView's Cancel does) must end both."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
ranks = t.number_of_ranks()
data = XMLImageDataReader(FileName=[setup.field()])


def cancelled_then_whole(proxy, name, change, restore, when, message):
    """`proxy`'s whole output; then, with `change` applied, an update aborted at the first
    progress `when` accepts, which must say `message` and show fewer points than the whole one;
    then, with `restore`, the whole output again."""
    whole = t.fetch(proxy)
    change()
    with t.AbortOnce(proxy, when) as abort, t.Messages() as messages:
        cancelled = t.fetch(proxy)
    if not abort.progress:
        raise AssertionError("%s: no progress event to abort at" % name)
    t.expect_message(messages, [message], "%s, aborted at progress %.2f on %d rank(s)" % (name, abort.progress[0], ranks))
    if not 0 < cancelled.GetNumberOfPoints() < whole.GetNumberOfPoints():
        raise AssertionError("%s: the aborted output has %d points, the whole one %d" % (
            name, cancelled.GetNumberOfPoints(), whole.GetNumberOfPoints()))
    restore()
    t.expect_same_surface(t.fetch(proxy), whole, "%s: after the abort" % name)
    print("%s on %d rank(s): aborted with %d of %d points, then whole again" % (
        name, ranks, cancelled.GetNumberOfPoints(), whole.GetNumberOfPoints()))


def setting(proxy, name, value):
    return lambda: setattr(proxy, name, value)


surface = setup.patch_in_cylinder_flow(data, 800, 25)
grow = GrowBoundary(Input=data, Surface=surface, Velocity=["POINTS", "velocity"], NumberOfGrowthSteps=3)
cancelled_then_whole(grow, "Grow Boundary", setting(grow, "NumberOfGrowthSteps", 4),
                     setting(grow, "NumberOfGrowthSteps", 3), lambda p: p > 0.3,
                     "Grow Boundary: cancelled after growth step")

line = Line(Point1=[-2.5, 0.3, -0.5], Point2=[-2.5, 1.5, 0.5], Resolution=20)
stream = StreamSurfaceFromCurve(Input=data, Seeds=line, Velocity=["POINTS", "velocity"], MaxNumberOfTimeLines=100)
cancelled_then_whole(stream, "Stream Surface From Curve", setting(stream, "MaxNumberOfTimeLines", 101),
                     setting(stream, "MaxNumberOfTimeLines", 100), lambda p: p > 0.3,
                     "Stream Surface From Curve: cancelled during seed curve")
