"""Every filter given a property out of its range: nothing is clamped silently; the message in the
Output Messages names the property as the panel shows it, its value and its range, and the
previous output is kept.  (Flow-Aligned Surface's own properties: test_flow_aligned_surface_bad_input.py.)"""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())
data = XMLImageDataReader(FileName=[setup.field()])
surface = setup.patch_in_cylinder_flow(data, faces=400, iterations=10)
seeds = ParametrizeAndSeed(Input=data, Surface=surface)
seeds.Velocity = ["POINTS", "velocity"]
seeds.NumberOfSeedCurves = 2
filters = {
    "Grow Boundary": (GrowBoundary(Input=data, Surface=surface, Distance=0.05, NumberOfIterations=5), [0]),
    "Parametrize And Seed": (seeds, [0, 1, 2]),
    "Stream Surface From Curve": (StreamSurfaceFromCurve(Input=data, Seeds=OutputPort(seeds, 1), MaxTime=0.5), [0]),
    "Flow Texture": (FlowTexture(Input=data, Surface=surface, TextureWidth=32, TextureHeight=32), [0, 1]),
}
for proxy, _ in filters.values():
    proxy.Velocity = ["POINTS", "velocity"]

cases = [
    ("Grow Boundary", "Distance", -0.05, "the property Distance is -0.05", ">= 0"),
    ("Grow Boundary", "NumberOfGrowthSteps", 0, "the property Number Of Growth Steps is 0", "from 1 to 1,000"),
    ("Grow Boundary", "MaxRotationAngle", 4.0, "the property Max Rotation Angle is 4", "(0, pi]"),
    ("Parametrize And Seed", "NumberOfSeedCurves", -1, "the property Number Of Seed Curves is -1", "from 0 to 100,000"),
    ("Parametrize And Seed", "SeedPointSpacing", -1.0, "the property Seed Point Spacing is -1", ">= 0"),
    ("Stream Surface From Curve", "TimeLineStep", -0.1, "the property Time Line Step is -0.1", ">= 0"),
    ("Stream Surface From Curve", "MaxNumberOfVertices", 0, "the property Max Number Of Vertices is 0", ">= 1"),
    ("Stream Surface From Curve", "TearAngle", 0.0, "the property Tear Angle is 0", "> 0"),
    ("Flow Texture", "TextureWidth", 0, "the property Texture Width is 0", "from 1 to 16,384"),
    ("Flow Texture", "MinRelativeSpeed", 2.0, "the property Min Relative Speed is 2", "in [0, 1]"),
]
for label, name, value, said, range_text in cases:
    proxy, ports = filters[label]
    good_value = proxy.GetPropertyValue(name)
    before = t.output_sizes(proxy, ports)
    if any(points == 0 for points, _ in before[:1]):
        raise AssertionError("%s: no output before the bad value" % label)
    proxy.SetPropertyWithName(name, value)
    t.expect_error_keeps_outputs(proxy, ports, before, [label, said, range_text], "%s %s = %s" % (label, name, value))
    proxy.SetPropertyWithName(name, good_value)
# A Velocity that names an array the input does not have (what a filter created in pvpython with
# keyword inputs only gets): the message names the property and lists the input's arrays.
before = t.output_sizes(seeds, [0, 1, 2])
seeds.Velocity = ["POINTS", "no_such_array"]
t.expect_error_keeps_outputs(seeds, [0, 1, 2], before,
                             ["Parametrize And Seed", "the property Velocity is 'no_such_array'",
                              "'velocity' (point data)"], "Velocity no_such_array")
seeds.Velocity = ["POINTS", "velocity"]
print("property ranges: all %d checks passed" % (len(cases) + 1))
