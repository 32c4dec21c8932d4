"""Whether paraview_mpi_filters.py gave the same outputs on different numbers of ranks.

  python3 compare_mpi_outputs.py WORKDIR FORM P [P ...]

Compares the points each filter wrote into WORKDIR/FORM_P/ for the first P with those of every
other P: the same number of points and the largest distance between corresponding points,
relative to the diagonal of the first output's bounding box.  Exits with 1 if a distance
exceeds 1e-9 or a count differs.
"""
import math
import os
import sys


def read_points(path):
    with open(path) as f:
        return [tuple(float(x) for x in line.split()) for line in f]


def diagonal(points):
    if not points:
        return 1.0
    low = [min(p[d] for p in points) for d in range(3)]
    high = [max(p[d] for p in points) for d in range(3)]
    return math.dist(low, high) or 1.0


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    workdir, form, ranks = sys.argv[1], sys.argv[2], sys.argv[3:]
    first = os.path.join(workdir, "%s_%s" % (form, ranks[0]))
    failed = False
    print("form            filter                   ranks relative_distance")
    for name in sorted(os.listdir(first)):
        expected = read_points(os.path.join(first, name))
        scale = diagonal(expected)
        for other in ranks[1:]:
            actual = read_points(os.path.join(workdir, "%s_%s" % (form, other), name))
            if len(actual) != len(expected):
                print("%-15s %-24s %s %d points against %d" % (form, name[:-4], other, len(actual), len(expected)))
                failed = True
                continue
            worst = max((math.dist(a, e) for a, e in zip(actual, expected)), default=0.0) / scale
            print("%-15s %-24s %s %.1e" % (form, name[:-4], other, worst))
            failed = failed or worst > 1e-9
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
