#!/usr/bin/env python3
"""Walks every state of a gait-parameter grid and maps speed, falls and reward (EXPERIMENTS.md).

usage: scripts/speed_map.py --output DIR [--grid GRID] [--stop-time 60] [--jobs N]
                            [--set comp.var=value ...] [--system FILE] [--stride PATH]
                            [--compare V_TABLE.csv ...]

A thin caller of `stride sweep` (docs/sweep.md), which does the work in one process:
  stride sweep SYSTEM --grid eval.eval_point=GRID --collect speed-map --output DIR ...
runs SYSTEM (default models/experiments/evaluate-point.xml: gait + robot + learner in evaluation
mode) for every state of GRID (`name:min:max:step,...`, default the 455 states of Experiment 1),
N points at a time, into DIR/points/<values>/; points already evaluated are kept, so an
interrupted map continues where it stopped. It writes DIR/speed_map.csv (grid values, W-footstep
windows walked without a fall, falls, mean speed over those windows in cm/s, mean reward per RL
step as the learner sees it, falls included) and, for a 2-D grid, DIR/speed_map.png, and prints
the best states. This is the ground truth the learner's V(s) should rank alike: with --compare,
for each learner V table (v_table.csv or a snapshot, same grid) this script prints the Spearman
rank correlation of V with the mean reward and how many of the 10 largest V are among the 10
fastest states without a fall.
Python 3 standard library only.
"""
import argparse
import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXP1_GRID = "period_time:450:960:15,swing_right_left:15:39:2"


def read_map(path):
    """The rows of speed_map.csv and the names of the grid's dimensions."""
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        names = reader.fieldnames[:reader.fieldnames.index("windows")]
        rows = [{"values": [float(r[n]) for n in names],
                 "windows": int(float(r["windows"])),
                 "falls": int(float(r["falls"])),
                 "mean_speed": float(r["mean_speed"]),
                 "mean_reward": float(r["mean_reward"])} for r in reader]
    return names, rows


def ranks(values):
    """Ranks 0..n-1, ties sharing their mean rank."""
    order = sorted(range(len(values)), key=lambda i: values[i])
    out = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            out[order[k]] = (i + j) / 2
        i = j + 1
    return out


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    ma, mb = sum(ra) / len(ra), sum(rb) / len(rb)
    cov = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    var = (sum((x - ma) ** 2 for x in ra) * sum((y - mb) ** 2 for y in rb)) ** 0.5
    return cov / var if var > 0 else float("nan")


def compare(path, names, rows):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != names + ["V"]:
            sys.exit(f"{path}: expected the columns {','.join(names + ['V'])}")
        values = {tuple(float(r[n]) for n in names): float(r["V"]) for r in reader}
    by_state = {tuple(r["values"]): r for r in rows}
    if values.keys() != by_state.keys():
        sys.exit(f"{path}: another grid than the speed map")
    states = sorted(by_state)
    rho = spearman([values[s] for s in states], [by_state[s]["mean_reward"] for s in states])
    top_v = set(sorted(states, key=lambda s: -values[s])[:10])
    fastest = set(sorted((s for s in states if by_state[s]["falls"] == 0
                          and by_state[s]["windows"] > 0),
                         key=lambda s: -by_state[s]["mean_speed"])[:10])
    print(f"{path}: Spearman rho(V, mean reward) = {rho:.3f}; "
          f"{len(top_v & fastest)} of its 10 largest V are among the 10 fastest states "
          "without a fall")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", required=True, help="folder for the points and the map")
    parser.add_argument("--grid", default=EXP1_GRID, help="name:min:max:step,... (eval.grid)")
    parser.add_argument("--stop-time", type=float, default=60.0, help="simulated s per point")
    parser.add_argument("--jobs", type=int, help="points at a time (default: every core)")
    parser.add_argument("--set", action="append", default=[], help="comp.var=value for all")
    parser.add_argument("--system", default=os.path.join(ROOT, "models/experiments/"
                                                         "evaluate-point.xml"))
    parser.add_argument("--stride", default=os.path.join(ROOT, "build/bin/stride"))
    parser.add_argument("--compare", action="append", default=[], metavar="V_TABLE",
                        help="a learner V table of the same grid to rank against the map")
    args = parser.parse_args()
    if not os.access(args.stride, os.X_OK):
        sys.exit(f"{args.stride}: not found; build first (scripts/build.sh) or give --stride")
    cmd = [args.stride, "sweep", args.system, "--grid", f"eval.eval_point={args.grid}",
           "--collect", "speed-map", "--output", args.output, "--stop-time", str(args.stop_time)]
    if args.jobs is not None:
        cmd += ["--jobs", str(args.jobs)]
    for s in args.set:
        cmd += ["--set", s]
    sys.stdout.flush()
    done = subprocess.run(cmd)
    if done.returncode != 0:
        sys.exit(done.returncode)
    if args.compare:
        names, rows = read_map(os.path.join(args.output, "speed_map.csv"))
        for path in args.compare:
            compare(path, names, rows)


if __name__ == "__main__":
    main()
