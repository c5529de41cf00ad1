#!/usr/bin/env python3
"""Speed of two builds side by side: the same bench command from two build directories, run in
alternation so that both see the same machine, compared by the CPU time each run used (user +
system, from the kernel's accounting), which a busy machine disturbs far less than wall time.

  bench/side_by_side.py OLD_BUILD NEW_BUILD [--repeats 5] -- bench/ejecta_bench_sedov --n 50

Prints each run, the median CPU seconds of each build and the ratio new/old (1.00 = the same;
above 1 = the new build is slower). With --instructions each build runs once under valgrind's
callgrind instead and the ratio is of instructions executed: exact and independent of the
machine's load (a virtual machine without hardware counters included), though blind to memory
effects, so use a short bench command (e.g. --steps 10). Build the old commit in a second worktree, e.g.
  git worktree add --detach ../base <commit> && cmake -S ../base -B ../base/build ...
Use --threads 1 in the bench command for the steadiest numbers on a shared machine.
"""
import argparse
import os
import re
import resource
import statistics
import subprocess
import sys


def cpu_seconds_of(command):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def instructions_of(command):
    out = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + command,
                         check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True).stderr
    found = re.search(r"Collected : (\d+)", out)
    if not found:
        sys.exit("valgrind reported no instruction count:\n" + out[-2000:])
    return int(found.group(1))


def main():
    parser = argparse.ArgumentParser(
        usage="%(prog)s OLD_BUILD NEW_BUILD [--repeats N] -- PROGRAM [ARGS...]",
        description=__doc__.split("\n\n")[0])
    parser.add_argument("old_build")
    parser.add_argument("new_build")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--instructions", action="store_true",
                        help="compare instructions executed (valgrind callgrind), one run each")
    argv = sys.argv[1:]
    if "--" not in argv:
        parser.error("give the bench command (relative to the build) after --")
    cut = argv.index("--")
    args = parser.parse_args(argv[:cut])
    bench = argv[cut + 1:]
    if not bench:
        parser.error("give the bench command after --")
    if args.instructions:
        counts = {}
        for which, build in (("old", args.old_build), ("new", args.new_build)):
            counts[which] = instructions_of([os.path.join(build, bench[0])] + bench[1:])
            print(f"{which}: {counts[which]:,} instructions", flush=True)
        print(f"ratio new/old {counts['new'] / counts['old']:.4f} (instructions)")
        return 0
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
