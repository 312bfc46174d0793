#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Full coupling against Johnson's level at the same load, measured in one run (issue 24, "Done when").

`roughroll point` of data/aluminium-on-steel.toml (coupling = "johnson") and of the same scene with
coupling = "full", at the default settings (the ladder chooses n), for free rolling and Q/f = +-0.75, the
two levels interleaved in every repetition so that both see the same load of a shared machine. CPU time
(user + sys) of each child process, medians over the repetitions, and the ratio full / Johnson of the medians.

    bench/full_coupling_ratio.py BUILD/roughroll [--repetitions 5] [--friction 0.05] [--extra '--n 128']
                                 [--old OLD/roughroll]

Prints a Markdown table (docs/performance.md quotes it) and, per point, the n the ladder answered at and the
alternation's steps. With --old, a second program (the one before a change) runs every point too, interleaved
with the first in each repetition, and the table has both programs' medians and ratios and full old / new.
Not a test: a timing on a shared machine varies by tens of percent.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "data", "aluminium-on-steel.toml")
LOADS = [("free rolling", 0.0), ("driven Q/f = +0.75", 0.75), ("braked Q/f = -0.75", -0.75)]


def cpu_of(command):
    """Runs `command`; returns (user + sys CPU seconds of the child, its standard output)."""
    with tempfile.TemporaryFile() as out:
        child = subprocess.Popen(command, stdout=out, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        out.seek(0)
        text = out.read().decode()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("failed: " + " ".join(command))
    return usage.ru_utime + usage.ru_stime, text


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary")
    parser.add_argument("--old", help="the program before a change, run interleaved with `binary`")
    parser.add_argument("--repetitions", type=int, default=5)
    parser.add_argument("--friction", type=float, default=0.05)
    parser.add_argument("--extra", default="", help="further options of `roughroll point` (e.g. '--n 128')")
    args = parser.parse_args()
    programs = [("new", args.binary)] + ([("old", args.old)] if args.old else [])
    with open(SCENE) as f:
        johnson_text = f.read()
    if 'coupling = "johnson"' not in johnson_text:
        sys.exit("the scene no longer says coupling = \"johnson\": " + SCENE)
    with tempfile.TemporaryDirectory() as tmp:
        scenes = {}
        for level in ("johnson", "full"):
            scenes[level] = os.path.join(tmp, level + ".toml")
            with open(scenes[level], "w") as f:
                f.write(johnson_text.replace('coupling = "johnson"', 'coupling = "%s"' % level))
        times = {(program, load, level): [] for program, _ in programs for load, _ in LOADS for level in scenes}
        facts = {}
        for _ in range(args.repetitions):
            for load, ratio in LOADS:
                for program, binary in programs:
                    for level in ("johnson", "full"):
                        command = [binary, "point", scenes[level], "--friction", repr(args.friction), "--Q",
                                   repr(ratio * args.friction), "--json"] + args.extra.split()
                        seconds, text = cpu_of(command)
                        times[(program, load, level)].append(seconds)
                        point = json.loads(text)
                        coupling = point.get("coupling") or {}
                        facts[(program, load, level)] = (point.get("n"), coupling.get("iterations"),
                                                         coupling.get("newton_residuals"))

    def median(program, load, level):
        return statistics.median(times[(program, load, level)])

    def ratio_text(program, load):
        j, f = median(program, load, "johnson"), median(program, load, "full")
        return "%.3f / %.3f (**%.1f**)" % (j, f, f / j if j > 0 else float("inf"))

    if not args.old:
        print("| load | Johnson's n | full's n (steps) | Johnson s | full s | full / Johnson |")
        print("|---|---|---|---|---|---|")
        for load, _ in LOADS:
            j, f = median("new", load, "johnson"), median("new", load, "full")
            n, steps, _ = facts[("new", load, "full")]
            print("| %s | %s | %s (%s) | %.3f | %.3f | **%.1f** |" % (load, facts[("new", load, "johnson")][0], n, steps,
                                                                   j, f, f / j if j > 0 else float("inf")))
    else:
        print("| load | n (Johnson, full) | full's steps, systems old / new | old: Johnson / full s (ratio) | "
              "new: Johnson / full s (ratio) | full old / new |")
        print("|---|---|---|---|---|---|")
        for load, _ in LOADS:
            _, old_steps, old_systems = facts[("old", load, "full")]
            n, steps, systems = facts[("new", load, "full")]
            gain = median("old", load, "full") / median("new", load, "full")
            print("| %s | %s, %s | %s, %s / %s, %s | %s | %s | %.2f |" % (
                load, facts[("new", load, "johnson")][0], n, old_steps, old_systems, steps, systems,
                ratio_text("old", load), ratio_text("new", load), gain))
    print("\nmedians of %d repetitions (CPU, user + sys); load average %s" %
          (args.repetitions, " ".join("%.1f" % v for v in os.getloadavg())))


if __name__ == "__main__":
    main()
