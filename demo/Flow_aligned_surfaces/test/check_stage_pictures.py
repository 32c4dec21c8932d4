#!/usr/bin/env python3
"""The main job's pictures as a user opens them: runs ALIGN_PATCH (argv[1]) on the built-in
cylinder flow into a fresh folder and checks that
- it writes exactly the scene and stage pictures (PNG) the manual and the README name, all listed
  in summary.json;
- every one of them shows the scene's context: the obstacle (the cylinder, lit grey with the
  obstacle colour's blue tint), the domain's outline (its unlit grey lines), and, but for the
  textured surface, the colour bar in its own strip below the view, at least 400 pixels wide
  (narrower, its labels ran into each other), and no obstacle in that strip;
- a stage picture's view is the size of one of the scene's views (the same camera frames them
  alike): as wide, and as high as the scene (the textured one, without a colour bar: as high as
  the scene's views).
The pixels are read by a small PNG decoder (zlib only: no imaging module is needed).  Exits
non-zero with the reasons when a check fails.
"""
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

OUTLINE = (115, 115, 115)  # scene_assembly.h's box_outline(): 0.45 grey, unlit
STRIP = 0.12               # scene_rendering.h's scene_bar_strip: the colour bar's strip, of the height


def read_png(path):
    """(width, height, rows): the rows of (r, g, b) tuples, top row first; 8-bit RGB or RGBA."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + " is not a PNG file")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", data[pos + 8:pos + 8 + 13])
        elif kind == b"IDAT":
            idat += data[pos + 8:pos + 8 + length]
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"{path}: depth {depth}, colour type {colour}, interlace {interlace}: not read here")
    channels = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        line = unfilter(raw[start], bytearray(raw[start + 1:start + 1 + stride]), previous, channels)
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def unfilter(kind, line, previous, channels):
    """One scanline of PNG filter type `kind` back to its bytes."""
    for i in range(len(line)):
        left = line[i - channels] if i >= channels else 0
        up, corner = previous[i], (previous[i - channels] if i >= channels else 0)
        if kind == 1:
            line[i] = (line[i] + left) & 255
        elif kind == 2:
            line[i] = (line[i] + up) & 255
        elif kind == 3:
            line[i] = (line[i] + (left + up) // 2) & 255
        elif kind == 4:
            p = left + up - corner
            pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
            line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 255
    return line


def is_obstacle(p):
    """The obstacle's colour (0.72, 0.72, 0.76) under the light kit: grey, blue a little above."""
    r, g, b = p
    return abs(r - g) <= 1 and 4 <= b - r <= 12 and 50 <= r <= 200


def is_bar(p):
    """A colour of the blue-to-red colour map at full saturation."""
    return max(p) - min(p) > 200


def context_failures(name, rows, height, with_bar):
    """What `name`'s pixels lack of the scene's context."""
    strip_top = int(height * (1 - STRIP)) + 1
    view, strip = rows[:strip_top], rows[strip_top:]
    failures = []
    obstacle = sum(1 for row in view for p in row if is_obstacle(p))
    outline = sum(1 for row in view for p in row if p == OUTLINE)
    if obstacle < 1000:
        failures.append(f"{name}: {obstacle} pixels of the obstacle, expected at least 1000")
    if outline < 500:
        failures.append(f"{name}: {outline} pixels of the domain's outline, expected at least 500")
    if with_bar:
        bar = [x for row in strip for x, p in enumerate(row) if is_bar(p)]
        span = max(bar) - min(bar) + 1 if bar else 0
        if span < 400:
            failures.append(f"{name}: the colour bar is {span} pixels wide in its strip, expected at least 400")
        # (The outline's grey is not looked for there: the labels' anti-aliased edges have it.)
        spilled = sum(1 for row in strip for p in row if is_obstacle(p))
        if spilled:
            failures.append(f"{name}: {spilled} pixels of the obstacle in the colour bar's strip")
    return failures


def main(align_patch):
    stages = {"tangential": ["initial", "aligned", "textured", "seed_curves", "stream_surfaces"],
              "orthogonal": ["initial", "aligned", "seed_curves", "stream_surfaces", "stream_lines"]}
    scene_views = {"tangential": 3, "orthogonal": 2}  # the tangential scene's third: the textured stream surface
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out")
        p = subprocess.run([align_patch, "--faces", "300", "--output", out, "--quiet"], capture_output=True,
                           text=True, timeout=600)
        if p.returncode != 0:
            sys.exit(f"FAIL: align_patch exited with {p.returncode}:\n{p.stderr}")
        with open(os.path.join(out, "summary.json")) as summary:
            listed = sorted(f for f in json.load(summary)["files"] if f.endswith(".png"))
        expected = sorted([f"{n}_{s}.png" for n in stages for s in stages[n] + ["scene"]] +
                          ["tangential_stream_surfaces_texture.png"])  # the texture image, not a picture
        written = sorted(f for f in os.listdir(out) if f.endswith(".png"))
        if listed != expected or written != expected:
            sys.exit(f"FAIL: pictures written {written}, listed in summary.json {listed}, expected {expected}"
                     f"\n{p.stderr}")
        failures = []
        for name, names in stages.items():
            scene_width, scene_height, scene = read_png(os.path.join(out, name + "_scene.png"))
            failures += context_failures(name + "_scene.png", scene, scene_height, True)
            for stage in names:
                file = f"{name}_{stage}.png"
                width, height, rows = read_png(os.path.join(out, file))
                view_height = scene_height * (1 - STRIP) if stage == "textured" else scene_height
                if abs(height - view_height) > 1 or width * scene_views[name] != scene_width:
                    failures.append(f"{file}: {width} x {height}, not one view of the scene's "
                                    f"{scene_width} x {scene_height}")
                failures += context_failures(file, rows, height, stage != "textured")
        if failures:
            sys.exit("FAIL: " + "\nFAIL: ".join(failures))
        print(f"check_stage_pictures: {len(expected) - 1} pictures with the obstacle, the outline and the colour bar")


if __name__ == "__main__":
    main(sys.argv[1])
