#!/usr/bin/python3
# Draws the steps of the construction and what runs in TBB's tasks in each,
# with the time of each step for Sequential_tag and Parallel_tag, from the
# output of `triangulation_benchmark [--threads T] stages N INPUT RUNS`:
#
#   plot_stages.py SEQUENTIAL.txt PARALLEL.txt THREADS OUT.png
#
# The figure of the user manual's section on threads.
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# What each step runs beside the calling thread with Parallel_tag, in the
# order of triangulation_benchmark's steps.
PARALLEL_WORK = [
    "each level's tiles surveyed\n(the density) in tasks of 1024,\nthe next level's while this\nlevel's triangles are linked;\nthe last level in two halves",
    "blocks of\n2^14 vertices",
    "the TDS's storage\nreserved and its faces\nmade in a task beside",
    "blocks of\n2^14 faces",
    "",
]
SHORT_NAMES = ["base mesh", "moves", "flips", "TDS", "rest"]


def read_stages(path):
    steps, total = [], None
    for line in open(path):
        m = re.match(r"(.*): ([0-9.eE+-]+) ms", line.strip())
        if m and m.group(1) == "construction":
            total = float(m.group(2))
        elif m:
            steps.append((m.group(1), float(m.group(2))))
    if len(steps) != len(SHORT_NAMES) or total is None:
        sys.exit(f"{path}: not the output of triangulation_benchmark stages")
    return steps, total


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: plot_stages.py SEQUENTIAL.txt PARALLEL.txt THREADS OUT.png")
    sequential, parallel = read_stages(sys.argv[1]), read_stages(sys.argv[2])
    threads = sys.argv[3]
    colours = ["#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#bab0ac"]
    fig, ax = plt.subplots(figsize=(11, 4.2))
    rows = [("Sequential_tag", sequential), (f"Parallel_tag, {threads} threads", parallel)]
    for y, (label, (steps, total)) in enumerate(rows):
        left = 0.0
        for k, (_, ms) in enumerate(steps):
            ax.barh(y, ms, left=left, color=colours[k], edgecolor="white", height=0.55)
            if ms > 0.06 * total:
                ax.text(left + ms / 2, y, f"{SHORT_NAMES[k]}\n{ms:.0f} ms", ha="center", va="center",
                        fontsize=8, color="white")
            left += ms
        ax.text(left + 0.01 * total, y, f"{total:.0f} ms", va="center", fontsize=9)
    # what the tasks do, under the parallel bar's steps
    steps, _ = parallel
    left = 0.0
    for k, (_, ms) in enumerate(steps):
        if PARALLEL_WORK[k] and ms > 0.04 * parallel[1]:
            ax.annotate(PARALLEL_WORK[k], xy=(left + ms / 2, 1.3), xytext=(left + ms / 2, 1.55),
                        ha="center", va="bottom", fontsize=7, arrowprops=dict(arrowstyle="-", lw=0.5))
        left += ms
    ax.set_yticks([0, 1])
    ax.set_yticklabels([label for label, _ in rows])
    ax.set_ylim(-0.5, 2.6)
    ax.set_xlabel("milliseconds (medians); the calling thread runs every step, the tasks run what is written above")
    ax.spines[["top", "right"]].set_visible(False)
    fig.tight_layout()
    fig.savefig(sys.argv[4], dpi=110)


if __name__ == "__main__":
    main()
