"""A small OpenFOAM case written without OpenFOAM, for the tests of data as ParaView gives it: an
n x n x n hexahedral mesh of the unit cube (constant/polyMesh, ASCII), three boundary patches
(inlet x = 0, outlet x = 1, walls), and the time directory 1 (or several, one swirl w each) with
the cell velocity U of a swirling channel flow v(x) = (1, -w (z - 1/2), w (y - 1/2)), given at
the cell centres: its stream
surfaces are helicoids around the axis y = z = 1/2, and what a filter samples can be told apart
between the cell values (constant per cell) and the point values ParaView's reader interpolates
from them."""
import os

HEADER = """FoamFile
{
    version 2.0;
    format ascii;
    class %s;
    location "%s";
    object %s;
}
"""


def velocity(x, y, z, swirl):
    return (1.0, -swirl * (z - 0.5), swirl * (y - 0.5))


def _write(path, cls, location, items, count_first=True):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER % (cls, location, os.path.basename(path)))
        f.write("%d\n(\n" % len(items) if count_first else "(\n")
        f.write("\n".join(items))
        f.write("\n)\n")


def _vector(v):
    return "(%.17g %.17g %.17g)" % v


def write_case(folder, n=12, swirl=2.0, swirls=None):
    """Writes the case into `folder` (the time directory 1 with `swirl`, or one time directory per
    item {time: swirl} of `swirls`); returns the path of its `case.foam` for OpenFOAMReader."""
    def point(i, j, k):
        return i + (n + 1) * (j + (n + 1) * k)

    def cell(i, j, k):
        return i + n * (j + n * k)

    points = [_vector((i / n, j / n, k / n)) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
    # Faces with their normal from owner to neighbour (boundary faces: outwards).
    plus = {  # the face on the + side of cell (i, j, k) along each axis
        0: lambda i, j, k: (point(i + 1, j, k), point(i + 1, j + 1, k), point(i + 1, j + 1, k + 1), point(i + 1, j, k + 1)),
        1: lambda i, j, k: (point(i, j + 1, k), point(i, j + 1, k + 1), point(i + 1, j + 1, k + 1), point(i + 1, j + 1, k)),
        2: lambda i, j, k: (point(i, j, k + 1), point(i + 1, j, k + 1), point(i + 1, j + 1, k + 1), point(i, j + 1, k + 1)),
    }
    step = {0: (1, 0, 0), 1: (0, 1, 0), 2: (0, 0, 1)}

    def minus(axis, i, j, k):  # the face on the - side, facing outwards from (i, j, k)
        di, dj, dk = step[axis]
        return tuple(reversed(plus[axis](i - di, j - dj, k - dk)))

    faces, owner, neighbour = [], [], []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                for axis in range(3):  # neighbours in increasing cell index: +x, +y, +z
                    ni, nj, nk = i + step[axis][0], j + step[axis][1], k + step[axis][2]
                    if max(ni, nj, nk) < n:
                        faces.append(plus[axis](i, j, k))
                        owner.append(cell(i, j, k))
                        neighbour.append(cell(ni, nj, nk))
    patches = []
    cells = [(i, j, k) for k in range(n) for j in range(n) for i in range(n)]
    sides = {
        "inlet": [(minus(0, i, j, k), (i, j, k)) for (i, j, k) in cells if i == 0],
        "outlet": [(plus[0](i, j, k), (i, j, k)) for (i, j, k) in cells if i == n - 1],
        "walls": [(minus(a, i, j, k), (i, j, k)) for a in (1, 2) for (i, j, k) in cells if (j, k)[a - 1] == 0] +
                 [(plus[a](i, j, k), (i, j, k)) for a in (1, 2) for (i, j, k) in cells if (j, k)[a - 1] == n - 1],
    }
    for name, side in sides.items():
        patches.append((name, len(faces), len(side), [c for _, c in side]))
        for face, (i, j, k) in side:
            faces.append(face)
            owner.append(cell(i, j, k))

    mesh = os.path.join(folder, "constant", "polyMesh")
    _write(os.path.join(mesh, "points"), "vectorField", "constant/polyMesh", points)
    _write(os.path.join(mesh, "faces"), "faceList", "constant/polyMesh",
           ["4(%d %d %d %d)" % f for f in faces])
    _write(os.path.join(mesh, "owner"), "labelList", "constant/polyMesh", [str(o) for o in owner])
    _write(os.path.join(mesh, "neighbour"), "labelList", "constant/polyMesh", [str(o) for o in neighbour])
    _write(os.path.join(mesh, "boundary"), "polyBoundaryMesh", "constant/polyMesh",
           ["%s\n{\n    type %s;\n    nFaces %d;\n    startFace %d;\n}" %
            (name, "wall" if name == "walls" else "patch", count, start) for name, start, count, _ in patches])

    for time, w in sorted((swirls or {1: swirl}).items()):
        _write_velocity(folder, str(time), n, cells, patches, w)
    os.makedirs(os.path.join(folder, "system"), exist_ok=True)
    with open(os.path.join(folder, "system", "controlDict"), "w") as f:
        f.write(HEADER % ("dictionary", "system", "controlDict"))
        f.write("application simpleFoam;\nstartFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\n"
                "deltaT 1;\nwriteControl timeStep;\nwriteInterval 1;\nwriteFormat ascii;\n")
    case = os.path.join(folder, "case.foam")
    open(case, "w").close()
    return case


def _write_velocity(folder, time_name, n, cells, patches, swirl):
    """The time directory `time_name` with the cell velocity U of `swirl`."""
    def centre_velocity(i, j, k):
        return velocity((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n, swirl)

    time = os.path.join(folder, time_name)
    os.makedirs(time, exist_ok=True)
    with open(os.path.join(time, "U"), "w") as f:
        f.write(HEADER % ("volVectorField", time_name, "U"))
        f.write("dimensions [0 1 -1 0 0 0 0];\n\ninternalField nonuniform List<vector>\n%d\n(\n" % len(cells))
        f.write("\n".join(_vector(centre_velocity(*c)) for c in cells))
        f.write("\n);\n\nboundaryField\n{\n")
        for name, _, count, owners in patches:
            f.write("    %s\n    {\n        type calculated;\n        value nonuniform List<vector>\n%d\n(\n" %
                    (name, count))
            f.write("\n".join(_vector(centre_velocity(*c)) for c in owners))
            f.write("\n);\n    }\n")
        f.write("}\n")
