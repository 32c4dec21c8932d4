#!/usr/bin/env python3
"""Draws the schematic figures of the user manual as SVG (pure Python, no dependencies).

    python3 doc/Flow_aligned_surfaces/fig/make_figures.py   # rewrites the .svg files beside it

The figures show the exact flow-aligned surfaces of the flow of a point source,
v(x) = x / |x|^3, whose stream lines are the rays from the source: the flow-orthogonal
surfaces are spheres around the source and the stream surfaces are cones with their apex
at the source (planes through the source among them).  They are drawn from these closed
forms; they are not output of the package.
"""

import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

AZIMUTH = math.radians(-50.0)
ELEVATION = math.radians(18.0)
LIGHT = (0.35, -0.55, 0.76)


def rotate_view(p):
    """Orthographic view: returns (screen x, screen y, depth); larger depth is nearer."""
    x, y, z = p
    ca, sa = math.cos(AZIMUTH), math.sin(AZIMUTH)
    x1, y1 = ca * x - sa * y, sa * x + ca * y
    ce, se = math.cos(ELEVATION), math.sin(ELEVATION)
    return x1, ce * z - se * y1, -(se * z + ce * y1)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(a[0] ** 2 + a[1] ** 2 + a[2] ** 2)
    return (a[0] / n, a[1] / n, a[2] / n)


def shade(rgb, normal):
    lam = abs(sum(n * l for n, l in zip(normalize(normal), normalize(LIGHT))))
    k = 0.55 + 0.45 * lam
    return "#%02x%02x%02x" % tuple(min(255, int(c * k)) for c in rgb)


def grid(surface, n):
    """Quads of an n x n grid over the unit square (s, t) in [-1, 1]^2 mapped by surface."""
    pts = [[surface(-1 + 2 * i / n, -1 + 2 * j / n) for j in range(n + 1)] for i in range(n + 1)]
    return [(pts[i][j], pts[i + 1][j], pts[i + 1][j + 1], pts[i][j + 1])
            for i in range(n) for j in range(n)]


class Canvas:
    def __init__(self, width, height, scale, origin):
        self.width, self.height, self.scale, self.origin = width, height, scale, origin
        self.items = []  # (depth, svg)

    def xy(self, p):
        x, y, d = rotate_view(p)
        return self.origin[0] + self.scale * x, self.origin[1] - self.scale * y, d

    def quads(self, quads, rgb, opacity, stroke):
        for q in quads:
            pts = [self.xy(p) for p in q]
            depth = sum(p[2] for p in pts) / 4
            normal = cross(sub(q[1], q[0]), sub(q[3], q[0]))
            path = " ".join("%.1f,%.1f" % (p[0], p[1]) for p in pts)
            self.items.append((depth, '<polygon points="%s" fill="%s" fill-opacity="%.2f" '
                                      'stroke="%s" stroke-width="0.6"/>'
                               % (path, shade(rgb, normal), opacity, stroke)))

    def ray(self, a, b, colour, pieces=16, lift=0.0):
        """A stream line from a to b, cut into pieces so that surfaces hide the right parts;
        lift moves it towards the viewer (for stream lines drawn on a stream surface)."""
        for i in range(pieces):
            p = tuple(a[k] + (b[k] - a[k]) * i / pieces for k in range(3))
            q = tuple(a[k] + (b[k] - a[k]) * (i + 1) / pieces for k in range(3))
            pa, pb = self.xy(p), self.xy(q)
            marker = ' marker-end="url(#arrow)"' if i == pieces - 1 else ""
            self.items.append(((pa[2] + pb[2]) / 2 + lift,
                               '<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" '
                               'stroke-width="1.1"%s/>'
                               % (pa[0], pa[1], pb[0], pb[1], colour, marker)))

    def point(self, p, colour, label):
        x, y, d = self.xy(p)
        self.items.append((d + 10.0, '<circle cx="%.1f" cy="%.1f" r="3.5" fill="%s"/>'
                                     '<text x="%.1f" y="%.1f" font-size="12" '
                                     'font-family="sans-serif">%s</text>'
                           % (x, y, colour, x + 6, y + 14, label)))

    def text(self, x, y, s, size=14, weight="normal"):
        self.items.append((1e9, '<text x="%.1f" y="%.1f" font-size="%d" font-weight="%s" '
                                'font-family="sans-serif">%s</text>' % (x, y, size, weight, s)))

    def svg(self):
        head = ('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
                'viewBox="0 0 %d %d">\n<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" '
                'refY="5" markerWidth="6" markerHeight="6" orient="auto-start-reverse">'
                '<path d="M 0 0 L 10 5 L 0 10 z" fill="#808080"/></marker></defs>\n'
                '<rect width="100%%" height="100%%" fill="white"/>\n'
                % (self.width, self.height, self.width, self.height))
        body = "\n".join(s for _, s in sorted(self.items, key=lambda item: item[0]))
        return head + body + "\n</svg>\n"


