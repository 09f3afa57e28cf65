#!/usr/bin/env python3
"""Spread of the learnt best region over several learner runs (EXPERIMENTS.md).

usage: scripts/seed_spread.py [--table v_snapshot_100000.csv] [--top 10] RUN_DIR...

Reads the V table of every run directory (default `v_table.csv`) and prints, as Markdown:
per run the best state, its V and the bounding box of its `--top` states; then every state that
is in the top set of at least half of the runs, with how many runs, and the mean and standard
deviation of its V over the runs. Python 3 standard library only.
"""
import argparse
import csv
import os
import statistics
import sys


def read_table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows or rows[0][-1] != "V":
        sys.exit(f"{path}: not a V table (expected a header ending in 'V')")
    names = rows[0][:-1]
    table = {}
    for line, row in enumerate(rows[1:], start=2):
        if len(row) != len(names) + 1:
            sys.exit(f"{path}:{line}: expected {len(names) + 1} fields, got {len(row)}")
        table[tuple(float(v) for v in row[:-1])] = float(row[-1])
    return names, table


def fmt_state(state):
    return "/".join(f"{v:g}" for v in state)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="+", help="learner output directories")
    parser.add_argument("--table", default="v_table.csv", help="V table file in each directory")
    parser.add_argument("--top", type=int, default=10, help="size of the best region")
    args = parser.parse_args()

    names, tables = None, []
    for run in args.runs:
        path = os.path.join(run, args.table)
        if not os.path.isfile(path):
            sys.exit(f"{path}: missing")
        n, t = read_table(path)
        if names is not None and (n != names or t.keys() != tables[0].keys()):
            sys.exit(f"{path}: another grid than {os.path.join(args.runs[0], args.table)}")
        names = n
        tables.append(t)

    print(f"| run | best state ({'/'.join(names)}) | V | top {args.top}: " +
          " × ".join(f"{n} range" for n in names) + " |")
    print("|---|---|---|---|")
    tops = []
    for run, t in zip(args.runs, tables):
        ranked = sorted(t, key=lambda s: (-t[s], s))[: args.top]
        tops.append(set(ranked))
        box = " × ".join(f"{min(s[d] for s in ranked):g}..{max(s[d] for s in ranked):g}"
                         for d in range(len(names)))
        print(f"| {os.path.basename(os.path.normpath(run))} | {fmt_state(ranked[0])} | "
              f"{t[ranked[0]]:.1f} | {box} |")

    print()
    print(f"| state ({'/'.join(names)}) | in the top {args.top} of | mean V | sd V |")
    print("|---|---|---|---|")
    states = sorted(tables[0], key=lambda s: -statistics.fmean(t[s] for t in tables))
    for s in states:
        count = sum(s in top for top in tops)
        if 2 * count < len(tables):
            continue
        values = [t[s] for t in tables]
        sd = statistics.stdev(values) if len(values) > 1 else 0.0
        print(f"| {fmt_state(s)} | {count} / {len(tables)} | {statistics.fmean(values):.1f} | "
              f"{sd:.1f} |")


if __name__ == "__main__":
    main()
