"""The table of run_mpi_filters.sh: from the lines paraview_mpi_filters.py printed in several
rounds of 1, 2 and 4 ranks of one form of the data (FORM_runs.txt), per filter and number of
ranks the median time over the rounds, the median over the rounds of that round's time divided
by 1 rank's in the same round (a ratio the machine's drift between rounds does not bend), whether
that ratio meets the target of 2 ranks (at most 1.5), the exchanges and the points; then the
exchanges per time line of the stream surface and the peak memory per rank of the last round.

  python3 summarize_mpi_filters.py FORM_runs.txt
"""
import statistics
import sys
from collections import defaultdict

TARGET = 1.5  # 2 ranks take at most this times the time of 1 rank


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    seconds = defaultdict(list)  # (filter, ranks) -> median seconds of each round
    last = {}                    # (filter, ranks) -> (exchanges, points) of the last round
    notes = {}                   # (filter, ranks) -> the last round's line on time lines or memory
    filters = []
    with open(sys.argv[1]) as f:
        for line in f:
            words = line.split()
            form, name, ranks = words[0], words[1], int(words[2])
            if words[3] in ("time", "peak"):
                notes[(name, ranks)] = " ".join(words[3:])
                continue
            if name not in filters:
                filters.append(name)
            seconds[(name, ranks)].append(float(words[3]))
            last[(name, ranks)] = (int(words[4]), int(words[5]))
    print("form            filter                   ranks median_s ratio_to_1 rounds exchanges   points")
    for name in filters:
        for ranks in sorted(r for (n, r) in seconds if n == name):
            times, serial = seconds[(name, ranks)], seconds[(name, 1)]
            ratio = statistics.median(t / s for t, s in zip(times, serial))
            mark = " met" if ranks == 2 and ratio <= TARGET else " NOT MET" if ranks == 2 else ""
            exchanges, points = last[(name, ranks)]
            print("%-15s %-24s %d %8.3f %10.2f%-8s %d %9d %8d" % (
                form, name, ranks, statistics.median(times), ratio, mark, len(times), exchanges, points))
    for (name, ranks), note in sorted(notes.items()):
        print("%-15s %-24s %d %s" % (form, name, ranks, note))


if __name__ == "__main__":
    main()