def rays(canvas, directions, r0, r1):
    for d in directions:
        d = normalize(d)
        canvas.ray(tuple(r0 * c for c in d), tuple(r1 * c for c in d), "#909090")


def planar_patch(center, u, v, half):
    return lambda s, t: tuple(center[k] + half * (s * u[k] + t * v[k]) for k in range(3))


def spherical_cap(half):
    """The orthogonal surface through (0, 0, 1): the unit sphere, parametrized by geodesic
    distance from (0, 0, 1) so that the planar patch maps onto it without stretching."""
    def f(s, t):
        x, y = half * s, half * t
        rho = math.hypot(x, y)
        if rho == 0:
            return (0.0, 0.0, 1.0)
        return (math.sin(rho) * x / rho, math.sin(rho) * y / rho, math.cos(rho))
    return f


def principle_figure(path, small=False):
    half = 0.55
    n = 10
    if small:
        c = Canvas(200, 160, 95, (95, 140))
    else:
        c = Canvas(760, 360, 150, (175, 300))
    source = (0.0, 0.0, 0.0)
    directions = [(math.sin(a) * math.cos(b), math.sin(a) * math.sin(b), math.cos(a))
                  for a in (0.0, 0.35, 0.7) for b in ([0.0] if a == 0 else
                                                       [k * math.pi / 3 for k in range(6)])]
    # (a) orthogonal: the plane z = 1 becomes the unit sphere around the source.
    rays(c, directions, 0.12, 1.55)
    c.quads(grid(planar_patch((0, 0, 1), (1, 0, 0), (0, 1, 0), half), n), (200, 200, 200), 0.45,
            "#8a8a8a")
    c.quads(grid(spherical_cap(half), n), (70, 120, 200), 0.9, "#23457a")
    c.point(source, "#c03030", "" if small else "source")
    if not small:
        c.text(20, 30, "(a) orthogonal alignment", 15, "bold")
        c.text(20, 50, "plane M\u2080 \u2192 sphere around the source", 12)
        # (b) tangential: a tilted plane through (0, 0, 1) becomes the plane x = 0, which
        # holds the stream lines through it.  Drawn beside (a), shifted along the view's x axis.
        shift = 2.55
        ca, sa = math.cos(AZIMUTH), math.sin(AZIMUTH)
        offset = (shift * ca, -shift * sa, 0.0)

        def moved(f):
            return lambda s, t: tuple(a + b for a, b in zip(f(s, t), offset))

        tilt = math.radians(35)
        initial = planar_patch((0, 0, 1), (0, 1, 0), (math.sin(tilt), 0, math.cos(tilt)), half)
        final = planar_patch((0, 0, 1), (0, 1, 0), (0, 0, 1), half)
        in_plane = [(0.0, math.sin(a), math.cos(a)) for a in (-0.6, -0.3, 0.0, 0.3, 0.6)]
        for d in in_plane:
            d = normalize(d)
            c.ray(tuple(offset[k] + 0.12 * d[k] for k in range(3)),
                  tuple(offset[k] + 1.75 * d[k] for k in range(3)), "#5a2a08", lift=1e6)
        c.quads(grid(moved(initial), n), (200, 200, 200), 0.45, "#8a8a8a")
        c.quads(grid(moved(final), n), (220, 130, 60), 0.9, "#7a3a10")
        c.point(offset, "#c03030", "source")
        c.text(400, 30, "(b) tangential alignment", 15, "bold")
        c.text(400, 50, "tilted plane M\u2080 \u2192 plane through the source", 12)
    with open(path, "w", encoding="utf-8") as out:
        out.write(c.svg())


if __name__ == "__main__":
    principle_figure(os.path.join(HERE, "fas_principle.svg"))
    principle_figure(os.path.join(HERE, "fas_small.svg"), small=True)
