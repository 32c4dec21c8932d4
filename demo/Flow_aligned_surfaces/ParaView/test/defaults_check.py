"""Every filter applied with its defaults, as a new user would, on the package's real CFD data
(../shared/data: the cylinder as an image and as its solver cells, the cavity's solver cells):
Flow-Aligned Surface and Grow Boundary give a converged tangential surface (normalized flux at
most 0.02, at least 95 % of the area sampled), Parametrize And Seed gives seed curves, Stream
Surface From Curve a surface that reaches across the data, Flow Texture a texture that shows
(three repeats along the flow and a measured contrast on the surface); no filter warns.  Used by
test_defaults.py (pvbatch) and test_gui.py (the GUI)."""
from paraview.simple import *

import math
import os

import fas_plugin_test as t

DATA_SETS = ["CYLINDER_grid.vtk", "CYLINDER_cells.vtk", "CAVITY_cells.vtk"]


def expect_aligned(out, what):
    flux, sampled = t.field_value(out, "normalized_flux"), t.field_value(out, "sampled_area_fraction")
    if not (flux <= 0.02 and sampled >= 0.95):
        raise AssertionError("%s: normalized flux %g, sampled area %g" % (what, flux, sampled))
    return "flux %.4f" % flux


def texture_contrast(surface, texture):
    """The standard deviation of the texture's luminance (0..1) looked up at the surface's
    texture coordinates, on the vertices of faces the mask leaves textured (mask < 0.5)."""
    tcoords, mask = surface.GetPointData().GetTCoords(), surface.GetCellData().GetArray("texture_mask")
    width, height, _ = texture.GetDimensions()
    pixels = texture.GetPointData().GetScalars()
    textured = set()
    for c in range(surface.GetNumberOfCells()):
        if mask.GetValue(c) < 0.5:
            ids = surface.GetCell(c).GetPointIds()
            textured.update(ids.GetId(k) for k in range(ids.GetNumberOfIds()))
    values = []
    for i in textured:
        u, v = tcoords.GetTuple2(i)
        x, y = int((u % 1.0) * width) % width, int((v % 1.0) * height) % height
        rgb = pixels.GetTuple3(x + width * y)
        values.append((0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]) / 255)
    if len(values) < 100:
        return 0.0, len(values)
    mean = sum(values) / len(values)
    return math.sqrt(sum((x - mean) ** 2 for x in values) / len(values)), len(values)


def check_defaults(folder, name, filters, shown=lambda proxy: None):
    """Every filter with its defaults on `folder`/`name`; `filters` holds the plugin's filters by
    name (the namespace the plugin was loaded into), `shown(proxy)` is called with each filter once
    it is created (the GUI test shows them, as Apply does)."""
    data = LegacyVTKReader(FileNames=[os.path.join(folder, name)])
    data.UpdatePipeline()
    bounds = data.GetDataInformation().GetBounds()
    extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    report = []
    with t.Messages() as m:
        surface = filters["FlowAlignedSurface"](Input=data)
        shown(surface)
        report.append("Flow-Aligned Surface " + expect_aligned(t.fetch(surface, surface.NumberOfIterations),
                                                              name + ", Flow-Aligned Surface"))
        grown = filters["GrowBoundary"](Input=data, Surface=surface)
        shown(grown)
        grown_out = t.fetch(grown)
        if t.field_value(grown_out, "number_of_new_faces") <= 0:
            raise AssertionError(name + ", Grow Boundary: nothing grown")
        report.append("Grow Boundary " + expect_aligned(grown_out, name + ", Grow Boundary"))
        seeds = filters["ParametrizeAndSeed"](Input=data, Surface=surface)
        shown(seeds)
        curves = t.fetch_port(seeds, 1)
        if curves.GetNumberOfCells() < 1:
            raise AssertionError(name + ", Parametrize And Seed: no seed curve")
        report.append("%d seed curves" % curves.GetNumberOfCells())
        stream = filters["StreamSurfaceFromCurve"](Input=data, Seeds=OutputPort(seeds, 1))
        shown(stream)
        stream_out = t.fetch(stream)
        b = stream_out.GetBounds()
        reach = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
        if stream_out.GetNumberOfCells() == 0 or reach < 0.5 * extent:
            raise AssertionError("%s, Stream Surface From Curve: %d faces reaching %g of the data's extent %g" % (
                name, stream_out.GetNumberOfCells(), reach, extent))
        report.append("stream surface reaching %.2f of the data's extent" % (reach / extent))
        texture = filters["FlowTexture"](Input=data, Surface=surface)
        shown(texture)
        textured, image = t.fetch_port(texture, 0), t.fetch_port(texture, 1)
        u_range = textured.GetPointData().GetTCoords().GetRange(0)
        contrast, vertices = texture_contrast(textured, image)
        if not (abs(u_range[1] - u_range[0] - 3) < 1e-9 and contrast > 0.05):
            raise AssertionError("%s, Flow Texture: u spans %g repeats, contrast %g on %d vertices" % (
                name, u_range[1] - u_range[0], contrast, vertices))
        report.append("texture contrast %.3f" % contrast)
    if "Warning" in m.text() or "ERR" in m.text():
        raise AssertionError("%s: the defaults gave a warning or an error: %s" % (name, m.text()))
    for proxy in [texture, stream, seeds, grown, surface, data]:
        Delete(proxy)
    return "%s with the defaults: %s" % (name, ", ".join(report))
