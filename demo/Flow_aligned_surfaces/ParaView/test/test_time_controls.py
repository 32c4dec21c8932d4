"""The time controls over a pipeline on a steady flow: Flow-Aligned Surface's iterations are its
time steps, and the filters that take its surface (Grow Boundary, Parametrize And Seed, and so
on down the tutorial's chain) have the same time steps, so that ParaView's time keeper, which
leaves out the time steps of a filter's inputs, still offers the iterations; and a filter's output
at an iteration is made from the surface of that iteration."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
ITERATIONS = 10
iterations = [float(k) for k in range(ITERATIONS + 1)]
data = XMLImageDataReader(FileName=[setup.field()])
surface = setup.patch_in_cylinder_flow(data, 800, ITERATIONS)


def expect_iterations(proxy, name):
    proxy.UpdatePipelineInformation()  # its properties set after creation (Number Of Iterations)
    keeper = list(GetTimeKeeper().TimestepValues)
    own = list(proxy.TimestepValues)
    if keeper != iterations or own != iterations:
        raise AssertionError("after %s: the time keeper offers %s, the filter has %s; expected %s" % (
            name, keeper, own, iterations))
    print("%s: the time controls offer the %d iterations" % (name, ITERATIONS))


expect_iterations(surface, "Flow-Aligned Surface")
grow = GrowBoundary(Input=data, Surface=surface, Velocity=["POINTS", "velocity"], NumberOfIterations=5)
expect_iterations(grow, "Grow Boundary")
seeds = ParametrizeAndSeed(Input=data, Surface=grow, Velocity=["POINTS", "velocity"], NumberOfSeedCurves=1)
expect_iterations(seeds, "Parametrize And Seed")
stream = StreamSurfaceFromCurve(Input=data, Seeds=OutputPort(seeds, 1), Velocity=["POINTS", "velocity"],
                                MaxNumberOfTimeLines=20)
expect_iterations(stream, "Stream Surface From Curve")
texture = FlowTexture(Input=data, Surface=stream, Velocity=["POINTS", "velocity"])
expect_iterations(texture, "Flow Texture")

# The grown surface at the first iteration is grown from the patch itself, at the last from the
# aligned surface: they differ.
def differ(a, b):
    return a.GetNumberOfPoints() != b.GetNumberOfPoints() or t.max_point_distance(a, b) > 0


if not differ(t.fetch(surface, 0.0), t.fetch(surface, float(ITERATIONS))):
    raise AssertionError("Flow-Aligned Surface: the same surface at iterations 0 and %d" % ITERATIONS)
first, last = t.fetch(grow, 0.0), t.fetch(grow, float(ITERATIONS))
if first.GetNumberOfPoints() == 0 or not differ(first, last):
    raise AssertionError("Grow Boundary: the same output at iterations 0 and %d" % ITERATIONS)
print("Grow Boundary follows the iterations: its outputs at 0 and %d differ" % ITERATIONS)
