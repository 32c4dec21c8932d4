"""The filters of one flow share its velocity field (fas_field_cache.h): a chain of filters on the
same cells builds the field once, a first Apply builds it once (not in RequestInformation and
again in RequestData), a changed velocity array builds a new one, and a field no filter holds any
more is built anew.  Counted by the outputs' number_of_velocity_fields_built; the surfaces are
checked against the same filters on a copy of the flow that nothing shares."""
from paraview.simple import *  # first: an error before it would leave MPI ranks spinning

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fas_plugin_test as t

setup = t.Setup(globals())


def cells(scale):
    """The cylinder flow on tetrahedra (an unstructured grid: the field a cell hierarchy), its
    velocity times `scale` as the point array `flow`."""
    image = XMLImageDataReader(FileName=[setup.field()])
    scaled = Calculator(Input=Tetrahedralize(Input=image))
    scaled.ResultArrayName = "flow"
    scaled.Function = "%g*velocity" % scale
    return scaled


def flow_filter(proxy):
    proxy.Velocity = ["POINTS", "flow"]
    return proxy


def built(proxy, port=0):
    return t.field_value(t.fetch_port(proxy, port), "number_of_velocity_fields_built")


def expect_built(proxy, expected, what, port=0):
    got = built(proxy, port)
    if got != expected:
        raise AssertionError("%s: built %g velocity fields, expected %d" % (what, got, expected))


def chain(data):
    surface = flow_filter(setup.patch_in_cylinder_flow(data, 200, 5))
    grown = flow_filter(GrowBoundary(Input=data, Surface=surface))
    grown.Distance = 0.2
    return surface, grown


data = cells(2.0)
surface, grown = chain(data)
expect_built(surface, 1, "a first Apply of Flow-Aligned Surface")
expect_built(grown, 0, "Grow Boundary on the flow Flow-Aligned Surface sampled")
seeds = flow_filter(ParametrizeAndSeed(Input=data, Surface=grown))
expect_built(seeds, 0, "Parametrize And Seed on the same flow")
expect_built(seeds, 0, "Parametrize And Seed's seed curves", port=1)

# The same chain on a flow of its own (another reader: other arrays) builds its own field and
# computes the same surfaces.
other = cells(2.0)
other_surface, other_grown = chain(other)
expect_built(other_surface, 1, "Flow-Aligned Surface on a second reader of the same file")
t.expect_same_surface(t.fetch(grown), t.fetch(other_grown), "Grow Boundary on a shared field")

# A new velocity array (the calculator re-executes): a new field, and the surface of that flow.
data.Function = "3*velocity"
expect_built(grown, 0, "Grow Boundary after the velocity changed (Flow-Aligned Surface built it)")
expect_built(surface, 1, "Flow-Aligned Surface after the velocity changed")
fresh = cells(3.0)
fresh_surface, fresh_grown = chain(fresh)
t.expect_same_surface(t.fetch(grown), t.fetch(fresh_grown), "Grow Boundary after the velocity changed")

# Once no filter holds the field, the next filter builds it again.
for proxy in (seeds, grown, surface):
    Delete(proxy)
again = flow_filter(setup.patch_in_cylinder_flow(data, 200, 5))
expect_built(again, 1, "Flow-Aligned Surface after the filters of its flow were deleted")
