#!/usr/bin/env python3
"""Speed of two builds side by side: the same bench command from two build directories, run in
alternation so that both see the same machine, compared by the CPU time each run used (user +
system, from the kernel's accounting), which a busy machine disturbs far less than wall time.

  bench/side_by_side.py OLD_BUILD NEW_BUILD [--repeats 5] -- bench/ejecta_bench_sedov --n 50

Prints each run, the median CPU seconds of each build and the ratio new/old (1.00 = the same;
above 1 = the new build is slower). Build the old commit in a second worktree, e.g.
  git worktree add --detach ../base <commit> && cmake -S ../base -B ../base/build ...
Use --threads 1 in the bench command for the steadiest numbers on a shared machine.
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys


def cpu_seconds_of(command):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    parser = argparse.ArgumentParser(
        usage="%(prog)s OLD_BUILD NEW_BUILD [--repeats N] -- PROGRAM [ARGS...]",
        description=__doc__.split("\n\n")[0])
    parser.add_argument("old_build")
    parser.add_argument("new_build")
    parser.add_argument("--repeats", type=int, default=5)
    argv = sys.argv[1:]
    if "--" not in argv:
        parser.error("give the bench command (relative to the build) after --")
    cut = argv.index("--")
    args = parser.parse_args(argv[:cut])
    bench = argv[cut + 1:]
    if not bench:
        parser.error("give the bench command after --")
    times = {"old": [], "new": []}
    for r in range(args.repeats):
        # Alternate which goes first, so a slow drift of the machine's load favours neither.
        order = ("old", "new") if r % 2 == 0 else ("new", "old")
        for which in order:
            build = args.old_build if which == "old" else args.new_build
            program = os.path.join(build, bench[0])
            t = cpu_seconds_of([program] + bench[1:])
            times[which].append(t)
            print(f"run {r + 1} {which}: {t:.3f} s CPU", flush=True)
    old, new = statistics.median(times["old"]), statistics.median(times["new"])
    print(f"median CPU: old {old:.3f} s, new {new:.3f} s, ratio new/old {new / old:.3f}")


if __name__ == "__main__":
    sys.exit(main())
